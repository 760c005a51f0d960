#pragma once
// [ext] The picture of an ensemble, <stem>_ensemble.svg: two charts over the
// position x along the ground, with the footprint (gray lines) and the site
// limits (red dashed lines):
//   top: per plan, the probability that the debris reaches past x (on the
//        right of the footprint the share of runs whose rightmost node lies
//        beyond x, on the left the share whose leftmost lies before x): the
//        distribution of the reach on each side, read against the site;
//   bottom: per plan, the probability that debris lies at x (the share of runs
//        whose debris covers x: the ensemble table's `cover`).
// One curve per plan, from its runs with debris figures.
#include <string>
#include <vector>

#include "macro/studies/EnsembleTable.h"
#include "macro/studies/PlanStatistics.h"

namespace c2d {

// "" when no run has debris figures.
std::string ensembleSvg(const EnsembleData& data, const std::vector<PlanStats>& plans,
                        const std::string& title, int points = 400);

}  // namespace c2d
