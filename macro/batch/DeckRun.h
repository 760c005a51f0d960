#pragma once
// What running a deck takes and gives, as the batch sees it: the options of a
// deck's run, its exit status and outcome, its plan (the runs it makes), and
// the calls that run and plan a deck (macro/DeckRunner.h gives them:
// deckCalls). The batch (BatchRunner, ParallelRuns) runs decks through these
// alone.
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/Error.h"
#include "macro/deck/Warnings.h"
#include "macro/run/RunSummary.h"

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

// The runs a deck makes and whether it ends with a study's table (a SWEEp or
// an ENSEmble): macro/DeckRunner.h's planDeck.
struct DeckPlan {
  int runs = 0;
  bool study = false;
};

// A deck run and a deck planned: runDeck and planDeck of macro/DeckRunner.h
// with the solution commands bound.
struct DeckCalls {
  std::function<DeckOutcome(const std::string& deck, const DeckOptions& options, std::ostream& out)>
      run;
  std::function<DeckPlan(const std::string& deck, const std::map<std::string, double>& params)>
      plan;
};

// The log line after a shard's last run (macro/batch/ParallelRuns.h joins the
// logs of the parts at it).
constexpr const char* kEndOfRuns = "  end of the runs";

}  // namespace c2d
