// ProblemRun's printed tables: nodal values (DISP, VELO, ACCE, REAC), section
// forces and the hinge table (STRE).
#include <algorithm>

#include "macro/run/CommandRange.h"
#include "macro/run/ProblemRun.h"
#include "macro/run/Report.h"

namespace c2d {

void ProblemRun::printNodal(const Macro& m) {
  const State& s = analysis_->state();
  std::vector<int> nodes;
  for (int n : commandRange(m, params_, model_.numNodes()))
    if (analysis_->assembler().dofs().used(n) || model_.hasCoord(n)) nodes.push_back(n);
  if (m.is("reac")) {
    Eigen::VectorXd r;
    const Status st = analysis_->reactions(r);
    if (!st) fail(m, st.why);
    printNodalTable(log_, NodalQuantity::Reaction, model_, s, analysis_->loadFactor(), r, nodes,
                    longFormat_);
  } else if (m.is("velo")) {
    printNodalTable(log_, NodalQuantity::Velocity, model_, s, analysis_->loadFactor(), s.v, nodes,
                    longFormat_);
  } else if (m.is("acce")) {
    printNodalTable(log_, NodalQuantity::Acceleration, model_, s, analysis_->loadFactor(), s.a,
                    nodes, longFormat_);
  } else {
    printNodalTable(log_, NodalQuantity::Displacement, model_, s, analysis_->loadFactor(), s.u,
                    nodes, longFormat_);
  }
}

void ProblemRun::printStresses(const Macro& m) {
  Eigen::VectorXd r;
  const Status st = analysis_->reactions(r);  // evaluates every element at the current state
  if (!st) fail(m, st.why);
  printStressTable(log_, model_, analysis_->state(), analysis_->loadFactor(),
                   commandRange(m, params_, model_.numElements()));
}

void ProblemRun::printHinges() {
  printHingeTable(log_, model_, analysis_->state(), analysis_->loadFactor(),
                  watches_.hingeSteps());
}

}  // namespace c2d
