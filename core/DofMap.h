#pragma once
// Equation numbers of the node dofs for one topology version. A dof is an
// equation when it is free and some element (or joint) uses it; restrained
// dofs carry prescribed values and give reactions; a rotation that no element
// holds (Element::holdsRotation: every element there is jointed) is none. A shared joint aliases the
// slave's translations to the master's equations.
#include <array>
#include <vector>

#include "core/Model.h"

namespace c2d {

class DofMap {
 public:
  DofMap() = default;
  explicit DofMap(const Model& model);

  int numEquations() const { return numEq_; }
  int numNodes() const { return static_cast<int>(used_.size()); }
  int version() const { return version_; }

  // Equation of node dof (node*3 + dof), or -1 (restrained or unused).
  int eq(int nodeDof) const { return eq_[nodeDof]; }
  int eq(int node, int dof) const { return eq_[node * kNodeDofs + dof]; }
  bool used(int node) const { return used_[node]; }
  // The node is the slave of a shared joint (its translations are the master's).
  bool aliased(int node) const { return aliased_[node]; }
  bool restrained(int node, int dof) const { return restrained_[node * kNodeDofs + dof]; }
  std::array<int, kElemDofs> elementEqs(const Element& e) const;

 private:
  void orderForFill(const Model& model);

  std::vector<int> eq_;
  std::vector<char> used_, restrained_, aliased_;
  int numEq_ = 0;
  int version_ = -1;
};

}  // namespace c2d
