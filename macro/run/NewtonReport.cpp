#include "macro/run/NewtonReport.h"

#include <cstdio>
#include <sstream>

#include "macro/run/EnergyWatch.h"
#include "macro/output/NumberText.h"
#include "solvers/Analysis.h"

namespace c2d {

std::string newtonHistoryText(const Analysis& analysis) {
  std::ostringstream os;
  os << "    iteration      residual   energy |du.R|\n";
  for (const IterationInfo& i : analysis.stepHistory()) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "    %9d  %12.5e  %12.5e\n", i.iteration, i.residual, i.energy);
    os << buf;
  }
  int node = -1, dof = -1;
  const double r = analysis.largestResidual(node, dof);
  if (node >= 0)
    os << "    largest residual " << formatNumber("%.5e", r) << " at node " << node + 1 << ", dof "
       << dof + 1 << "\n";
  return os.str();
}

std::string newtonAdvice(Analysis& analysis, const EnergyWatch& energy, bool cutting,
                         const std::string& why, bool lineSearch, int iterations) {
  std::ostringstream os;
  if (energy.gainStep() > 0)
    os << "    " << energyGainText(energy.gained(), energy.gainStep(), energy.gainTime()) << "\n";
  os << "    to try:";
  if (why.find("singular") != std::string::npos) {
    os << " the model may be a mechanism or have lost all stiffness somewhere: check the "
          "BOUNdary codes, joints and released hinges near the node named;";
  }
  if (analysis.pathFollowing())
    os << " a smaller path increment (ARCL data)";
  else
    os << " a smaller step (DT,,dt)";
  if (!cutting)
    os << ", step cutting (AUTO,CUT,dtmin)";
  else
    os << ", a smaller dtmin (AUTO,CUT,dtmin)";
  if (!lineSearch && !analysis.pathFollowing()) os << ", a line search (TANG,LINE,1)";
  if (iterations > 0) os << ", more iterations (LOOP,," << 2 * iterations << ")";
  os << ", a looser tolerance (TOL,,etol,rtol)\n";
  return os.str();
}

}  // namespace c2d
