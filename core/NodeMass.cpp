#include "core/NodeMass.h"

#include <limits>

#include "core/FloorLoad.h"

namespace c2d {

std::vector<double> translationalMasses(const Model& model) {
  const int nn = model.numNodes();
  std::vector<double> mass(static_cast<std::size_t>(nn), 0.0);
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    const Element& el = model.element(e);
    const ElemMat m = el.mass();
    const auto nodes = el.nodes();
    // The vertical translations' rows (the horizontal ones give the same).
    for (int a = 0; a < 2; ++a)
      mass[nodes[a]] += m(a * kNodeDofs + 1, 1) + m(a * kNodeDofs + 1, kNodeDofs + 1);
  }
  const Eigen::VectorXd lumped = lumpedNodalMass(model);
  for (int n = 0; n < nn; ++n) mass[n] += lumped[static_cast<Eigen::Index>(n) * kNodeDofs + 1];
  for (const Joint& j : model.joints())
    if (j.form == JointForm::Shared && j.slave >= 0 && j.slave < nn && j.master >= 0 &&
        j.master < nn) {
      mass[j.master] += mass[j.slave];
      mass[j.slave] = 0;
    }
  for (int n = 0; n < nn; ++n)
    if (model.bound(n)[0] != 0 && model.bound(n)[1] != 0)
      mass[n] = std::numeric_limits<double>::infinity();
  return mass;
}

}  // namespace c2d
