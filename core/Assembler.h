#pragma once
// Assembles the residual and the tangent of the whole model at a trial state.
//
// The residual per node dof is r = f_int + M a_eff - f_ext - f_contact. At a free
// dof it must vanish; at a restrained dof it is the reaction. M holds the
// elements' masses and the lumped nodal ones (core/FloorLoad.h). f_ext is
// lambda*FORCe plus the constant loads (self-weight, QLOAd, weight of MASS) and the
// forces of removed elements being released, with lambda per dof the factor of its
// proportional load table at the step rule's load point (t_n+1, or the mid-point
// for the mid-point scheme).
//
// The sparsity pattern and the scatter positions of every element are computed
// once per topology version; assemble() allocates nothing.
//
// Member contact couples a node with the ends of an element segment: its pairs
// are in the pattern too. The pattern holds the candidate pairs of the contact
// search (core/contact/ContactSearch.h) whose penetration is within a quarter of the
// search margin of touching (so the pairs that come into contact over the next
// steps are mostly there already) and is rebuilt, with the current candidates, only when
// a pair carrying a force is not in it; structureVersion() then changes and the
// solver analyses the new pattern.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/contact/ContactMotion.h"
#include "core/DofMap.h"
#include "core/contact/MemberContact.h"
#include "core/Model.h"
#include "core/State.h"
#include "core/SparseMatrix.h"

namespace c2d {

class Assembler {
 public:
  explicit Assembler(Model& model);

  // Rebuilds dof map, pattern and scatter maps when the model's topology version
  // changed; returns true when it did.
  bool refresh();
  const DofMap& dofs() const { return dofs_; }
  int patternVersion() const { return patternVersion_; }
  // Changes whenever the sparsity pattern does (topology or member contact pairs).
  int structureVersion() const { return structureVersion_; }
  // False when the tangent is unsymmetric in every scheme (ground friction).
  bool symmetricTangent() const { return !(model_.ground() && model_.ground()->mu > 0); }

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
  // Ground contact forces on the nodes at the last assembly, normal and
  // friction (per node dof; included in the residual with a minus sign).
  // Member contact forces are pairs inside the residual, like element forces.
  const Eigen::VectorXd& contactForces() const { return fContact_; }
  // Lumped nodal masses per node dof (MASS, QLOAd carried as mass).
  const Eigen::VectorXd& nodalMass() const { return mNodal_; }
  // The mass moving with each node's translation (core/NodeMass.h), per node.
  const std::vector<double>& nodeMasses() const { return masses_; }
  // Forces of removed elements being released (core/Model.h ReleasedForce) at
  // the load point of the last assembly, per node dof: a load.
  const Eigen::VectorXd& releasedLoad() const { return fRel_; }
  // Element e's residual (internal and inertia forces, global frame) at the last assembly.
  const ElemVec& elementForce(int e) const { return elemForce_[e]; }

  // Scatter a node-dof vector to equations (and back).
  void toEquations(const Eigen::VectorXd& nodal, Eigen::VectorXd& eqs) const;

  // Energies at the last assembled state.
  double strainEnergy() const;
  // Ground and member contact penalty energy (not const, as the other
  // questions about the member contact below: it keeps what it finds).
  double contactEnergy(const State& s);
  // The contacts' state at the end of the last assembled step into s when it
  // is committed: the ground's loading points and friction stretches, the
  // member contact pairs' memory. Returns the energy that released without
  // work (MemberContact::commit).
  // `given`: the energy the ground's contacts gave back of the scheme's decay
  // (core/contact/GroundContact.h groundImpactOwed), not in the return value.
  double commitContact(State& s, const StepRule& rule = {}, double* given = nullptr);
  // Member contact pairs whose node was pushed past the member's centre line
  // while in contact, since the assembler was made, and the energy released.
  int pushedThrough() const { return pushedThrough_; }
  double pushedThroughEnergy() const { return pushedThroughEnergy_; }
  // After the member contact starts or the topology changes (s committed):
  // pairs set free inside each other's contact distance start at zero force
  // (MemberContact::openPairs).
  void openContacts(State& s) {
    if (members_) members_->openPairs(model_, s);
  }
  double kineticEnergy(const State& s) const;
  // Linear momentum and angular momentum about the origin (counterclockwise)
  // of the elements and nodal masses at s (positions X + u).
  struct Momentum {
    Vec2 linear = Vec2::Zero();
    double angular = 0;
  };
  Momentum momentum(const State& s) const;
  // Energy the contact laws took over the step from the committed state to the
  // trial state s, >= 0: the dissipative terms of the ground and member contact
  // (mid-point scheme) and the ground friction. Under the static and Newmark
  // rules the penalty forces are plain gradients at t_n+1; what that loses or
  // gains is the integrator's, not counted here.
  double contactDissipation(const State& s, const StepRule& rule);

