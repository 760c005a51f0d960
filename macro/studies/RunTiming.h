#pragma once
// [ext] <stem>_timing.csv: the CPU seconds of each run of an ensemble,
//   run,plan,sample,cpu_s
// beside <stem>_ensemble.csv and in its order. CPU time differs from process
// to process, so it is kept out of the ensemble table (whose bytes a sharded
// study's merge reproduces); `collapse2d merge` joins the parts' timing
// tables by run (Merge.h), as it joins the ensemble's.
#include <string>
#include <utility>
#include <vector>

#include "macro/studies/EnsembleTable.h"

namespace c2d {

inline constexpr const char* kTimingHeader = "run,plan,sample,cpu_s";

// The table's text for the ensemble's rows.
std::string timingCsv(const EnsembleTable& table);

// The rows of a timing table's text as (run, line), every cell checked.
// Throws std::runtime_error naming the line and column of a bad row: another
// header, a cell count other than 4, a run, plan or sample that is not a
// count, a cpu_s that is not a number at least 0, a cut last row.
std::vector<std::pair<int, std::string>> readTimingRows(const std::string& text);

}  // namespace c2d
