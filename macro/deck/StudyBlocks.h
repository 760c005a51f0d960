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

// One record of a SWEEp block added to the block: 'name = v1 v2 ...' (assignment)
// or, without 'name =', more values of the variable before it. DeckError at the
// offending field: no variable to continue, a bad name, no values, a name swept
// twice, a count that does not zip with the variables before.
void addSweepRecord(TopSweep& sweep, const Record& rec, bool assignment);
// The SWEEp block ended: at least one variable, the last one's count zipped.
void checkSweepVariables(const TopSweep& sweep);

// The ENSEmble head record ENSEmble,,n,seed: the sample count and the seed's
// expressions into the block.
void readEnsembleHead(TopEnsemble& ensemble);

// One record of an ENSEmble block (a drawn parameter, JITTer, DETOnators) added
// to the block, checked as far as it can be before evaluating; DeckError at the
// offending field. assignment: the record reads 'name = ...' (a drawn parameter).
void addEnsembleRecord(TopEnsemble& ensemble, const Record& rec, bool assignment);

// A name both drawn by the ensemble and swept by the sweep: DeckError at the draw.
void checkDrawsNotSwept(const TopEnsemble& ensemble, const TopSweep& sweep);

// The declared specs of the top-level structure (FEAP, SWEEp), for --help (the
// structure words are parsed by DeckParser, not by a registry).
void registerDeckBlocks(CommandRegistry& registry);
// The declared specs of the ENSEmble block and its DETOnators record, for --help.
void registerEnsembleBlock(CommandRegistry& registry);

}  // namespace c2d
