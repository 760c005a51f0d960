#include "solvers/FiniteResults.h"

#include <cmath>
#include <sstream>
#include <utility>

namespace c2d {

namespace {

std::string describe(const std::string& what, double value) {
  std::ostringstream os;
  os << what << " is " << value;
  return os.str();
}

// The first entry of a per node dof vector that is not finite.
std::string nodal(const char* what, const Eigen::VectorXd& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      return describe(std::string(what) + " of node " + std::to_string(i / kNodeDofs + 1) +
                          ", dof " + std::to_string(i % kNodeDofs + 1),
                      v[i]);
  return {};
}

}  // namespace

std::string nonFiniteResult(const Model& model, const State& state,
                            const Eigen::VectorXd& nodalResidual, const Energy& energy) {
  if (!std::isfinite(state.t)) return describe("the time", state.t);
  for (const auto& [what, v] :
       {std::pair{"the displacement", &state.u}, std::pair{"the velocity", &state.v},
        std::pair{"the acceleration", &state.a},
        std::pair{"the nodal force (reaction)", &nodalResidual}})
    if (std::string bad = nodal(what, *v); !bad.empty()) return bad;
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    const SectionForces f = model.element(e).sectionForces();
    for (const auto& [name, x] : {std::pair{"N", f.N}, std::pair{"V", f.V}, std::pair{"M", f.M}})
      if (!std::isfinite(x))
        return describe(
            "the section force " + std::string(name) + " of element " + std::to_string(e + 1), x);
  }
  for (const auto& [name, x] :
       {std::pair{"kinetic", energy.kinetic}, std::pair{"strain", energy.strain},
        std::pair{"contact", energy.contact}, std::pair{"external", energy.external},
        std::pair{"dissipated", energy.dissipated}})
    if (!std::isfinite(x)) return describe("the " + std::string(name) + " energy", x);
  return {};
}

}  // namespace c2d
