#include "elements/MemberFold.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Hinge.h"
#include "elements/Joints.h"

namespace c2d {

std::vector<MemberFold> foldedMembers(const Model& model, const State& state) {
  constexpr double kQuarterTurn = 0.5 * std::numbers::pi;
  std::vector<MemberFold> out;
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    const Element& in = innermost(model.element(e));
    const MaterialSet* mat = model.material(in.materialNumber());
    if (!mat || !(mat->hardening || mat->softening)) continue;
    // The rotations at the inner element's ends (a condensed joint's relative
    // rotation added at its end).
    const ElementKinematics kin = innermostKinematics(model.element(e), state);
    const double fold = std::abs(kin.d[5] - kin.d[2]);
    if (!(fold > kQuarterTurn)) continue;
    const auto* carrier = dynamic_cast<const HingeCarrier*>(&in);
    out.push_back({e, {in.nodes()[0], in.nodes()[1]}, fold, carrier && carrier->hinge().failed});
  }
  std::sort(out.begin(), out.end(),
            [](const MemberFold& a, const MemberFold& b) { return a.fold > b.fold; });
  return out;
}

}  // namespace c2d
