#pragma once
// Bending of a frame element's section with a softening plastic hinge at its
// critical point (paper section 2): the bulk follows the bilinear hardening law
// (BilinearHardening), the hinge the rigid-plastic softening law
// (LinearSoftening), and the rotation jump alpha is solved in closed form and
// condensed, so that the moment depends on the element's curvature alone.
//
// The element passes kappaD = (theta2 - theta1)/l (plus any initial-curvature
// shift of its own); with the embedded discontinuity (Gbar = -1/l) the bulk
// curvature is kappaD - alpha/l. The hinge equation -M + t = 0 makes the hinge
// moment t equal to the bulk moment M. The one-point elements of this program
// (InelasticFrame, small displacements; ReissnerFrame, finite) both integrate
// at the midpoint, where the jump leaves the rotation unchanged, so bending is
// the only part of the section the hinge touches.
//
// Once the hinge is active the bulk plastic curvature is frozen (eq 33) at the
// value where the bulk's yield radius reaches Mu (the plastic curvature
// kappa_p,u of verification.md V2), continuing the committed state along the
// hardening law in the direction of the moment at activation; a committed state
// already past Mu keeps its own. So the post-peak response does not depend on
// the step in which the solver happens to activate the hinge.
//
// A hinge whose rotation jump has been moved into a revolute joint (HINGE2JOINT,
// or a fully softened hinge during the run) is closed again with a fresh
// capacity: the joint is the broken section, and the rest of the element,
// whose bulk goes on with the hardening law from its history, can still open
// a hinge of its own at Mu (no member carries more than its capacity). A
// failed hinge with no end to put its joint at (a free end carries no moment:
// elements/HingeToJoint.h) stays failed.
#include <istream>
#include <optional>
#include <ostream>

#include "core/Error.h"
#include "core/Hinge.h"
#include "core/MaterialSet.h"
#include "materials/BilinearHardening.h"
#include "materials/LinearSoftening.h"

namespace c2d {

// Value-type history of one section.
struct HingedBendingState {
  BendingState bulk;
  SofteningState jump;
  bool hingeActive = false;
  bool hingeFailed = false;  // capacity exhausted: a free hinge (t = 0)
  double hingeSign = 1;      // sign of the moment when the hinge was activated
  double M = 0;              // bending moment at this state
};

struct HingedBendingResponse {
  HingedBendingState state;
  double tangent = 0;  // dM/d(kappaD)
};

// Restart files (core/Checkpoint.h): every field of the state.
void putSection(std::ostream& out, const HingedBendingState& s);
HingedBendingState getSection(std::istream& in);

class HingedBending {
 public:
  // Elastic bending unless the material set has HARDening; a hinge only with SOFTening.
  explicit HingedBending(const MaterialSet& mat);
  HingedBending(const BilinearHardening& bending, std::optional<LinearSoftening> softening)
      : bending_(bending), softening_(softening) {}

  double EI() const { return bending_.EI(); }
  bool hasHinge() const { return softening_.has_value(); }
  bool isElastic() const { return bending_.isElastic() && !softening_; }
  const BilinearHardening& bending() const { return bending_; }
  const std::optional<LinearSoftening>& softening() const { return softening_; }

  // Response at curvature kappaD of an element of length l from the committed
  // history `from`. openSign = +-1 opens the hinge in this evaluation (the
  // solver decides when), with the sign of the moment at activation; 0 leaves
  // an inactive hinge closed.
  Status respond(double kappaD, double l, const HingedBendingState& from, double openSign,
                 HingedBendingResponse& out) const;

  // |M|/Mu of a state whose hinge could still open; 0 otherwise.
  double demand(const HingedBendingState& s) const;
  bool canActivate(const HingedBendingState& s) const {
    return softening_ && !s.hingeActive;
  }
  // The hinge of a section state, at the element's midpoint (core/Hinge.h).
  HingeInfo info(const HingedBendingState& s) const;
  // Opens the hinge of a trial state with the sign of its moment (the solver's
  // decision, core/Hinge.h): the next evaluation takes it from there.
  void open(HingedBendingState& s) const;
  // The bending moment of the mid-point scheme (weight w = 1/2 + alpha) for a
  // step from section state `from` at curvature kappaD0 to `to` at kappaD1
  // (dM1/dkappaD1 = kt1), and its derivative with respect to kappaD1. With
  // dK = kappaD1 - kappaD0, dM = M1 - M0 and the plastic part of the step
  // dKp = dkp + dalpha/l (the bulk stays elastic: M = EI (kappaD - kp - alpha/l)),
  //   m = M1 - (1 - w) r dM,   r = 1 - dKp/dK = dM/(EI dK),
  // so that its work on the step is
  //   m dK l = l (M1^2 - M0^2)/(2 EI) + (w - 1/2) l dM^2/EI r + M1 dKp l,
  // the change of the stored energy plus the backward-Euler plastic work
  // M1 dKp >= 0 (the return maps flow along M1): a step never creates energy,
  // also when the moment reverses past yield within one step (the plain weighted
  // moment w M1 + (1 - w) M0 then did negative work). For an elastic step
  // (dKp = 0) m is the weighted moment w M1 + (1 - w) M0 and the scheme's
  // identity for elastic sections is unchanged.
  struct MidPointMoment {
    double m = 0, tangent = 0;
  };
  MidPointMoment midPointMoment(const HingedBendingState& from, double kappaD0,
                                const HingedBendingState& to, double kappaD1, double kt1, double l,
                                double w) const;
  // Elastic stored energy per unit length, M^2/(2 EI).
  double energyDensity(const HingedBendingState& s) const { return 0.5 * s.M * s.M / EI(); }

 private:
  BilinearHardening bending_;
  std::optional<LinearSoftening> softening_;
};

}  // namespace c2d
