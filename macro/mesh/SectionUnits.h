#pragma once
// Values of an RC section (SECTion, REBAr, STIRrups) or of a SOFTening's
// shortest piece Lb that are accepted but surely in another unit than the
// deck's kN, m (stresses kN/m^2): located deck warnings naming the likely
// unit and the value in the deck's, flagged as unit warnings (a run that then
// fails names them in its advice, macro/DeckRunner).
//
// What is an error stays one (checked before these run): a fc outside
// 1e3-2.5e5 (the shear rule, materials/ShearResistance), a bar layer outside
// the section, bars of a tenth of the section's area or more, eu below fu/Es.
// Warned, in the deck's units:
//   fc outside 5e3-1.5e5 (5-150 MPa: the band the rotation rules read as
//     kN/m^2, materials/Confinement stressUnitInMPa; below it psi is likely);
//   fy, fu (given), fyw (given) outside 1e5-2.5e6 (100-2500 MPa);
//   Es (given) outside 1e8-3e8 (100-300 GPa);
//   a size of the shape (b, h, D, t, beff, hf) above 30 (no section is 30 m
//     deep: mm or cm);
//   a REBAr layer's area above 0.05 m^2 (40 bars of 40 mm), a RING bar's above
//     5e-3 m^2 (a bar of 80 mm): cm^2 or mm^2;
//   links with Asw/(b s) above 0.1 (ten times the most a member carries);
//   a link spacing s above the depth h: a 45-degree crack may cross no link
//     (EC2 9.2.2(6) allows 0.75 d in beams, 9.5.3 the smaller of 20 bar
//     diameters, the smaller side and 0.4 m in columns; between those limits
//     and h it is a detailing choice, not warned).
// Once the mesh is built (before computing), per material set against its
// longest member (elements of the set in line within about 8 degrees, meeting
// at nodes; joints not counted, so the longest any member can be): the depth
// h, the link spacing s and a SOFTening's given Lb longer than it. A SECTion's
// derived Lb (Mu/Vu from the STIRrups) is not: longer than the member means a
// shear-critical member, physics and not a unit.
#include "core/MaterialSet.h"
#include "macro/mesh/MeshCommands.h"
#include "macro/mesh/SectionRecords.h"

namespace c2d {

// After finishLawRecords for material set mat: the checks of its records, and
// their keeping (ctx.lawOrigins, ctx.meshChecks) for the checks of the mesh.
void warnSectionUnits(MeshContext& ctx, const LawRecords& seen, const MaterialSet& mat);

// The checks against the members' lengths (ctx.meshChecks).
void warnMemberLengths(const MeshContext& ctx);

// The length of the longest member of each material set (as above), by set number.
std::map<int, double> longestMembers(const Model& model);

}  // namespace c2d
