#pragma once
// [ext] What an ensemble ends with, from its table of runs as written
// (<stem>_ensemble.csv): <stem>_plans.csv (PlanStatistics.h),
// <stem>_sensitivity.csv (Sensitivity.h, when something is drawn),
// <stem>_ensemble.svg (EnsemblePicture.h), and the report the log and the
// console give: the plans' table, the best plan and its lead, the
// sensitivity. The same function serves a run and `collapse2d merge`, so both
// give the same files.
#include <filesystem>
#include <string>
#include <vector>

#include "macro/studies/EnsembleTable.h"

namespace c2d {

struct EnsembleStudyReport {
  std::string text;                          // the log's lines (each starting with two blanks)
  std::string summary;                       // the console's: the plans' table and the best plan
  std::vector<std::filesystem::path> files;  // written
};

// title: the problem's title, for the picture.
EnsembleStudyReport writeEnsembleStudy(const std::filesystem::path& dir, const std::string& stem,
                                       const EnsembleData& data, const std::string& title);

}  // namespace c2d
