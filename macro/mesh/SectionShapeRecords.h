#pragma once
// The shape of a SECTion and the bars on a circle (deck language section 5):
//   SECTion RECTangular b h fc fy [Es [fu eu]]
//   SECTion TEE bw h beff hf fc fy [Es [fu eu]]
//   SECTion CIRCular D fc fy [Es [fu eu]]
//   SECTion ANNUlar D t fc fy [Es [fu eu]]
//   REBAr RING n A c   (n bars of area A evenly on a circle, c the cover from
//                       the outer face to the bars' centres)
// Binding into the MaterialSet's RcSectionData, and the checks that need the
// whole set (bars inside the concrete), as DeckErrors at the field at fault.
#include "core/MaterialSet.h"
#include "macro/mesh/MeshCommands.h"
#include "macro/mesh/SectionRecords.h"

namespace c2d {

void bindSectionShape(MeshContext& ctx, const Record& r, const CommandSpec& s, MaterialSet& mat,
                      LawRecords& seen);
// REBAr RING n A c: false when r is not a RING record.
bool bindRebarRing(MeshContext& ctx, const Record& r, LawRecords& seen);
// After the set's records: the RING records' bars checked within the
// concrete (DeckError at the cover's field) and added as layers, one per
// depth (the bars at +-theta from the top share it; the first bar at the top).
void placeSectionBars(const LawRecords& seen, RcSectionData& d);

}  // namespace c2d
