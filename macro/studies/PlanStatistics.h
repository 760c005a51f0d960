#pragma once
// [ext] The plans of an ensemble judged on their distributions: <stem>_plans.csv,
// one row per plan:
//   plan,<swept values...>,samples,failed,
//   F_min,F_p10,F_median,F_p90,F_max for F in left, right, left95, right95,
//   centroid, height, outside_mass (over the runs with debris figures),
//   p_outside,p_outside_lo,p_outside_hi (the share of those runs with debris
//   outside the SITE and its 95 % Wilson interval; empty without a site),
//   p_moving (the share still moving at their end)
// and the best plan: the least p_outside, then the least median reach95
// (max(left95, right95) of a run), with the test of its lead over the next
// plan on the paired runs (PairedComparison.h).
#include <string>
#include <vector>

#include "macro/studies/EnsembleTable.h"
#include "macro/studies/PairedComparison.h"

namespace c2d {

// The debris figures summarised per plan, in the table's order.
extern const std::vector<std::string> kPlanFigures;

struct PlanStats {
  int plan = 0;
  std::vector<double> swept;
  std::string name;   // the plan's name (SWEEp's PLAN record), "" without
  std::string label;  // its name, else "delay = 0.5", or "plan 1" without a sweep
  int samples = 0, failed = 0, debrisRuns = 0;
  // Per figure of kPlanFigures: min, p10, median, p90, max (NaN without runs).
  std::vector<std::array<double, 5>> quantiles;
  bool site = false;
  int outside = 0, moving = 0;
  double pOutside = 0, pOutsideLo = 0, pOutsideHi = 1, pMoving = 0;
  double medianReach95 = 0;
};

std::vector<PlanStats> planStatistics(const EnsembleData& data);
std::string plansCsv(const EnsembleData& data, const std::vector<PlanStats>& plans);

// The best plan and its lead over the next, as the log and the console say it
// (several lines, each starting with two blanks); "" with fewer than one plan.
std::string bestPlanText(const EnsembleData& data, const std::vector<PlanStats>& plans);
// The plans' table as the log prints it.
std::string plansText(const std::vector<PlanStats>& plans);

}  // namespace c2d
