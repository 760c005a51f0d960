#include "solvers/HingeEvents.h"

#include <algorithm>
#include <cmath>

#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/LocalizationZones.h"
#include "solvers/Analysis.h"

namespace c2d {

namespace {

// Demand band of a located event: the hinge opens at 1 <= demand <= 1 + band,
// band = the element's HingeCarrier::demandBand (1e-12 for a midpoint moment;
// an end moment M -+ V l/2 carries the shear's round-off, about 1e-11).
// Newton's iterations from the chord between a bracket's converged ends
// before the sub-step is solved from the committed state instead. The chord
// is off by the square of the bracket's width and takes 1-6 iterations; where
// it does not (a law's branch other than the committed state's and the
// bracket's ends: a damped section's moment turning, see
// materials/SectionDamping.h) its iterates wander for up to the 60 allowed,
// where the committed state converges in 3-17.
constexpr int kChordIterations = 15;
// A converged state past Mu by more than this opens an event. Elements left at
// their ultimate moment by a located event (demand up to 1 + band) do not
// open a second hinge in a step that does not load them further.
constexpr double kTrigger = 1e-9;
// The shortest dynamic sub-step to an event, as a fraction of the step: an
// event located closer to the step's start opens at the committed state. A
// sub-step's velocities are its displacements over its length h (Newmark:
// gamma / (beta h) times them), so the round-off of positions of metres, eps
// |u|, makes velocity errors of eps |u| / h: a sub-step of 5e-9 s (f = 5e-7 of
// a 10 ms step, a second hinge reaching Mu just after the first opened) changed
// the kinetic energy by 1.6e-6 of its 14 MJ with no work done. The error goes
// as 1 / f: at 1e-5 it is below 1e-7 of the kinetic energy, and the hinge
// opens below its capacity by at most 1e-5 of the step's change of demand
// (the opening books what it changes: locate()).
constexpr double kShortestFraction = 1e-5;

}  // namespace

const std::vector<std::pair<int, HingeCarrier*>>& HingeEvents::carriers() {
  Model& model = an_.model();
  if (carriersVersion_ == model.topologyVersion()) return carriers_;
  carriers_.clear();
  for (int e = 0; e < model.numElements(); ++e)
    if (!model.hasElement(e))
      continue;
    else if (auto* h = dynamic_cast<HingeCarrier*>(&innermost(model.element(e))))
      carriers_.emplace_back(e, h);
  carriersVersion_ = model.topologyVersion();
  return carriers_;
}

double HingeEvents::maxDemand(int& element) {
  double demand = 0;
  for (const auto& [e, h] : carriers()) demand = std::max(demand, h->hingeDemand());
  // Demands equal to round-off (a uniform moment) go to the lowest element
  // number, so that the place where the hinge opens does not depend on the
  // last bits of the solution.
  element = -1;
  for (const auto& [e, h] : carriers_)
    if (demand > 0 && h->hingeDemand() >= demand * (1 - 1e-12)) {
      element = e;
      break;
    }
  return demand;
}

void HingeEvents::committed() {
  // The zones of the hinges open in the committed state hold their members'
  // other elements from the next evaluation on (elements/LocalizationZones.h).
  zones_.hold(an_.model());
  int e = -1;
  committedDemand_ = maxDemand(e);
}

void HingeEvents::open(int element) {
  for (const auto& [e, h] : carriers())
    if (e == element) {
      h->activateHinge();
      if (an_.onHingeActivated) an_.onHingeActivated(e, h->hinge());
    }
}

void HingeEvents::openAt(int element, int end) {
  for (const auto& [e, h] : carriers())
    if (e == element) {
      h->activateHingeAt(end);
      if (an_.onHingeActivated) an_.onHingeActivated(e, h->hinge());
    }
}

Status HingeEvents::afterConvergence(IterationInfo& info, bool lineSearch, bool& handled) {
  handled = false;
  if (locating_ || carriers().empty()) return Status::success();
  // The end of the bracket: a converged state only.
  if (!info.converged)
    return Status::failure("internal: a hinge event after an unconverged iteration");
  // The demand of the converged state.
  if (Status st = an_.evaluateState(); !st) return st;
  int e = -1;
  if (maxDemand(e) <= 1.0 + kTrigger) return Status::success();
  handled = true;
  const Status st = locate(info, lineSearch);
  // The hinge opened at the step's end (the event was not found inside the
  // step): the step is done, converged where it was committed.
  if (st && info.converged) handled = false;
  return st;
}

Status HingeEvents::solveFraction(double fraction, double tEnd, bool lineSearch,
                                  const Eigen::VectorXd* start, int maxIterations) {
  // Elements keep their trial flags (a hinge just activated); their trial
  // history follows from the committed one at the next evaluation.
  State& s = an_.state_;
  solved_ = false;
  s.u = s.un;
  s.v = s.vn;
  s.a = s.an;
  s.arcLambda = s.arcLambdan;
  // A dynamic sub-step's rule follows from its length (Analysis::stepRule).
  an_.beginStep(s.tn + fraction * (tEnd - s.tn), fraction, false);
  if (start) {
    const DofMap& dofs = an_.assembler_.dofs();
    for (Eigen::Index i = 0; i < s.u.size(); ++i)
      if (dofs.eq(static_cast<int>(i)) >= 0) s.u[i] = (*start)[i];
    an_.updateRates();
  }
  IterationInfo it;
  double first = -1;
  for (int k = 0; k < maxIterations; ++k) {
    const Status st = an_.iterate(lineSearch, true, it);
    if (!st) return st;
    if (it.converged) break;
    // Diverging (the test of the solution commands' Newton loops): stop before
    // the iterates get so large that a correction falls below their resolution.
    if (first < 0 || it.iteration == 1) first = it.energy;
    if (it.iteration > 4 && it.energy > 1e30 * first) break;
  }
  if (!it.converged || !an_.converged_)
    return Status::failure("no convergence while locating the point where a hinge opens");
  const Status st = an_.evaluateState();  // element states at the converged displacements
  solved_ = st.ok;
  return st;
}

Status HingeEvents::solveBetween(double fraction, double sLo, double sHi, double tEnd,
                                 bool lineSearch) {
  // Between two converged states the solution is smooth but for the kinks of
  // the laws: the chord between them is off by the square of the bracket's
  // width, and Newton's method from there takes a correction or two, where one
  // from the committed state solves the whole sub-step again.
  // Dynamic steps only: a static step keeps Newton's path from the committed
  // state (with a softening hinge the start decides which branch the
  // iterates follow), and path following measures its constraint from there.
  if (!an_.integrator_.dynamic() || an_.path_) return solveFraction(fraction, tEnd, lineSearch);
  // (A bracket at round-off can close: its two ends are then one state.)
  const double w = sHi > sLo ? (fraction - sLo) / (sHi - sLo) : 1.0;
  start_ = uLo_ + w * (uHi_ - uLo_);
  if (solveFraction(fraction, tEnd, lineSearch, &start_, kChordIterations))
    return Status::success();
  return solveFraction(fraction, tEnd, lineSearch);
}

Status HingeEvents::evaluateOpened(int element) {
  // The innermost element at the committed displacements, its joints' relative
  // rotations as committed (JointedElement::innerKinematics).
  Element& el = an_.model().element(element);
  ElemVec r;
  ElemMat k;
  return innermost(el).evaluate(innermostKinematics(el, an_.state_), an_.stepRule(), false, r, k);
}

void HingeEvents::restoreCommitted() {
  // A sub-step of zero length: the committed state itself, not a solve (a
  // dynamic step of length zero has no step rule; the rule of dt would solve
  // a whole step from t_n and commit it at t_n).
  for (auto& el : an_.model().elements())
    if (el) el->revert();
  an_.state_.revert();
  an_.ratesStale_ = false;
  an_.dirty_ = false;
  solved_ = true;
}

Status HingeEvents::commitSolved() {
  // Only the converged end of a located sub-step (or the committed state) may
  // be committed here; this never fails in a correct run.
  if (!solved_) return Status::failure("internal: committing an unconverged state");
  return an_.commit();
}

Status HingeEvents::locate(IterationInfo& info, bool lineSearch) {
  // The demand is piecewise smooth in the step fraction: regula falsi
  // (Illinois) for max demand in [1, 1 + band], from above (see the header).
  // It is often kinked at the root (an element reaching another branch of its
  // law there): flat on one side, steep on the other, where the chord of the
  // bracket creeps over dozens of solves. So when the last two points of one
  // side are known, the secant through them (their true demands, not Illinois'
  // scaled ones) is tried first: on the flat side it lands next to the root.
  // A trial halves the bracket when the two before it did not bring the
  // demand four times closer to the target: a secant creeping along a flat
  // side does not. (A rule on the bracket's width instead threw away the
  // secant's approach from one side, where the other end stays put, at every
  // third trial, and the event then took three trials more.)
  State& s = an_.state_;
  locating_ = true;
  const double tEnd = s.t;
  int element = -1;
  double sLo = 0, dLo = committedDemand_, sHi = 1, dHi = maxDemand(element);
  double f = 0;
  bool found = dLo >= 1.0;  // the committed state is already at Mu: open there
  Status st;
  int side = 0;
  uLo_ = s.un;
  uHi_ = s.u;
  // The points each side had before its last update, and the true demands.
  double sLoOld = -1, dLoOld = 0, sHiOld = -1, dHiOld = 0, dLoTrue = dLo, dHiTrue = dHi;
  double band = 1e-12;
  // The hinge past its capacity at the bracket's upper end, and its end when
  // it may open below its capacity (HingeCarrier::earlyEnd).
  int elementHi = element, endHi = -1;
  for (const auto& [e, h] : carriers())
    if (e == element) {
      band = h->demandBand();
      endHi = h->earlyEnd();
    }
  const double target = 1.0 + 0.5 * band;
  // The closest approach to the target before each trial.
  double best[3] = {0, 0, 0};
  double closest = std::min(std::abs(dLo - target), std::abs(dHi - target));
  for (int k = 0; k < 60 && !found && sHi - sLo > 4e-16; ++k) {
    f = -1;
    if (side == -1 && sHiOld >= 0 && dHiTrue != dHiOld)
      f = sHi - (dHiTrue - target) * (sHi - sHiOld) / (dHiTrue - dHiOld);
    else if (side == 1 && sLoOld >= 0 && dLoTrue != dLoOld)
      f = sLo - (dLoTrue - target) * (sLo - sLoOld) / (dLoTrue - dLoOld);
    if (!(f > sLo && f < sHi)) f = sLo + (target - dLo) * (sHi - sLo) / (dHi - dLo);
    if (k >= 2 && closest > 0.25 * best[(k - 2) % 3]) f = 0.5 * (sLo + sHi);
    best[k % 3] = closest;
    f = std::clamp(f, sLo + 1e-9 * (sHi - sLo), sHi - 1e-9 * (sHi - sLo));
    st = solveBetween(f, sLo, sHi, tEnd, lineSearch);
    if (!st) break;
    const double d = maxDemand(element);
    found = d >= 1.0 && d <= 1.0 + band;
    if (found) break;
    closest = std::min(closest, std::abs(d - target));
    if (d > 1.0) {
      elementHi = element;
      endHi = -1;
      for (const auto& [e, h] : carriers_)
        if (e == element) endHi = h->earlyEnd();
      sHiOld = sHi;
      dHiOld = dHiTrue;
      sHi = f;
      dHi = dHiTrue = d;
      uHi_ = s.u;
      if (side == -1) dLo = 1.0 - 0.5 * (1.0 - dLo);
      side = -1;
    } else {
      sLoOld = sLo;
      dLoOld = dLoTrue;
      sLo = f;
      dLo = dLoTrue = d;
      uLo_ = s.u;
      if (side == 1) dHi = 1.0 + 0.5 * (dHi - 1.0);
      side = 1;
    }
  }
  // Not located within the band: the demand jumps past it between the
  // bracket's ends (a discontinuity in the step fraction: the axial force
  // driving Mu(N) to its floor at the diagram's ends within a sub-step, or
  // the step's own solution on another branch than the sub-steps' from the
  // committed state), or the 60 trials ran out. A hinge that may open below
  // its capacity (at a member's end: a joint rigid until its moment reaches
  // C(xi, N)) opens at the lower end, below Mu, so that no commit carries a
  // moment past its capacity: the rest of the step returns it to C(xi, N).
  // Others (a midpoint hinge takes its softening branch from Mu, a fracture
  // happens at eu) open at the closest point found past it.
  const bool early = st && !found && endHi >= 0;
  if (st && !found) f = early ? sLo : sHi;
  // An event within the shortest sub-step of the step's start opens at the
  // committed state (see kShortestFraction): the element that reached its
  // capacity there, at the end of its larger demand when it may open early.
  // (Dynamic steps only: a static sub-step has no velocities, and opens at its
  // located point.)
  const bool atStart = st && f > 0 && f < kShortestFraction && an_.integrator_.dynamic();
  int startEnd = -1;
  if (atStart) {
    if (!found) {
      element = elementHi;
      startEnd = endHi;
    } else {
      for (const auto& [e, h] : carriers_)
        if (e == element) startEnd = h->earlyEnd();
    }
    f = 0;
  }
  if (st && f == 0) {
    restoreCommitted();
  } else if (st && !found) {
    st = solveBetween(f, sLo, sHi, tEnd, lineSearch);
  }
  if (st) st = commitSolved();  // the sub-step up to the hinge's ultimate moment
  if (st) {
    if (atStart && startEnd >= 0) {
      openAt(element, startEnd);
    } else if (atStart) {
      open(element);
    } else if (early) {
      element = elementHi;
      openAt(element, endHi);
    } else {
      maxDemand(element);
      open(element);
    }
    info.hingeActivated = element;
    // At the ultimate moment the open hinge has no jump yet (to 1e-12): the
    // committed state is already the equilibrium. A step of length zero: only
    // the opened section is evaluated, and the elements commit in place. (An
    // evaluation of the whole model would take the rule of dt at t = t_n: a
    // dynamic step of dt for the internal unknowns, a joint's relative
    // rotation, with the nodes held, and Newmark's inertia forces in the
    // energy account.)
    // The account books what the opening changed at the committed positions,
    // as a step's commit books its stored energy: the balance closes at this
    // commit too (an opening below Mu lowered the moment there: 4e-6 of the
    // peak energy until the next step booked it).
    const double stored = an_.model().element(element).strainEnergy();
    st = evaluateOpened(element);
    if (st) an_.account_.released(stored - an_.model().element(element).strainEnergy());
  }
  if (st)
    st = solved_ ? an_.commitEvaluated()
                 : Status::failure("internal: committing an unconverged state");
  solved_ = false;
  locating_ = false;
  if (!st) return st;
  // The rest of the step; none when the hinge opened at the step's end (a
  // sub-step of length zero would take the rule of the whole step).
  if (1.0 - f <= 1e-12) {
    info.converged = true;
    return Status::success();
  }
  an_.beginStep(tEnd, 1.0 - f, false);
  info.converged = false;
  return Status::success();
}

}  // namespace c2d
