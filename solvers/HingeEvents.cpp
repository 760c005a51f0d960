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
  // Then from the sub-step's constant-velocity prediction, whose inertia
  // residual is of order h^2; from the committed state (last) it is 2 M v_n / h,
  // of the whole velocity (docs/history.md, the ten-storey building with a core).
  const State& s = an_.state_;
  start_ = s.un + (s.tn + fraction * (tEnd - s.tn) - s.tn) * s.vn;
  if (s.vn.size() == s.un.size() && solveFraction(fraction, tEnd, lineSearch, &start_))
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

// The step fractions around an event, their demands, and the event's point
// once found (locate()).
struct HingeEvents::Bracket {
  double sLo = 0, dLo = 0, sHi = 1, dHi = 0;
  // The points each side had before its last update, and the true demands.
  double sLoOld = -1, dLoOld = 0, sHiOld = -1, dHiOld = 0, dLoTrue = 0, dHiTrue = 0;
  int side = 0;  // the side the last trial moved: -1 the upper end, 1 the lower
  double band = 1e-12, target = 0;
  int element = -1;  // the element of the largest demand at the last solve
  // The hinge past its capacity at the bracket's upper end, and its end when
  // it may open below its capacity (HingeCarrier::earlyEnd).
  int elementHi = -1, endHi = -1;
  // The closest approach to the target before each trial.
  double best[3] = {0, 0, 0};
  double closest = 0;
  double f = 0;        // the step fraction of the last trial, then the event's
  bool found = false;  // located within the band
  // The event's point: an early opening at the lower end, or at the
  // committed state (at the end startEnd when >= 0).
  bool early = false, atStart = false;
  int startEnd = -1;

  // The step fraction of trial k: the secant through one side's last two
  // points, else regula falsi; the bisection when the last trials did not
  // close in on the target.
  double trial(int k) {
    double t = -1;
    if (side == -1 && sHiOld >= 0 && dHiTrue != dHiOld)
      t = sHi - (dHiTrue - target) * (sHi - sHiOld) / (dHiTrue - dHiOld);
    else if (side == 1 && sLoOld >= 0 && dLoTrue != dLoOld)
      t = sLo - (dLoTrue - target) * (sLo - sLoOld) / (dLoTrue - dLoOld);
    if (!(t > sLo && t < sHi)) t = sLo + (target - dLo) * (sHi - sLo) / (dHi - dLo);
    if (k >= 2 && closest > 0.25 * best[(k - 2) % 3]) t = 0.5 * (sLo + sHi);
    best[k % 3] = closest;
    return std::clamp(t, sLo + 1e-9 * (sHi - sLo), sHi - 1e-9 * (sHi - sLo));
  }
};

HingeEvents::Bracket HingeEvents::startBracket() {
  const State& s = an_.state_;
  Bracket b;
  b.dLo = committedDemand_;
  b.dHi = maxDemand(b.element);
  b.found = b.dLo >= 1.0;  // the committed state is already at Mu: open there
  uLo_ = s.un;
  uHi_ = s.u;
  b.dLoTrue = b.dLo;
  b.dHiTrue = b.dHi;
  b.elementHi = b.element;
  for (const auto& [e, h] : carriers())
    if (e == b.element) {
      b.band = h->demandBand();
      b.endHi = h->earlyEnd();
    }
  b.target = 1.0 + 0.5 * b.band;
  b.closest = std::min(std::abs(b.dLo - b.target), std::abs(b.dHi - b.target));
  return b;
}

Status HingeEvents::bracketEvent(Bracket& b, double tEnd, bool lineSearch) {
  Status st;
  for (int k = 0; k < 60 && !b.found && b.sHi - b.sLo > 4e-16; ++k) {
    b.f = b.trial(k);
    // A dynamic trial inside the shortest sub-step of the step's start is not
    // solved: the event opens at the committed state (reachEvent). Its inertia
    // residual, 2 M v / h from the committed state, is at h = 1e-9 dt beyond
    // what round-off lets Newton's method reduce, and from the prediction its
    // energy is round-off from the start.
    if (b.f < kShortestFraction && an_.integrator_.dynamic()) {
      b.sHi = b.f;  // so that a hinge not found opens at the start, not past Mu
      break;
    }
    st = solveBetween(b.f, b.sLo, b.sHi, tEnd, lineSearch);
    if (!st) break;
    const double d = maxDemand(b.element);
    b.found = d >= 1.0 && d <= 1.0 + b.band;
    if (b.found) break;
    b.closest = std::min(b.closest, std::abs(d - b.target));
    narrow(b, d);
  }
  return st;
}

