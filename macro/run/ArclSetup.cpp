#include "macro/run/ArclSetup.h"

#include <optional>
#include <string>

#include "solvers/PathFollowing.h"

namespace c2d {

bool setUpArcl(const Macro& m, Analysis& analysis, const Model& model,
                      const Parameters& params, std::ostream& log) {
  if (m.option == "off") {
    analysis.setPathFollowing(std::nullopt);
    log << "  ARCL   off\n";
    return false;
  }
  const int kfl =
      m.has(0) && !m.record.text(2).empty() ? m.numbers[0].evalInt(params, "ARCL kfl") : 0;
  if (kfl < 4 && m.data.empty()) {
    // FEAPpv's arc length: the first step's load increment is its time step,
    // known when that step starts (advanceTime).
    log << "  ARCL   arc length (first load increment: the first step's dt)\n";
    return true;
  }
  const Record& rec = m.data.front();
  auto value = [&](std::size_t i) { return Expression::parse(rec[i]).eval(params); };
  if (kfl >= 4) {
    const int node = Expression::parse(rec[0]).evalInt(params, "node number");
    const int dof = Expression::parse(rec[1]).evalInt(params, "dof");
    if (node < 1 || node > model.numNodes() || dof < 1 || dof > 3)
      throw DeckError(rec.loc,
                      "ARCL: no node " + std::to_string(node) + " dof " + std::to_string(dof),
                      rec.lineText());
    analysis.assembler().refresh();
    const int eq = analysis.assembler().dofs().eq(node - 1, dof - 1);
    if (eq < 0)
      throw DeckError(rec.loc,
                      "ARCL: node " + std::to_string(node) + " dof " + std::to_string(dof) +
                          " is restrained (displacement control needs a free dof)",
                      rec.lineText());
    analysis.setPathFollowing(PathFollowing::displacementControl(eq, value(2)));
    log << "  ARCL   displacement control of node " << node << " dof " << dof << "\n";
  } else {
    // 'dlambda0' alone or 'ndamp dlambda0': the last value.
    analysis.setPathFollowing(PathFollowing::arcLength(value(rec.size() - 1)));
    log << "  ARCL   arc length\n";
  }
  return false;
}

}  // namespace c2d
