#include "macro/run/PrescribedReach.h"

#include <algorithm>
#include <cmath>

#include "macro/deck/Limits.h"
#include "macro/output/NumberText.h"
#include "solvers/Analysis.h"

namespace c2d {

std::string prescribedBeyondReach(const Model& model, Analysis& analysis) {
  const State& s = analysis.state();
  const DofMap& dofs = analysis.assembler().dofs();
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!dofs.used(n)) continue;
    for (int d = 0; d < kNodeDofs; ++d) {
      const double given = model.disp(n)[d];
      const double u = s.u[static_cast<Eigen::Index>(n) * kNodeDofs + d];
      if (!dofs.restrained(n, d) || given == 0 || std::abs(u) <= DeckLimits::kMaxCoordinate)
        continue;
      const int table = std::max(1, model.loadTable(n)[d]);
      return "the prescribed " + std::string(d < 2 ? "displacement" : "rotation") + " of node " +
             std::to_string(n + 1) + ", dof " + std::to_string(d + 1) + " reaches " +
             formatNumber("%.6e", u) + " (DISPlacement " + formatNumber("%.6e", given) +
             " times the factor " + formatNumber("%.6e", analysis.tableFactor(table, s.t)) +
             " of proportional load table " + std::to_string(table) +
             "): beyond the largest this program takes (" +
             formatNumber("%g", DeckLimits::kMaxCoordinate) + ", the limit of the coordinates)";
    }
  }
  return {};
}

}  // namespace c2d
