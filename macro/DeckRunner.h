#pragma once
// Runs a whole deck: parse it (lex, parse), bind every problem of every pass of
// the top-level loops (all deck errors reported before computing), then run.
#include <map>
#include <ostream>
#include <string>

#include "macro/batch/DeckRun.h"
#include "macro/deck/SolutionCommand.h"

namespace c2d {

// "<stem>_part<i>of<n>" for a shard, "<stem>" otherwise.
std::string shardStem(const std::string& stem, const DeckOptions& options);

DeckOutcome runDeck(const std::string& path, const DeckOptions& options,
                    const SolutionCommands& commands, std::ostream& out);

// The runs a deck makes and whether it ends with a study's table (a SWEEp or
// an ENSEmble): its check pass alone (parsed and bound, nothing computed).
// Throws DeckError. `params`: the values given from outside the deck
// (DeckOptions::params).
DeckPlan planDeck(const std::string& path, const SolutionCommands& commands,
                  const std::map<std::string, double>& params = {});

// runDeck and planDeck with the solution commands bound (which must outlive
// the calls), as the batch runs and plans decks (macro/batch/BatchRunner.h).
DeckCalls deckCalls(const SolutionCommands& commands);

}  // namespace c2d
