#include "core/FloorLoad.h"

namespace c2d {

namespace {

// Reference length of element e, 0 when it is absent.
double referenceLength(const Model& model, int e) {
  if (e < 0 || e >= model.numElements() || !model.elements()[e]) return 0;
  const auto n = model.element(e).nodes();
  return (model.coord(n[1]) - model.coord(n[0])).norm();
}

}  // namespace

double carriedMassPerLength(const Model& model, const ElementLoad& load) {
  const double g = model.gravity().norm();
  return load.asMass && g > 0 ? load.q.norm() / g : 0.0;
}

Eigen::VectorXd floorLoadVector(const Model& model) {
  Eigen::VectorXd f =
      Eigen::VectorXd::Zero(static_cast<Eigen::Index>(model.numNodes()) * kNodeDofs);
  for (const ElementLoad& l : model.elementLoads()) {
    const double len = referenceLength(model, l.element);
    if (len == 0) continue;
    for (int n : model.element(l.element).nodes())
      f.segment<2>(static_cast<Eigen::Index>(n) * kNodeDofs) += 0.5 * len * l.q;
  }
  const Vec2& g = model.gravity();
  for (int n = 0; n < model.numNodes(); ++n) {
    const auto& m = model.nodalMass(n);
    f[n * kNodeDofs] += m[0] * g.x();
    f[n * kNodeDofs + 1] += m[1] * g.y();
  }
  return f;
}

Eigen::VectorXd lumpedNodalMass(const Model& model) {
  Eigen::VectorXd m =
      Eigen::VectorXd::Zero(static_cast<Eigen::Index>(model.numNodes()) * kNodeDofs);
  for (int n = 0; n < model.numNodes(); ++n)
    for (int d = 0; d < kNodeDofs; ++d) m[n * kNodeDofs + d] = model.nodalMass(n)[d];
  for (const ElementLoad& l : model.elementLoads()) {
    const double mu = carriedMassPerLength(model, l);
    const double len = referenceLength(model, l.element);
    if (mu == 0 || len == 0) continue;
    for (int n : model.element(l.element).nodes()) {
      m[n * kNodeDofs] += 0.5 * mu * len;
      m[n * kNodeDofs + 1] += 0.5 * mu * len;
    }
  }
  return m;
}

}  // namespace c2d