void HingeEvents::narrow(Bracket& b, double d) {
  const State& s = an_.state_;
  if (d > 1.0) {
    b.elementHi = b.element;
    b.endHi = -1;
    for (const auto& [e, h] : carriers_)
      if (e == b.element) b.endHi = h->earlyEnd();
    b.sHiOld = b.sHi;
    b.dHiOld = b.dHiTrue;
    b.sHi = b.f;
    b.dHi = b.dHiTrue = d;
    uHi_ = s.u;
    if (b.side == -1) b.dLo = 1.0 - 0.5 * (1.0 - b.dLo);
    b.side = -1;
  } else {
    b.sLoOld = b.sLo;
    b.dLoOld = b.dLoTrue;
    b.sLo = b.f;
    b.dLo = b.dLoTrue = d;
    uLo_ = s.u;
    if (b.side == 1) b.dHi = 1.0 + 0.5 * (b.dHi - 1.0);
    b.side = 1;
  }
}

Status HingeEvents::reachEvent(Bracket& b, double tEnd, bool lineSearch) {
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
  b.early = !b.found && b.endHi >= 0;
  if (!b.found) b.f = b.early ? b.sLo : b.sHi;
  // An event within the shortest sub-step of the step's start opens at the
  // committed state (see kShortestFraction): the element that reached its
  // capacity there, at the end of its larger demand when it may open early.
  // (Dynamic steps only: a static sub-step has no velocities, and opens at its
  // located point.)
  b.atStart = b.f > 0 && b.f < kShortestFraction && an_.integrator_.dynamic();
  b.startEnd = -1;
  if (b.atStart) {
    if (!b.found) {
      b.element = b.elementHi;
      b.startEnd = b.endHi;
    } else {
      for (const auto& [e, h] : carriers_)
        if (e == b.element) b.startEnd = h->earlyEnd();
    }
    b.f = 0;
  }
  Status st;
  if (b.f == 0) {
    restoreCommitted();
  } else if (!b.found) {
    st = solveBetween(b.f, b.sLo, b.sHi, tEnd, lineSearch);
  }
  if (st) st = commitSolved();  // the sub-step up to the hinge's ultimate moment
  return st;
}

Status HingeEvents::openEvent(const Bracket& b, IterationInfo& info) {
  int element = b.element;
  if (b.atStart && b.startEnd >= 0) {
    openAt(element, b.startEnd);
  } else if (b.atStart) {
    open(element);
  } else if (b.early) {
    element = b.elementHi;
    openAt(element, b.endHi);
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
  const Status st = evaluateOpened(element);
  if (st) an_.account_.released(stored - an_.model().element(element).strainEnergy());
  return st;
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
  locating_ = true;
  const double tEnd = an_.state_.t;
  Bracket b = startBracket();
  Status st = bracketEvent(b, tEnd, lineSearch);
  if (st) st = reachEvent(b, tEnd, lineSearch);
  if (st) st = openEvent(b, info);
  if (st)
    st = solved_ ? an_.commitEvaluated()
                 : Status::failure("internal: committing an unconverged state");
  solved_ = false;
  locating_ = false;
  if (!st) return st;
  // The rest of the step; none when the hinge opened at the step's end (a
  // sub-step of length zero would take the rule of the whole step).
  if (1.0 - b.f <= 1e-12) {
    info.converged = true;
    return Status::success();
  }
  // From the rest's constant-velocity prediction (dynamic steps): from the
  // event's state its inertia residual would be 2 M v / h, of the whole
  // velocity, the larger the shorter the rest.
  an_.beginStep(tEnd, 1.0 - b.f, true);
  info.converged = false;
  return Status::success();
}

}  // namespace c2d
