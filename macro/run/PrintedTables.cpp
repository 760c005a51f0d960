#include "macro/run/PrintedTables.h"

#include "macro/run/CommandRange.h"
#include "macro/run/Report.h"

namespace c2d {

Status PrintedTables::nodal(const Macro& m, const Parameters& params, const Model& model,
                            Analysis& analysis) const {
  const State& s = analysis.state();
  std::vector<int> nodes;
  for (int n : commandRange(m, params, model.numNodes()))
    if (analysis.assembler().dofs().used(n) || model.hasCoord(n)) nodes.push_back(n);
  if (m.is("reac")) {
    Eigen::VectorXd r;
    const Status st = analysis.reactions(r);
    if (!st) return st;
    printNodalTable(log_, NodalQuantity::Reaction, model, s, analysis.loadFactor(), r, nodes,
                    longFormat_);
  } else if (m.is("velo")) {
    printNodalTable(log_, NodalQuantity::Velocity, model, s, analysis.loadFactor(), s.v, nodes,
                    longFormat_);
  } else if (m.is("acce")) {
    printNodalTable(log_, NodalQuantity::Acceleration, model, s, analysis.loadFactor(), s.a,
                    nodes, longFormat_);
  } else {
    printNodalTable(log_, NodalQuantity::Displacement, model, s, analysis.loadFactor(), s.u,
                    nodes, longFormat_);
  }
  return {};
}

Status PrintedTables::stresses(const Macro& m, const Parameters& params, Model& model,
                               Analysis& analysis) const {
  Eigen::VectorXd r;
  const Status st = analysis.reactions(r);  // evaluates every element at the current state
  if (!st) return st;
  printStressTable(log_, model, analysis.state(), analysis.loadFactor(),
                   commandRange(m, params, model.numElements()));
  return {};
}

void PrintedTables::hinges(Model& model, const Analysis& analysis,
                           const std::vector<int>& hingeSteps) const {
  printHingeTable(log_, model, analysis.state(), analysis.loadFactor(), hingeSteps);
}

}  // namespace c2d
