// ProblemRun's printed tables: nodal values (DISP, VELO, ACCE, REAC), section
// forces and the hinge table (STRE).
#include <algorithm>

#include "macro/deck/NumberRanges.h"
#include "macro/run/ProblemRun.h"
#include "macro/run/Report.h"

namespace c2d {

// ------------------------------------------------------------------ output

std::vector<int> ProblemRun::selection(const Macro& m, int count) const {
  std::vector<int> out;
  const bool all = m.option == "all" || m.numbers.empty() || m.record.text(2).empty();
  if (all) {
    for (int i = 0; i < count; ++i) out.push_back(i);
    return out;
  }
  const int n1 = m.numbers[0].evalInt(params_, "first number");
  int n2 =
      m.has(1) && !m.record.text(3).empty() ? m.numbers[1].evalInt(params_, "last number") : n1;
  int inc = m.has(2) && !m.record.text(4).empty() ? m.numbers[2].evalInt(params_, "increment") : 1;
  if (inc <= 0) inc = 1;
  for (int i : steppedRange(std::max(n1, 1), std::min(n2, count), inc)) out.push_back(i - 1);
  return out;
}

void ProblemRun::printNodal(const Macro& m) {
  const State& s = analysis_->state();
  std::vector<int> nodes;
  for (int n : selection(m, model_.numNodes()))
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
                   selection(m, model_.numElements()));
}

void ProblemRun::printHinges() {
  printHingeTable(log_, model_, analysis_->state(), analysis_->loadFactor(),
                  watches_.hingeSteps());
}

}  // namespace c2d
