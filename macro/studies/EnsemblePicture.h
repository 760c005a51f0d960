#pragma once
// [ext] The picture of an ensemble, <stem>_ensemble.svg, over the distance
// beyond the footprint: u = x - xmin_footprint (< 0) on its left,
// u = x - xmax_footprint (> 0) on its right, the footprint itself at u = 0
// (gray line), with the site's edges (red dashed) and the protected zones
// (purple dotted) marked:
//   reach: per plan, the probability that the debris reaches past u (on the
//        right the share of runs whose rightmost node lies beyond it, on the
//        left the share whose leftmost lies before it);
//   lies: per plan, the probability that debris lies at u (the share of runs
//        whose debris covers it: the ensemble table's `cover`).
// When the two are the same for every plan (contiguous debris), one panel
// shows them. The legend is a strip of its own below the charts (it covers no
// curve); one curve per plan, from its runs with debris figures.
#include <string>
#include <vector>

#include "macro/studies/EnsembleTable.h"
#include "macro/studies/PlanStatistics.h"

namespace c2d {

// "" when no run has debris figures.
std::string ensembleSvg(const EnsembleData& data, const std::vector<PlanStats>& plans,
                        const std::string& title, int points = 400);

}  // namespace c2d
