#pragma once
// [ext] `collapse2d run -j N DECK` with one deck whose runs form a study (a
// SWEEp, an ENSEmble): its runs are split over N processes, as N shards of it
// (run --shard i/N, each in a child of the batch: macro/batch/BatchRunner.h), and the
// parts are merged when all have ended (Merge.h): the tables, the ensemble's
// statistics and picture, the overlays are those one process would write.
// The deck's log <stem>.out is the parts' logs joined: the header of the first
// part, every run's section in run order, then the study. The parts' own files
// are removed once merged (kept when the merge refuses them or a part fails
// other than by failed runs).
#include <ostream>
#include <string>

#include "macro/batch/BatchRunner.h"

namespace c2d {

// The exit status (0, 2 when some runs failed, the first failing part's status
// otherwise, 128 + N when interrupted), or -1 when the deck is not a study of
// several runs (run it as one deck).
int runDeckInParallel(const std::string& deck, const BatchOptions& options,
                      const DeckCalls& calls, std::ostream& out, std::ostream& err);

// The parts' logs of a deck joined as described above (text of <stem>.out).
std::string joinPartLogs(const std::vector<std::string>& partLogs, const std::string& study);

}  // namespace c2d
