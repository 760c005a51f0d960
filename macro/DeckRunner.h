#pragma once
// Runs a whole deck: parse it (lex, parse), bind every problem of every pass of
// the top-level loops (all deck errors reported before computing), then run.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "macro/ProblemRun.h"
#include "macro/SolutionCommand.h"

namespace c2d {

struct DeckOptions {
  std::filesystem::path outDir;  // empty: the current directory
  std::string logName;           // empty: <deck stem>.out
  bool quiet = false;            // no progress line, no summary
  bool progress = false;         // progress line on stderr (a terminal)
  std::string solver = "auto";
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
  RunSummary total;     // summed over every problem run
  int runs = 0;
  int interrupted = 0;  // the signal that stopped the deck, 0 when none
};

// The summary of a run: steps, iterations, cuts, hinges, for a dynamic run the
// energy figure (the largest |change of the total energy| since the first
// dynamic step over the largest energy seen: kinetic + strain + contact -
// external work), wall time.
std::string runSummaryText(const RunSummary& s);
// Above this energy figure a run with the energy conserving scheme is warned about.
constexpr double kConservedEnergyTolerance = 1e-3;
// The warning for a run with the conserving scheme whose energy changed by
// more than kConservedEnergyTolerance, else "".
std::string energyWarning(const RunSummary& s);

DeckOutcome runDeck(const std::string& path, const DeckOptions& options,
                    const SolutionCommands& commands, std::ostream& out);

}  // namespace c2d
