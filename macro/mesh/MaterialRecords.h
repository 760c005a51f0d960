#pragma once
// The sub-records of a MATErial set (FRAMe, ELAStic, CROSs, ..., DAMPing):
// their specs (registerMaterialSubRecords, declared in macro/mesh/MeshCommands.h)
// and the reading of the records whose values need more than a range check.
#include "macro/deck/Record.h"

namespace c2d {

struct MeshContext;

// DAMPing RAYLeigh a0 a1 (FEAPpv's record; a0 must be 0) or DAMPing RATIo zeta f:
// the stiffness-proportional coefficient a1 (s) of the section's dashpot
// (materials/SectionDamping.h), a1 = zeta / (pi f) for the ratio zeta at the
// frequency f (Hz). DeckError at the offending field.
double readDamping(const MeshContext& ctx, const Record& r);

}  // namespace c2d
