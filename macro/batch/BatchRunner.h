#pragma once
// Batch runs (collapse2d run DECK... [-j N]): every deck in a child process of
// its own (fork), at most N at once, so that one deck's failure or crash never
// stops the others. A child's console output is kept and printed in one piece
// when it ends; its figures come back through a small result file. The table
// of every deck (status, runs, steps, iterations, wall time) ends the batch.
//
// Each child runs in a process group of its own and ends with the batch
// (Linux: a parent-death signal): a SIGINT or SIGTERM to the batch is passed on
// to every running deck, which stops at its next step and keeps its outputs as
// "interrupted"; decks not started yet are not started ("not run"). A deck that
// runs longer than the timeout gets SIGTERM, and SIGKILL kGraceSeconds later.
#include <ostream>
#include <string>
#include <vector>

#include "macro/batch/DeckRun.h"

namespace c2d {

struct BatchOptions {
  DeckOptions deck;       // output directory, quiet, solver (progress is the batch's own)
  int jobs = 1;           // decks run at the same time
  bool progress = false;  // a status line on stderr (a terminal)
  double timeout = 0;     // seconds a deck may run (0: no limit)
};

// Exit status of a deck stopped by the batch's timeout (as timeout(1)'s).
constexpr int kExitTimedOut = 124;
// Seconds between the timeout's SIGTERM and SIGKILL.
constexpr double kGraceSeconds = 5;

struct BatchResult {
  std::string deck;
  int exitCode = 0;   // the deck's exit status (kExitInternal when it crashed)
  int signal = 0;     // the signal that ended the child, 0 when it exited
  int runs = 0, steps = 0, iterations = 0;
  int debrisRuns = 0, outsideRuns = 0;  // runs with debris figures; those outside the site
  double seconds = 0;  // wall time of the child
  std::string output;  // what the deck printed on standard output (summaries)
  std::string errors;  // and on standard error (its error message, warnings)
  bool started = false;      // false: the batch was interrupted before this deck
  bool timedOut = false;     // stopped by the timeout
  int interruptedBy = 0;     // the signal passed on from the batch, 0 when none

  bool ok() const { return started && exitCode == 0 && signal == 0 && !timedOut && !interruptedBy; }
  // "ok", "deck error", "analysis failed", "timed out", "interrupted (SIGTERM)",
  // "not run", "crashed (signal 11)", ...
  std::string status() const;
};

// Runs the decks; results in the order of `decks`. Each child's output is
// written to `out` as the child ends.
std::vector<BatchResult> runBatch(const std::vector<std::string>& decks, const BatchOptions& options,
                                  const DeckCalls& calls, std::ostream& out);
// The same for decks each run with options of its own (options.deck unused):
// the parts of one deck's runs (macro/batch/ParallelRuns.h).
struct BatchJob {
  std::string deck;
  DeckOptions options;
};
std::vector<BatchResult> runBatch(const std::vector<BatchJob>& jobs, const BatchOptions& options,
                                  const DeckCalls& calls, std::ostream& out);

void printBatchTable(std::ostream& os, const std::vector<BatchResult>& results);

// 0 when every deck succeeded, else the status of the first deck (in the
// given order) that did not.
int batchExitCode(const std::vector<BatchResult>& results);

// Two decks whose outputs would overwrite each other (same file stem): the
// message naming them, or "".
std::string batchStemClash(const std::vector<std::string>& decks);

}  // namespace c2d
