#pragma once
// Assembles the residual and the tangent of the whole model at a trial state.
//
// The residual per node dof is r = f_int + M a_eff - f_ext - f_contact. At a free
// dof it must vanish; at a restrained dof it is the reaction. M holds the
// elements' masses and the lumped nodal ones (core/FloorLoad.h). f_ext is
// lambda*FORCe plus the constant loads (self-weight, QLOAd, weight of MASS), with lambda per dof the factor of its
// proportional load table at the step rule's load point (t_n+1, or the mid-point
// for the mid-point scheme).
//
// The sparsity pattern and the scatter positions of every element are computed
// once per topology version; assemble() allocates nothing.
#include <array>
#include <vector>

#include "core/DofMap.h"
#include "core/Model.h"
#include "core/State.h"
#include "solvers/LinearSolver.h"

namespace c2d {

class Assembler {
 public:
  explicit Assembler(Model& model);

  // Rebuilds dof map, pattern and scatter maps when the model's topology version
  // changed; returns true when it did.
  bool refresh();
  const DofMap& dofs() const { return dofs_; }
  int patternVersion() const { return patternVersion_; }

  // Evaluates every element and the ground contact. loadFactors (per node dof)
  // multiply FORCe.
  Status assemble(const State& s, const StepRule& rule, const Eigen::VectorXd& loadFactors,
                  bool wantTangent);

  const SparseMatrix& tangent() const { return K_; }
  // Largest element force of the last assembly: the scale of round-off in the residual.
  double forceScale() const { return forceScale_; }
  const Eigen::VectorXd& nodalResidual() const { return r_; }  // size numNodes*3
  // External load vector (FORCe pattern, unit factor) per node dof.
  const Eigen::VectorXd& referenceLoad() const { return fRef_; }
  // Constant loads: self-weight, element loads (QLOAd), weight of nodal masses.
  const Eigen::VectorXd& gravityLoad() const { return fGrav_; }
  // Contact forces on the nodes at the last assembly (per node dof; included in
  // the residual with a minus sign).
  const Eigen::VectorXd& contactForces() const { return fContact_; }
  // Lumped nodal masses per node dof (MASS, QLOAd carried as mass).
  const Eigen::VectorXd& nodalMass() const { return mNodal_; }

  // Scatter a node-dof vector to equations (and back).
  void toEquations(const Eigen::VectorXd& nodal, Eigen::VectorXd& eqs) const;

  // Energies at the last assembled state.
  double strainEnergy() const;
  double contactEnergy(const State& s) const;
  double kineticEnergy(const State& s) const;

 private:
  void buildPattern();
  void gather(const Element& e, const State& s, ElementKinematics& kin) const;

  Model& model_;
  DofMap dofs_;
  SparseMatrix K_;
  std::vector<std::array<int, kElemDofs * kElemDofs>> elemPos_;  // index into K_ values, -1: none
  std::vector<int> diagPos_;                                     // per equation
  Eigen::VectorXd r_, fRef_, fGrav_, fContact_, mNodal_;
  int patternVersion_ = -1;
  double forceScale_ = 0;
};

}  // namespace c2d
