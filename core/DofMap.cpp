#include "core/DofMap.h"

#include "core/FillOrder.h"

namespace c2d {

DofMap::DofMap(const Model& model) : version_(model.topologyVersion()) {
  const int nn = model.numNodes();
  eq_.assign(static_cast<size_t>(nn) * kNodeDofs, -1);
  used_.assign(nn, 0);
  aliased_.assign(nn, 0);
  restrained_.assign(static_cast<size_t>(nn) * kNodeDofs, 0);
  // A rotation that no element holds (every element at the node is jointed
  // there: the joints' relative rotations take up the node's) is no equation:
  // its row and column would be empty. It keeps its value.
  std::vector<char> rotationHeld(nn, 0);
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e)) {
      const Element& el = model.element(e);
      const auto n = el.nodes();
      for (int a = 0; a < 2; ++a) {
        used_[n[a]] = 1;
        if (el.holdsRotation(a)) rotationHeld[n[a]] = 1;
      }
    }
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
      if (d == 2 && !rotationHeld[n]) continue;
      eq_[nd] = numEq_++;
    }
  }
  for (int n = 0; n < nn; ++n)
    if (aliasOf[n] >= 0)
      for (int d = 0; d < 2; ++d) {
        restrained_[n * kNodeDofs + d] = restrained_[aliasOf[n] * kNodeDofs + d];
        eq_[n * kNodeDofs + d] = eq_[aliasOf[n] * kNodeDofs + d];
      }
  orderForFill(model);
}

void DofMap::orderForFill(const Model& model) {
  // Equations numbered in AMD order, so that the factorizations need no
  // permutation of their own (and no permuted copy of the matrix per
  // factorization): the graph of the equations, element by element.
  if (numEq_ < 3) return;
  std::vector<std::vector<int>> adj(numEq_);
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    const auto eqs = elementEqs(model.element(e));
    for (int i : eqs)
      if (i >= 0)
        for (int j : eqs)
          if (j >= 0 && j != i) adj[i].push_back(j);
  }
  const std::vector<int> perm = fillReducingOrder(adj);
  if (perm.empty()) return;
  std::vector<int> newNumber(numEq_);
  for (int k = 0; k < numEq_; ++k) newNumber[perm[k]] = k;
  for (int& eq : eq_)
    if (eq >= 0) eq = newNumber[eq];
}

std::array<int, kElemDofs> DofMap::elementEqs(const Element& e) const {
  std::array<int, kElemDofs> out{};
  const auto n = e.nodes();
  for (int a = 0; a < 2; ++a)
    for (int d = 0; d < kNodeDofs; ++d) out[a * kNodeDofs + d] = eq_[n[a] * kNodeDofs + d];
  return out;
}

}  // namespace c2d
