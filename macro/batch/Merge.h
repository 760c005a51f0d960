#pragma once
// [ext] `collapse2d merge DIR`: joins the parts of studies run with
// `collapse2d run --shard i/n` (macro/batch/Shard.h) into what one run would have
// written:
//   - a deck's study: for every complete set <stem>_part<i>of<n>_*: the plans
//     table <stem>_plans.csv (a SWEEp: its rows ordered by run), or the
//     ensemble's <stem>_ensemble.csv and from it <stem>_plans.csv,
//     <stem>_sensitivity.csv and <stem>_ensemble.svg (EnsembleStudy.h), and the
//     overlays of the runs' curves; equal to the unsharded run's files;
//   - the batch tables batch_part<i>of<n>.csv into batch.csv (a deck split
//     over the parts gets one row: the first failure's status, the counts
//     summed).
// Every part is checked before anything is written, and a bad one is refused
// by name (the set is not merged): a part missing, empty or cut in the middle
// of a row; a header unlike the others'; a manifest that names another part,
// another deck (its fingerprint) or another run count; runs other than exactly
// those of shard i of n (a row missing, doubled, or part 1 copied over part 2);
// text in a number column.
#include <filesystem>
#include <ostream>
#include <string>

namespace c2d {

// 0 when every set found was merged, 1 when a set was refused (messages on
// err), 3 when a file cannot be read or written.
int mergeParts(const std::filesystem::path& dir, std::ostream& out, std::ostream& err);

// The parts of one deck's study alone, <stem>_part<i>of<n>_* in dir: true when
// merged; log (when given) receives what the deck's log says of the study.
// Throws IoError when a file cannot be read or written.
bool mergeStudyParts(const std::filesystem::path& dir, const std::string& stem, int n,
                     std::ostream& out, std::ostream& err, std::string* log = nullptr);

}  // namespace c2d
