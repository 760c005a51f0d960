#pragma once
// The softening law of a hinge at a member's end (HingeSite::Ends), carried by
// the revolute joint made there when the hinge opens (elements/JointedElement):
// the joint is rigid while the moment it carries is below the capacity
//   C(xi, N) = Mu(N) max(1 - xi / xiF, 0),
// and slips beyond it (rigid-plastic, the moment at the capacity, opposing
// the slip), xi the accumulated |slip| (rad): the hinge's moment falls
// linearly with its rotation jump, Ks = -Mu/xiF, until it is a free joint at
// xi = xiF; with a residual moment Mr (the broken section's, SOFTening's Mr)
// the softening stops where the capacity reaches it, at xi = xiF (1 - Mr/Mu)
// (Mu at the opening), and the joint keeps Mr as its friction from then on
// (elements/JointedElement). Mu follows the member's axial force N (moment-axial interaction,
// materials/MomentCapacity.h) at the sign of the moment the hinge opened with,
// for either direction of the moment; xiF is fixed at the opening, so the
// share of its capacity a hinge has lost stays when N changes.
// Units: moments kN m (the decks' system), rotations rad.
#include <memory>

#include "materials/MomentCapacity.h"

namespace c2d {

class EndHinge {
 public:
  // capacity: the member's (null: a fixed Mu); sign: of the moment at opening;
  // Mu at the opening; requires Mu > 0, xiF > 0 and 0 <= Mr < Mu (throws
  // std::invalid_argument).
  EndHinge(std::shared_ptr<const MomentCapacity> capacity, int sign, double Mu, double xiF,
           double Mr = 0);

  int sign() const { return sign_; }
  double failureJump() const { return xiF_; }
  double ultimate(double N) const { return capacity_ ? capacity_->at(sign_, N).Mu : mu_; }
  // Spent: softened to the residual moment (to zero without one).
  bool failed(double xi) const { return xi >= xiEnd_; }
  double residual() const { return mr_; }
  // C(xi, N) and its derivatives with respect to xi and N.
  struct Value {
    double C = 0, dXi = 0, dN = 0;
  };
  Value capacity(double xi, double N) const;
  // The parameters as built (restart files rebuild it from them and the member's capacity).
  double givenUltimate() const { return mu_; }

 private:
  std::shared_ptr<const MomentCapacity> capacity_;
  int sign_;
  double mu_, xiF_, mr_, xiEnd_;
};

}  // namespace c2d