  // The motion over the step from the committed state to s of every contact
  // that touches at either end (ground nodes, then member pairs), into out.
  void contactMotions(const State& s, std::vector<ContactMotion>& out);

  // Starts the member contact search and its pattern afresh, as a new
  // assembler would (a continuation from a restart file is then bit for bit).
  void restartContactSearch();

  // The member contact (null without a MEMBers record).
  MemberContact* memberContact() { return members_.get(); }

 private:
  void buildPattern();
  // Member contact forces at s into contactForces_; rebuilds the pattern when
  // a pair with a force has no place in it.
  void evaluateMemberContact(const State& s, const StepRule& rule, bool wantTangent);
  // The released forces at the step rule's load point into fRel_.
  void releasedLoadAt(const State& s, const StepRule& rule);
  // assemble()'s steps: the elements' residuals and tangents, the lumped
  // nodal masses' inertia, the ground's contact and friction, the member
  // contact forces found by evaluateMemberContact.
  Status assembleElements(const State& s, const StepRule& rule, bool wantTangent);
  Status addNodalInertia(const State& s, const StepRule& rule, bool wantTangent);
  void addGroundContact(const State& s, const StepRule& rule, bool wantTangent);
  void addPairContact(bool wantTangent);

  Model& model_;
  DofMap dofs_;
  SparseMatrix K_;
  std::vector<std::array<int, kElemDofs * kElemDofs>> elemPos_;  // index into K_ values, -1: none
  std::vector<int> diagPos_;                                     // per equation
  std::vector<int> uvPos_;        // per node: K(eq u, eq v) for the ground friction, -1: none
  Eigen::VectorXd r_, fRef_, fGrav_, fContact_, mNodal_, fRel_;
  std::vector<double> masses_;         // per node (core/NodeMass.h)
  std::vector<double> groundDamping_;  // per node: the ground's dashpot coefficient
  std::vector<double> groundStick_;    // per node: the friction's stick dashpot (kN s/m)
  Eigen::VectorXd stretch_;  // per node: friction stretches at the end of the last assembled step
  Eigen::VectorXd stretchU_, stretchUn_;  // the state (u, u_n) stretch_ was evaluated at
  // The friction stretches that go with s: the last assembly's when it was of
  // s, else the committed ones (s is a committed state, or nothing assembled it).
  const Eigen::VectorXd& stretchesOf(const State& s) const;
  std::vector<ElemVec> elemForce_;  // per element, of the last assembly
  int patternVersion_ = -1;
  int structureVersion_ = 0;
  double forceScale_ = 0;

  std::unique_ptr<MemberContact> members_;
  int pushedThrough_ = 0;
  double pushedThroughEnergy_ = 0;
  std::vector<std::uint64_t> patternPairs_;   // sorted keys of the pairs in the pattern
  bool patternPending_ = false;  // refreshed with member contact: built at the next assembly
  std::vector<std::array<int, 36>> pairPos_;  // per pattern pair: index into K_ values
  struct PairForce {
    ContactPair pair;
    int slot = -1;  // index into patternPairs_
    PairVec force;
    PairMat tangent;
  };
  std::vector<PairForce> contactForces_;  // of the last assembly
};

}  // namespace c2d
