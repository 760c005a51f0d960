#pragma once
// [ext] The plans of an ensemble judged on their distributions: <stem>_plans.csv,
// one row per plan:
//   plan,<swept values...>,samples,failed,
//   F_min,F_p10,F_median,F_p90,F_max for F in left, right, left95, right95,
//   centroid, height, outside_mass (over the runs with debris figures),
//   p_outside,p_outside_lo,p_outside_hi (the share of those runs with debris
//   outside the SITE and its 95 % Wilson interval; empty without a site),
//   p_moving (the share still moving at their end),
//   p_felled,p_felled_lo,p_felled_hi (the share of the runs with a verdict
//   (SITE's dir) that were felled, and its 95 % Wilson interval; empty without)
//   then per protected zone z (ZoneStatistics.h): p_<z>,p_<z>_lo,p_<z>_hi,
//   mass_<z>_median,mass_<z>_max,p_<z>_bound,runs_<z>_needed,p_flyrock_<z>,
//   p_flyrock_<z>_lo,p_flyrock_<z>_hi, and over them p_protected,
//   p_protected_lo,p_protected_hi,protected_mass_mean
// and the best plan, with the test of its lead over the next plan on the
// paired runs (PairedComparison.h). With protected zones: the least share of
// runs hitting any, then the least mean mass in them, then the least median
// 95 % reach toward the protected sides (a side that receives the debris is no
// zone and never counts); without a site: the least median reach95
// (max(left95, right95) of a run).
#include <string>
#include <vector>

#include "macro/studies/EnsembleTable.h"
#include "macro/studies/PairedComparison.h"
#include "macro/studies/ZoneStatistics.h"

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
  // The runs with a verdict (SITE's dir), those felled, and the share felled
  // with its 95 % Wilson interval.
  int verdicts = 0, felled = 0;
  double pFelled = 0, pFelledLo = 0, pFelledHi = 1;
  // The protected zones (SITE) over the runs with debris figures.
  ProtectedStats protection;
};

std::vector<PlanStats> planStatistics(const EnsembleData& data);
std::string plansCsv(const EnsembleData& data, const std::vector<PlanStats>& plans);

// The best plan and its lead over the next, as the log and the console say it
// (several lines, each starting with two blanks); "" with fewer than one plan.
std::string bestPlanText(const EnsembleData& data, const std::vector<PlanStats>& plans);
// The plans' table as the log prints it.
std::string plansText(const std::vector<PlanStats>& plans);
// Per plan and protected zone: the exact upper bound on the probability of a
// hit, the runs that would show it below the site's risk level and whether
// the study has shown it ("" without zones).
std::string riskText(const std::vector<PlanStats>& plans);

}  // namespace c2d
