#pragma once
// Runs a whole deck: parse it (lex, parse), bind every problem of every pass of
// the top-level loops (all deck errors reported before computing), then run.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "macro/ProblemRun.h"
#include "macro/SolutionCommand.h"
#include "macro/Warnings.h"

namespace c2d {

struct DeckOptions {
  std::filesystem::path outDir;  // empty: the current directory
  std::string logName;           // empty: <deck stem>.out
  bool quiet = false;            // no progress line, no summary
  bool progress = false;         // progress line on stderr (a terminal)
  std::string solver = "auto";
  // --shard i/n: only the runs k (0-based over the deck) with k mod n == i - 1;
  // the deck's own outputs (log, plans table, overlays) are named <stem>_part<i>of<n>.
  int shard = 1, shards = 1;
};

// Exit status of a run.
enum ExitCode : int { kExitOk = 0, kExitDeckError = 1, kExitAnalysisFailed = 2, kExitInternal = 3 };

struct DeckOutcome {
  int exitCode = kExitOk;
  std::string message;  // the error, when there is one
  RunSummary total;     // summed over every problem run
  int runs = 0;
  std::vector<DeckWarning> warnings;  // printed on stderr and in the log
  int failedRuns = 0;   // runs of a study (SWEEp) that failed; the others ran
};

// "<stem>_part<i>of<n>" for a shard, "<stem>" otherwise.
std::string shardStem(const std::string& stem, const DeckOptions& options);

DeckOutcome runDeck(const std::string& path, const DeckOptions& options,
                    const SolutionCommands& commands, std::ostream& out);

}  // namespace c2d
