#pragma once
// [ext] The syntax of the study blocks, SWEEp and ENSEmble (the structure in
// macro/deck/Deck.h: TopSweep, TopEnsemble): their records read and checked as
// far as they can be before evaluating, and their declared specs for --help.
// What the blocks do with the values is macro/draws/Sweep.h's and
// macro/draws/Ensemble.h's.
#include <cstddef>
#include <vector>

#include "macro/deck/CommandSpec.h"
#include "macro/deck/Deck.h"

namespace c2d {

// The values of a SWEEp record from field `first` on: expressions, and ranges
// lo:step:hi (each part an expression). Throws DeckError at a bad field.
std::vector<SweepItem> parseSweepItems(const Record& rec, std::size_t first);

// One record of an ENSEmble block (a drawn parameter, JITTer, DETOnators) added
// to the block, checked as far as it can be before evaluating; DeckError at the
// offending field. assignment: the record reads 'name = ...' (a drawn parameter).
void addEnsembleRecord(TopEnsemble& ensemble, const Record& rec, bool assignment);

// The declared specs of the top-level structure (FEAP, SWEEp), for --help (the
// structure words are parsed by DeckParser, not by a registry).
void registerDeckBlocks(CommandRegistry& registry);
// The declared specs of the ENSEmble block and its DETOnators record, for --help.
void registerEnsembleBlock(CommandRegistry& registry);

}  // namespace c2d
