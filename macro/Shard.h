#pragma once
// [ext] Studies larger than one machine: `collapse2d run --shard i/n` runs the
// i-th of n interleaved parts, `collapse2d merge` joins the parts.
//
// With several decks the decks are split: part i runs the decks k (0-based, in
// the order given) with k mod n == i - 1. With one deck its runs (a SWEEp) are
// split the same way (DeckOptions::shard), and the deck's own outputs are named
// <stem>_part<i>of<n> (log, plans table, overlays); each run's outputs carry its
// sweep values as always. Every part writes batch_part<i>of<n>.csv, the batch
// table as CSV, in the output directory.
//
// merge reads a directory holding the parts: it joins every complete set of
// <stem>_part<i>of<n>_plans.csv into <stem>_plans.csv (rows ordered by run
// number) and the batch_part<i>of<n>.csv into batch.csv (a deck split over the
// parts gets one row: the first failure's status, the counts summed), prints the
// joint table, and refuses a set with a part missing.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "macro/BatchRunner.h"

namespace c2d {

struct ShardSpec {
  int index = 1, count = 1;  // part index (1-based) of count
  bool active() const { return count > 1; }
  std::string tag() const;  // "part2of4"
};

// "i/n" with 1 <= i <= n; false when malformed.
bool parseShard(const std::string& text, ShardSpec& spec);

// The decks part `spec` runs; with one deck, all of it (and deck.shard set so
// that its runs are split).
std::vector<std::string> shardDecks(const std::vector<std::string>& decks, const ShardSpec& spec,
                                    DeckOptions& deck);

// The batch table as CSV (header deck,status,exit,signal,runs,steps,iterations,
// wall_s,debris_runs,outside_runs).
std::string batchCsv(const std::vector<BatchResult>& results);
std::vector<BatchResult> readBatchCsv(const std::string& text);
void writeBatchPart(const std::filesystem::path& dir, const ShardSpec& spec,
                    const std::vector<BatchResult>& results);

// Joins the parts in dir (see above): 0 when every set found was complete and
// merged, 1 otherwise (messages on err).
int mergeParts(const std::filesystem::path& dir, std::ostream& out, std::ostream& err);

}  // namespace c2d
