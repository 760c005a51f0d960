#pragma once
// Ability of an element to carry a softening plastic hinge (embedded rotation
// discontinuity). Activation is decided globally, one hinge at a time, so that
// a uniform moment localizes in exactly one element: after a converged Newton
// iteration the solver asks every inactive hinge for its demand |M|/Mu and
// activates the largest one above 1, then iterates again.
namespace c2d {

struct HingeInfo {
  bool active = false;        // jump activated
  bool failed = false;        // fully softened: moment down to zero, a free hinge
  double position = 0.5;      // critical point s_d / l_e along the element
  double jump = 0;            // rotation jump alpha (rad)
  double moment = 0;          // hinge moment t (signed)
  double softening = 0;       // softening variable xi = |alpha| accumulated
  double ultimate = 0;        // the ultimate moment Mu of the law
};

class HingeCarrier {
 public:
  virtual ~HingeCarrier() = default;
  // |M|/Mu at the critical point of the last evaluated trial state; 0 when the
  // element has no softening law or its hinge is already active.
  virtual double hingeDemand() const = 0;
  // Activate the hinge in the trial state (made permanent by commit(), dropped by revert()).
  virtual void activateHinge() = 0;
  virtual HingeInfo hinge() const = 0;  // at the last evaluated trial state
};

}  // namespace c2d
