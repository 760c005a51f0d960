#pragma once
// Steps through impacts: a dynamic analysis shortens its steps where a contact
// (a ground node, a member pair) needs it, decided by the model alone.
//
// A penalty contact with restitution e and a dashpot is a fast oscillator: a
// mass m on the ground's k loads over (pi/2) sqrt(m/k) and unloads over e times
// that (10.2 t on k = 1e5: 16 and 5 ms), shorter than the decks' 10 ms step.
// Under the mid-point scheme the contact law's discrete gradient keeps the
// energy of any step exact and the peak of an impact is recovered from the
// step that turned (core/contact/CrushingLaw.h crushingLoadingPoint), so a point mass
// leaves with e v at any step, as long as its contact lasts more than one
// step: a contact that touched and turned, or turned and let go, within one
// step has no state from which its peak can be found. Newmark's trapezoidal
// rule integrates the law's kinks (touching, letting go, turning) with an
// error, and a dashpot's work c (dp/dt)^2 over an unresolved step is not its
// integral.
//
// After every converged step (or sub-step) from t_n to t_n+1, each contact that
// touched at either end is checked (core/contact/ContactMotion.h):
//   - a contact that touched and turned, or turned and let go, within the
//     step: the step is taken again, a quarter as long or one unloading time
//     1/omega_u of the contact's mass (omega_u = sqrt(k / (e^2 m))), whichever
//     is longer;
//   - the energy the scheme's integration of the law made or lost over the step,
//     |W_scheme - W_law| (the trapezoid of the end forces against the law's
//     work, Newmark; the dashpot's c (dp)^2 / h against c h (r0^2 + r0 r1 +
//     r1^2) / 3), against kTolerance e^2 of the contact's energy
//     m max(r0^2, r1^2) / 2 + U (the share an impact gives back): the ratio eta
//     grows as h^2, and a step with eta > 1 is taken again with
//     h 0.9 / sqrt(eta);
//   - a turn inside the step under the decaying mid-point scheme: its loss
//     beta m (r1 - r0)^2, which the ground contact gives back in shares of
//     loading and unloading (core/contact/GroundContact.h groundImpactOwed),
//     against the same kTolerance e^2 of the contact's energy.
// An accepted step proposes the next one, h min(2, 0.9 / sqrt(eta)), while a
// contact is in such a step; the next step of the deck's DT (TIME) is then
// taken in parts (Analysis::nextStepTime), which AUTO,CUT's cutting and
// regrowth of DT leave as they are. No step is shortened below
// kFloor of DT. A proposed step that fails and is cut is halved with DT when
// it is not longer than the halved DT (cut()): halving DT alone took it again
// as it was.
#include <istream>
#include <ostream>
#include <vector>

#include "core/Assembler.h"
#include "core/contact/ContactMotion.h"
#include "core/State.h"
#include "core/StepRule.h"

namespace c2d {

class ImpactSteps {
 public:
  // Off: every step keeps its length (tests of a law's per-step identities).
  void setEnabled(bool on) { enabled_ = on; }
  bool enabled() const { return enabled_; }

  // After a converged dynamic step from the committed state to s under rule
  // (rule.h its length), dt the deck's step: 0 when the step stands (and the
  // next is proposed), else the length to take it again with.
  double check(Assembler& a, const State& s, const StepRule& rule, double dt);
  // The length of the next step that the last step standing proposes (0: none).
  double proposal() const { return proposal_; }
  // A step was taken that was not checked (a static one, a located event's
  // sub-step): no proposal.
  void reset() { proposal_ = 0; }
  // A failed step is cut to dt (AUTO,CUT halved the deck's step): a proposal
  // not longer than dt would take the step again as it was, through the same
  // iterates, so it is halved with it.
  void cut(double dt) {
    if (proposal_ > 0 && proposal_ <= dt) proposal_ *= 0.5;
  }

  int rejected() const { return rejected_; }

  // Restart files: the proposal (and the count), so that a continuation takes
  // the same steps.
  void write(std::ostream& out) const;
  void read(std::istream& in);

  // What a contact's step needs, as the ratio eta (> 1: too long; see above);
  // kEvent for a contact that touched and turned or turned and let go in it.
  static double need(const ContactMotion& c, const StepRule& rule, double negligible = 0);
  static constexpr double kEvent = 1e300;
  static constexpr double kTolerance = 0.01;
  // A turn inside the step: the peak may lie this share beyond the steps'
  // ends. Newmark's rule integrates the turn's kink with an error that the
  // recovered peak carries (a 10.2 t mass on k = 1e5 left at 1.05 e v from
  // steps of 0.01 s with kPeak): its turns are resolved closer.
  static constexpr double kPeak = 0.1;
  static constexpr double kPeakNewmark = 0.02;
  static constexpr double kChatter = 10;
  static constexpr double kNegligible = 1e-4;
  static constexpr double kFloor = 1.0 / 256;

 private:
  bool enabled_ = true;
  bool growing_ = false;  // a step was taken again: the parts grow back by 2
  double proposal_ = 0;
  double peak_ = 0;  // the largest kinetic energy of the run at a checked step
  int rejected_ = 0;
  std::vector<ContactMotion> motions_;  // scratch
};

}  // namespace c2d
