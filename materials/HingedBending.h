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
//
// Signs of the moment: the laws of positive and negative moments may differ
// (HARDening/SOFTening NEGAtive, an RC section's bars); the bulk takes the law
// of its trial moment's sign, with one hardening variable (isotropic), the
// hinge the law of the sign it opened with.
//
// Moment-axial interaction (a MaterialSet with a capacity, materials/
// MomentCapacity.h): the laws' moments and moduli are those at the section's
// axial force N, passed in by the element. The history (plastic curvature,
// hardening and softening variables) is kept when N changes: the yield radius
// is R(xi, N), a hinge's capacity Mu(N) + Ks(N) xi with Ks(N) = -Mu(N)/xiF, so
// the share of its capacity a hinge has lost stays as it is. The response
// reports dM/dN for the elements' tangents.
//
// Hinges at the element ends (HingeSite::Ends): the element passes its end
// moments (from its equilibrium: a moment linear along the element, so the
// larger end moment is the element's largest); the hinge opens at the end
// whose moment first reaches Mu and is carried by a joint there
// (elements/JointedElement's hinge law), the midpoint never opens; this law
// then only reports the demand and which ends have opened.
#include <array>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>

#include "core/Error.h"
#include "core/Hinge.h"
#include "core/MaterialSet.h"
#include "materials/BilinearHardening.h"
#include "materials/LinearSoftening.h"
#include "materials/MomentCapacity.h"

namespace c2d {

// Value-type history of one section.
struct HingedBendingState {
  BendingState bulk;
  SofteningState jump;
  bool hingeActive = false;
  bool hingeFailed = false;  // capacity exhausted: a free hinge (t = 0)
  double hingeSign = 1;      // sign of the moment when the hinge was activated
  double M = 0;              // bending moment at this state
  double N = 0;              // axial force at this state (the laws' interaction)
  // HingeSite::Ends: the element's end moments at this state (section sign
  // convention: positive compresses the top face), and the hinges opened at
  // the ends (+-1: the sign of the moment at opening; 0: none).
  std::array<double, 2> endMoment{0, 0};
  std::array<double, 2> endHinge{0, 0};
};

struct HingedBendingResponse {
  HingedBendingState state;
  double tangent = 0;  // dM/d(kappaD)
  double dN = 0;       // dM/dN at fixed kappaD (moment-axial interaction)
};

// Restart files (core/io/Checkpoint.h): every field of the state.
void putSection(std::ostream& out, const HingedBendingState& s);
HingedBendingState getSection(std::istream& in);

class HingedBending {
 public:
  // Elastic bending unless the material set has HARDening; a hinge only with SOFTening.
  explicit HingedBending(const MaterialSet& mat);
  // The same law for both signs, not following N, hinge at the midpoint.
  HingedBending(const BilinearHardening& bending, std::optional<LinearSoftening> softening)
      : bending_{bending, bending}, softening_{softening, softening} {}

  double EI() const { return bending_[0].EI(); }
  bool hasHinge() const { return softening_[0].has_value(); }
  bool isElastic() const { return bending_[0].isElastic() && !softening_[0]; }
  HingeSite site() const { return site_; }
  const std::shared_ptr<const MomentCapacity>& capacity() const { return capacity_; }
  // The laws of positive (sign > 0) and negative moments as given (at N = 0).
  const BilinearHardening& bending(int sign = 1) const { return bending_[sign > 0 ? 0 : 1]; }
  const std::optional<LinearSoftening>& softening(int sign = 1) const {
    return softening_[sign > 0 ? 0 : 1];
  }
  // The ultimate moment of moments of `sign` at axial force N; 0 without a hinge.
  double ultimate(int sign, double N) const;

  // Response at curvature kappaD of an element of length l from the committed
  // history `from`, at axial force N. openSign = +-1 opens the (midpoint) hinge
  // in this evaluation (the solver decides when), with the sign of the moment
  // at activation; 0 leaves an inactive hinge closed. held: the section lies in
  // the localization zone of another element's open hinge, of a joint or of a
  // free end (elements/LocalizationZones.h) and opens none of its own; its closed hinge holds the
  // moment at Mu(N) (perfectly plastic: the bulk's plastic curvature takes the
  // rest, M dkp >= 0) instead of hardening past it.
  Status respond(double kappaD, double l, const HingedBendingState& from, double openSign,
                 HingedBendingResponse& out, double N = 0, bool held = false) const;

  // |M|/Mu of a state whose hinge could still open (the larger end's for
  // hinges at the ends); 0 otherwise.
  double demand(const HingedBendingState& s) const;
  bool canActivate(const HingedBendingState& s) const;
  // The hinge of a section state (core/Hinge.h).
  HingeInfo info(const HingedBendingState& s) const;
  // Opens the hinge of a trial state with the sign of its moment (the solver's
  // decision, core/Hinge.h): the next evaluation takes it from there. Hinges at
  // the ends: the end of the largest demand is marked.
  void open(HingedBendingState& s) const;
  // Hinges at the ends: the end of the larger demand whose hinge could still
  // open (-1: none, or not hinges at the ends), and opening that end with the
  // sign of its moment whatever its demand (solvers/HingeEvents opens an end
  // hinge at the lower end of a bracket across which the demand jumps past 1).
  int criticalEnd(const HingedBendingState& s) const;
  void openEnd(HingedBendingState& s, int end) const;
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
  // identity for elastic sections is unchanged. dM1 = dm/dM1 at fixed kappaD1
  // (for the moment's dependence on the axial force). With interaction a step
  // of plastic flow driven by N at almost no change of curvature would make r
  // unbounded: r is kept within kMidPointRatio there (the energy account books
  // what the step does).
  struct MidPointMoment {
    double m = 0, tangent = 0, dM1 = 0;
  };
  MidPointMoment midPointMoment(const HingedBendingState& from, double kappaD0,
                                const HingedBendingState& to, double kappaD1, double kt1, double l,
                                double w) const;
  static constexpr double kMidPointRatio = 10;
  // Elastic stored energy per unit length, M^2/(2 EI).
  double energyDensity(const HingedBendingState& s) const { return 0.5 * s.M * s.M / EI(); }

 private:
  // A held section past Mu(N): back to the moment Mu(N), tangent zero.
  void holdAtUltimate(double kappaD, HingedBendingResponse& out) const;
  // The bulk's return map at N, with dM/dN.
  BendingResponse bulk(const BendingState& from, double kappa, double N, double& dMdN) const;
  // The hinge's law of moments of `sign` at N (the law as given without a capacity).
  LinearSoftening softeningAt(int sign, double N, double* dMu = nullptr) const;

  std::array<BilinearHardening, 2> bending_;
  std::array<std::optional<LinearSoftening>, 2> softening_;
  std::shared_ptr<const MomentCapacity> capacity_;
  HingeSite site_ = HingeSite::Midpoint;
};

}  // namespace c2d
