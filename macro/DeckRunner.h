#pragma once
// Runs a whole deck: parse it (lex, parse), bind every problem of every pass of
// the top-level loops (all deck errors reported before computing), then run.
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "macro/run/ProblemRun.h"
#include "macro/commands/SolutionCommand.h"
#include "macro/deck/Warnings.h"

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
  // --set NAME=VALUE (collapse2d.run's params): a value given in place of the
  // one the deck's PARAmeter records assign to NAME (Parameters::setOverrides);
  // a name no record assigns is a usage error, a name a SWEEp or an ENSEmble
  // sets for each run a deck error at its record.
  std::map<std::string, double> params;
  // Called at every safe point of a run (the log's write check; tests).
  std::function<void()> safePoint;
};

// Exit status of a run: 0 ok, 1 deck error, 2 failed analysis, 3 internal or
// I/O error (unwritable output), 64 usage error (command line), 128 + N stopped
// by signal N (130 SIGINT, 143 SIGTERM).
enum ExitCode : int {
  kExitOk = 0,
  kExitDeckError = 1,
  kExitAnalysisFailed = 2,
  kExitInternal = 3,
  kExitUsage = 64
};

struct DeckOutcome {
  int exitCode = kExitOk;
  std::string message;  // the error, when there is one
  std::optional<SourceLoc> errorAt;  // a deck error's location
  RunSummary total;     // summed over every problem run
  int runs = 0;
  std::vector<DeckWarning> warnings;  // printed on stderr and in the log
  int failedRuns = 0;   // runs of a study (SWEEp) that failed; the others ran
  int interrupted = 0;  // the signal that stopped the deck, 0 when none
};

// "<stem>_part<i>of<n>" for a shard, "<stem>" otherwise.
std::string shardStem(const std::string& stem, const DeckOptions& options);

DeckOutcome runDeck(const std::string& path, const DeckOptions& options,
                    const SolutionCommands& commands, std::ostream& out);

// The runs a deck makes and whether it ends with a study's table (a SWEEp or
// an ENSEmble): its check pass alone (parsed and bound, nothing computed).
// Throws DeckError.
struct DeckPlan {
  int runs = 0;
  bool study = false;
};
// `params`: the values given from outside the deck (DeckOptions::params).
DeckPlan planDeck(const std::string& path, const SolutionCommands& commands,
                  const std::map<std::string, double>& params = {});

// The log line after a shard's last run (macro/studies/ParallelRuns.h joins the
// logs of the parts at it).
constexpr const char* kEndOfRuns = "  end of the runs";

}  // namespace c2d
