#pragma once
// A BLASt record of an element that a REMOve command of the same problem
// removes too: whichever comes first takes the element out, and then the blast
// removes nothing of it or the REMOve fails (the element is gone). Which one
// depends on the times reached, but the overlap is known when the deck is
// bound: a warning at the BLASt record, naming the REMOve, before anything is
// computed. (During the run the blast's log line names its record again.)
#include <vector>

#include "core/Model.h"
#include "macro/deck/Deck.h"
#include "macro/deck/Macro.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Warnings.h"

namespace c2d {

// problem: for the BLASt records' text; model: its blasts (Blast::origin);
// batches: the bound commands; params: the parameters they were bound with.
void warnBlastsOfRemovedElements(const Problem& problem, const Model& model,
                                 const std::vector<std::vector<Macro>>& batches,
                                 const Parameters& params, Warnings* warnings);

}  // namespace c2d
