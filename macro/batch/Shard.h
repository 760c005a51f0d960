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
// A part of a deck's study also writes <stem>_part<i>of<n>_manifest.csv (what
// it is a part of: the deck and its fingerprint, i, n, the deck's run count,
// the table's kind and swept names), and the curves of its runs for the
// overlays (<stem>_part<i>of<n>_curves.csv); `collapse2d merge` checks every
// part against it (macro/batch/Merge.h).
#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "macro/batch/BatchRunner.h"

namespace c2d {

// The most parts a study or a list of decks is split into (as many as the
// runs a deck may have: more parts than runs run nothing).
inline constexpr int kMaxShards = 10000;

struct ShardSpec {
  int index = 1, count = 1;  // part index (1-based) of count
  bool active() const { return count > 1; }
  std::string tag() const;  // "part2of4"
};

// "i/n" with 1 <= i <= n <= kMaxShards; false when malformed or out of range.
bool parseShard(const std::string& text, ShardSpec& spec);

// The decks part `spec` runs; with one deck, all of it (and deck.shard set so
// that its runs are split).
std::vector<std::string> shardDecks(const std::vector<std::string>& decks, const ShardSpec& spec,
                                    DeckOptions& deck);

// The batch table as CSV (header deck,status,exit,signal,runs,steps,iterations,
// wall_s,debris_runs,outside_runs). readBatchCsv throws std::runtime_error
// (line, column, why) for a text that is not one whole.
std::string batchCsv(const std::vector<BatchResult>& results);
std::vector<BatchResult> readBatchCsv(const std::string& text);
void writeBatchPart(const std::filesystem::path& dir, const ShardSpec& spec,
                    const std::vector<BatchResult>& results);

extern const char* const kBatchHeader;

// What a part of a deck's study is a part of.
struct ShardManifest {
  std::string deck, fingerprint;  // the deck as given, and deckFingerprint of it
  int part = 1, parts = 1;
  int runs = 0;                     // the runs of the whole deck
  std::string table;                // "plans" (a SWEEp) or "ensemble"
  std::vector<std::string> swept;   // the swept names (the tables' columns)
  std::string title;                // the problem's title
  int curves = 0;                   // runs whose curves the part wrote for the overlays
  // contentFingerprint of the table and of the curves the part wrote (empty:
  // none), so that a file of another deck or run put in their place is refused.
  std::string tableHash, curvesHash;
};
// A hash of a text (FNV-1a, 16 hex digits).
std::string contentFingerprint(std::string_view text);
// A hash of the deck's records (INCLude expanded, comments dropped): parts of
// different decks with the same stem differ in it.
std::string deckFingerprint(const std::string& path);
void writeShardManifest(const std::filesystem::path& dir, const std::string& partStem,
                        const ShardManifest& manifest);
// Throws std::runtime_error saying what is wrong with the text.
ShardManifest readShardManifest(const std::string& text);

}  // namespace c2d
