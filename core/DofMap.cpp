#include "core/DofMap.h"

namespace c2d {

DofMap::DofMap(const Model& model) : version_(model.topologyVersion()) {
  const int nn = model.numNodes();
  eq_.assign(static_cast<size_t>(nn) * kNodeDofs, -1);
  used_.assign(nn, 0);
  aliased_.assign(nn, 0);
  restrained_.assign(static_cast<size_t>(nn) * kNodeDofs, 0);
  for (int e = 0; e < model.numElements(); ++e)
    for (int n : model.element(e).nodes()) used_[n] = 1;
  // The slave of a shared joint is attached to its own elements; its translations
  // follow the master's equations.
  std::vector<int> aliasOf(nn, -1);
  for (const Joint& j : model.joints())
    if (j.form == JointForm::Shared) {
      aliasOf[j.slave] = j.master;
      aliased_[j.slave] = 1;
    }

  for (int n = 0; n < nn; ++n) {
    const auto& code = model.bound(n);
    for (int d = 0; d < kNodeDofs; ++d) {
      const int nd = n * kNodeDofs + d;
      restrained_[nd] = code[d] != 0;
      if (!used_[n] || restrained_[nd]) continue;
      if (aliasOf[n] >= 0 && d < 2) continue;  // numbered from the master below
      eq_[nd] = numEq_++;
    }
  }
  for (int n = 0; n < nn; ++n)
    if (aliasOf[n] >= 0)
      for (int d = 0; d < 2; ++d) {
        restrained_[n * kNodeDofs + d] = restrained_[aliasOf[n] * kNodeDofs + d];
        eq_[n * kNodeDofs + d] = eq_[aliasOf[n] * kNodeDofs + d];
      }
}

std::array<int, kElemDofs> DofMap::elementEqs(const Element& e) const {
  std::array<int, kElemDofs> out{};
  const auto n = e.nodes();
  for (int a = 0; a < 2; ++a)
    for (int d = 0; d < kNodeDofs; ++d) out[a * kNodeDofs + d] = eq_[n[a] * kNodeDofs + d];
  return out;
}

}  // namespace c2d
