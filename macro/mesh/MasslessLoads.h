#pragma once
// A floor load given as a load only (QLOAd without MASS) in a run that is
// dynamic (DYNAmic, TRANsient other than OFF): the floor's weight then pushes
// on members that do not carry its mass, so the structure falls faster and
// rings at a higher frequency than the floor would let it. Surely not meant in
// a collapse: a warning at the first such QLOAd record, when the deck is bound.
#include <vector>

#include "macro/deck/Deck.h"
#include "macro/deck/Macro.h"
#include "macro/deck/Warnings.h"

namespace c2d {

void warnMasslessFloorLoads(const Problem& problem, const std::vector<std::vector<Macro>>& batches,
                            Warnings* warnings);

}  // namespace c2d
