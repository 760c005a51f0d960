// The analysis's Newton iteration (TANG, UTAN, FORM, SOLV): a correction solved
// and applied (with the prescribed increments, the rotation limit and the line
// search), the cycle and convergence tests, the check of the solve and the
// correction from the step's earlier factors.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "solvers/Analysis.h"
#include "solvers/LineSearch.h"
#include "solvers/linear/CheckedSolve.h"

namespace c2d {

void Analysis::applyIncrement(const Eigen::VectorXd& du, double scale) {
  const DofMap& dofs = assembler_.dofs();
  const Eigen::Index nd = state_.u.size();
  for (Eigen::Index i = 0; i < nd; ++i) {
    const int eq = dofs.eq(static_cast<int>(i));
    if (eq >= 0) state_.u[i] += scale * du[eq];
  }
  stepInc_ += scale * du;
  ratesStale_ = true;
}

double Analysis::rotationStepLimit(const Eigen::VectorXd& du, double s) const {
  if (!stepRule().rotationsByCayley()) return s;
  const DofMap& dofs = assembler_.dofs();
  for (Eigen::Index i = 2; i < state_.u.size(); i += kNodeDofs) {
    const int eq = dofs.eq(static_cast<int>(i));
    if (eq < 0) continue;
    const double inc = state_.u[i] - state_.un[i];
    if (std::abs(inc + s * du[eq]) < std::numbers::pi) continue;
    s = std::min(s, 0.5 * (std::copysign(std::numbers::pi, du[eq]) - inc) / du[eq]);
  }
  return s;
}

bool Analysis::holdPrescribed() {
  if (assembler_.patternVersion() != model_.topologyVersion()) topologyChanged();
  const DofMap& dofs = assembler_.dofs();
  bool moved = false;
  for (int n = 0; n < model_.numNodes(); ++n) {
    if (!dofs.used(n)) continue;
    for (int d = 0; d < kNodeDofs; ++d) {
      const int i = n * kNodeDofs + d;
      dPrescribed_[i] = 0;
      if (!dofs.restrained(n, d) || state_.u[i] == state_.un[i]) continue;
      dPrescribed_[i] = state_.u[i] - state_.un[i];
      state_.u[i] = state_.un[i];
      moved = true;
    }
  }
  return moved;
}

Status Analysis::addPrescribedIncrement() {
  const DofMap& dofs = assembler_.dofs();
  const StepRule rule = stepRule();
  ElementKinematics kin;
  ElemVec re, dp;
  ElemMat ke;
  Status st;
  for (int e = 0; e < model_.numElements() && st; ++e) {
    if (!model_.hasElement(e)) continue;
    Element& el = model_.element(e);
    const auto nodes = el.nodes();
    for (int a = 0; a < 2; ++a)
      dp.segment<kNodeDofs>(a * kNodeDofs) =
          dPrescribed_.segment<kNodeDofs>(static_cast<Eigen::Index>(nodes[a]) * kNodeDofs);
    if (dp.isZero(0)) continue;
    kin = state_.kinematics(nodes);
    // The same evaluation as in the assembly just done: the element's trial state is unchanged.
    st = el.evaluate(kin, rule, true, re, ke);
    if (!st) {
      st = Status::failure("element " + std::to_string(e + 1) + ": " + st.why);
      break;
    }
    const ElemVec f = ke * dp;
    for (int a = 0; a < 2; ++a)
      for (int d = 0; d < kNodeDofs; ++d) {
        const int eq = dofs.eq(nodes[a], d);
        if (eq >= 0) R_[eq] -= f[a * kNodeDofs + d];
      }
  }
  return st;
}

Status Analysis::iterate(bool lineSearch, bool symmetric, IterationInfo& info) {
  const Status st = newtonIteration(lineSearch, symmetric, info);
  // From a predicted start the iteration fails, or its energy grows past the
  // first value: the prediction lies outside the region where Newton's method
  // converges (a fast rotation extrapolated linearly stretches the members).
  // The step starts again from the committed state.
  if (predicted_ && !info.subStep &&
      (!st || (!keepPrediction_ && !info.converged && info.iteration >= 2 &&
               !(info.energy <= energy0_)))) {
    for (auto& el : model_.elements())
      if (el) el->revert();
    state_.u = state_.un;
    beginStep(state_.t, 1.0, false);
    const int iteration = info.iteration;
    info = IterationInfo{};
    info.iteration = iteration;
    info.restarted = true;
    return Status::success();
  }
  return st;
}

Status Analysis::newtonIteration(bool lineSearch, bool symmetric, IterationInfo& info) {
  info = IterationInfo{};
  info.iteration = static_cast<int>(history_.size()) + 1;
  Status st = newtonCorrection(symmetric, info);
  if (!st) return st;
  if (path_) {
    st = followPath(info);
    if (!st) return st;
  } else {
    info.energy = std::abs(du_.dot(R_));
  }
  if (!std::isfinite(info.energy)) return Status::failure("non-finite solution increment");
  if (info.iteration == 1) energy0_ = info.energy;

  const double s = lineSearchScale(lineSearch, info);
  applyIncrement(du_, rotationStepLimit(du_, s));
  dirty_ = true;
  ++totalIterations_;

  info.converged = convergedAt(info.energy, info.iteration);
  // Through an impact the step may be too long for a contact: taken again
  // shorter from the committed state (solvers/ImpactSteps.h).
  if (info.converged && integrator_.dynamic() && !path_ && !hinges_.locating() &&
      shortenedForImpact(info))
    return Status::success();
  if (info.converged) {
    syncRates();
    // A hinge past its ultimate moment: the event is located, and the rest of
    // the step starts a new iteration history.
    bool handled = false;
    st = hinges_.afterConvergence(info, lineSearch || globalized_, handled);
    if (!st) return st;
    if (handled) {
      converged_ = false;
      return Status::success();
    }
  }
  // A landing time of the member removal inside the step (a blast, the end
  // of a release): the step is committed there, the removal made, and the
  // rest of the step starts a new iteration history.
  if (info.converged && !hinges_.locating() && !path_ &&
      state_.t < stepEnd_ - MemberRemoval::tolerance(state_.dt))
    return commitAtRemoval(info);
  converged_ = info.converged;
  history_.push_back(info);
  // Plain Newton cycling (on the kinks of a hardening law, of the contact
  // laws): the line search of TANG,LINE takes over.
  if (!info.converged && !lineSearch && !globalized_ && !path_ && cycling()) globalize(info);
  return Status::success();
}

Status Analysis::newtonCorrection(bool symmetric, IterationInfo& info) {
  // The first iteration of a static step takes the prescribed displacement
  // increments through the tangent of the converged state (FEAP's treatment of
  // specified boundary values). Evaluated with the increments already in place,
  // the elements next to a prescribed dof would take the whole increment: an
  // element at its yield surface would load plastically there while the
  // solution unloads it, and in a softening step Newton's method can then
  // cycle between sets of branches none of which holds the solution.
  const bool predictor =
      info.iteration == 1 && !path_ && !integrator_.dynamic() && holdPrescribed();
  Status st = assemble();
  info.residual = R_.norm();
  // Close to the solution (the residual below 1e-6 of the step's first one)
  // the tangent changes little from one iteration to the next: the Newton
  // correction is first sought with the factors of the step's last tangent
  // (solveWithEarlierFactors). When that succeeds and the correction passes the
  // convergence test, the step ends without a new factorization.
  bool reused = false;
  if (st && !predictor && !path_ && !history_.empty() &&
      analyzedVersion_ == assembler_.structureVersion() &&
      info.residual <= 1e-6 * history_.front().residual)
    reused = solveWithEarlierFactors() && convergedAt(std::abs(du_.dot(R_)), info.iteration);
  if (st && !reused) st = factor(symmetric);
  if (predictor) {
    if (st) st = addPrescribedIncrement();
    state_.u += dPrescribed_;
  }
  if (!st) return st;
  if (!reused) {
    st = solver_->solve(R_, du_);
    if (!st) return Status::failure("linear solve failed: " + st.why);
    st = checkSolve();
    if (!st) return st;
  }
  return Status::success();
}

Status Analysis::followPath(IterationInfo& info) {
  const StepRule rule = stepRule();
  dofFactors(state_.t, rule.loadWeight(), lamn_);
  lamn_ = lamn_.cwiseProduct(assembler_.referenceLoad());
  assembler_.toEquations(lamn_, F_);
  Status st = solver_->solve(F_, duF_);
  if (!st) return Status::failure("linear solve failed: " + st.why);
  double dlambda = 0;
  st = path_->correction(stepInc_, du_, duF_, dlambda);
  if (!st) return Status::failure("path following: " + st.why);
  du_ += dlambda * duF_;
  state_.arcLambda += dlambda;
  stepDlambda_ += dlambda;
  // K du = R + dlambda F: the energy of the whole increment.
  info.energy = std::abs(du_.dot(R_) + dlambda * du_.dot(F_));
  return Status::success();
}

double Analysis::lineSearchScale(bool lineSearch, const IterationInfo& info) {
  double s = 1.0;
  if ((lineSearch || globalized_) && !path_ && info.iteration > 1 && info.energy > 0) {
    const StepRule rule = stepRule();
    s = bracketedLineSearch(du_.dot(R_), [&](double step, double& out) -> bool {
      applyIncrement(du_, step);
      const Status s2 = assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
      assembler_.toEquations(assembler_.nodalResidual(), duF_);  // reuse work vector
      out = -du_.dot(duF_);
      applyIncrement(du_, -step);
      return s2.ok;
    });
  }
  return s;
}

bool Analysis::shortenedForImpact(IterationInfo& info) {
  syncRates();
  const double h = impacts_.check(assembler_, state_, stepRule(), state_.dt);
  if (!(h > 0)) return false;
  for (auto& el : model_.elements())
    if (el) el->revert();
  state_.u = state_.un;
  beginStep(state_.tn + h, state_.dt > 0 ? h / state_.dt : 1.0, true);
  info.converged = false;
  info.subStep = true;
  info.shortened = h;
  converged_ = false;
  return true;
}

Status Analysis::commitAtRemoval(IterationInfo& info) {
  const Status st = commit();
  if (!st) return st;
  const double t = nextStepTime();
  beginStep(t, state_.dt > 0 ? (t - state_.tn) / state_.dt : 1.0, true);
  info.converged = false;
  info.subStep = true;
  converged_ = false;
  return Status::success();
}

void Analysis::globalize(IterationInfo& info) {
  // A static step starts again from the committed state, so that a step
  // TANG,LINE converges converges here too, through the same iterates; a
  // dynamic one goes on from the iterate it reached (from u_n the inertia
  // residual is that of the whole velocity: the line search took 9-10
  // iterations more from there on the main example with member contact).
  // The iterations from here on are the line search's (a static step's
  // history starts again with them).
  history_.back().globalized = true;
  if (!integrator_.dynamic()) {
    for (auto& el : model_.elements())
      if (el) el->revert();
    state_.u = state_.un;
    beginStep(state_.t, 1.0, false);
  }
  globalized_ = true;
  info.globalized = true;
}

bool Analysis::cycling() const {
  // The energy (or the residual) of the last iterations repeats. Statics:
  // period one to three to 1e-6 (the kinks of the hardening laws: an RC
  // cantilever in tension pushed at its tip cycled with period three, its
  // sections passing first yield and back; the paper's decks keep their
  // located events), or the residual runs away (ConvergenceTest.h runsAway).
  // Dynamics: a period of one to six to 1 % (ConvergenceTest.h
  // stopsProgressing: the contact laws' kinks).
  const bool dynamic = integrator_.dynamic();
  constexpr std::size_t kWindow = 12;
  if (!dynamic) {
    double residual[kWindow];
    const std::size_t all = std::min(history_.size(), kWindow);
    for (std::size_t k = 0; k < all; ++k) residual[k] = history_[history_.size() - all + k].residual;
    // From the step's first iteration: the least residual is the step's.
    if (history_.size() <= kWindow && runsAway(residual, all)) return true;
  }
  const std::size_t n = std::min(history_.size(), dynamic ? kWindow : 6);
  if (n < 4) return false;
  double energy[kWindow], residual[kWindow];
  for (std::size_t k = 0; k < n; ++k) {
    energy[k] = history_[history_.size() - n + k].energy;
    residual[k] = history_[history_.size() - n + k].residual;
  }
  // Dynamics with contact: no progress over two iterations (the energy above
  // the one two iterations before, from the fourth on) is a cycle on the
  // contact laws' kinks beginning: its repeats match to 1 % only some
  // iterations later (a typical step of the main example with member contact
  // rose at its 5th iteration, was seen cycling at its 10th). Taken at the
  // rise: 71.0k -> 53.9k iterations, 1608 -> 1301 cuts there (one history
  // each). Without contact a smooth step's energy may rise once on the way
  // (the double pendulum's fast swings), and the line search then slowed it.
  const bool kinked = model_.ground().has_value() || model_.memberContact().has_value();
  if (dynamic && kinked && history_.size() >= 4 &&
      history_.back().energy > history_[history_.size() - 3].energy)
    return true;
  const int periods = dynamic ? 6 : 3;
  const double tolerance = dynamic ? 1e-2 : 1e-6;
  return stopsProgressing(energy, n, periods, tolerance) ||
         stopsProgressing(residual, n, periods, tolerance);
}

Status Analysis::checkSolve() {
  // A mechanism's tangent leaves the residual unbalanced; an ill-conditioned
  // one may too until refined or factored with pivoting (solvers/linear/CheckedSolve).
  CheckedSolve check;
  if (check.check(*solver_, assembler_.tangent(), R_, du_, rho_, drho_)) return Status::success();
  // The mechanism's motion: the largest component of the correction.
  const DofMap& dofs = assembler_.dofs();
  int node = -1, dof = -1;
  double largest = -1;
  for (int i = 0; i < dofs.numNodes() * kNodeDofs; ++i) {
    const int eq = dofs.eq(i);
    if (eq < 0 || eq >= du_.size() || !(std::abs(du_[eq]) > largest)) continue;
    largest = std::abs(du_[eq]);
    node = i / kNodeDofs;
    dof = i % kNodeDofs;
  }
  return Status::failure(check.diagnosis() + "; the correction is largest at node " +
                         std::to_string(node + 1) + ", dof " + std::to_string(dof + 1));
}

bool Analysis::solveWithEarlierFactors() {
  // Iterative refinement of K du = R with the factors of an earlier K as the
  // preconditioner: the linear residual shrinks by |K_old^-1 (K - K_old)| per
  // sweep. Accepted at 1e-6 of R within three sweeps: the correction is then
  // Newton's to far below the quadratic remainder it leaves, so converged
  // states (and the energy balance of the conserving scheme) are those of
  // Newton's method. A solver without valid factors (the last factorization
  // failed) fails the solve: the caller factors afresh.
  const SparseMatrix& k = assembler_.tangent();
  const double target = 1e-6 * R_.norm();
  if (!solver_->solve(R_, du_)) return false;
  for (int sweep = 0; sweep < 3; ++sweep) {
    rho_.noalias() = k * du_;
    rho_ = R_ - rho_;
    if (rho_.norm() <= target) return true;
    if (!solver_->solve(rho_, drho_)) return false;
    du_ += drho_;
  }
  return false;
}

bool Analysis::convergedAt(double energy, int iteration) const {
  ConvergenceTest::Figures f;
  f.iteration = iteration;
  f.energy = energy;
  f.energy0 = energy0_;
  f.previousEnergy = history_.empty() ? -1.0 : history_.back().energy;
  f.residual = R_.norm();
  f.residual0 = history_.empty() ? f.residual : history_.front().residual;
  f.largestResidual = R_.size() ? R_.cwiseAbs().maxCoeff() : 0.0;
  f.roundoff = 1e-10 * assembler_.forceScale();
  f.largestCorrection = du_.size() ? du_.cwiseAbs().maxCoeff() : 0.0;
  f.positions = coordScale_ + (state_.u.size() ? state_.u.cwiseAbs().maxCoeff() : 0.0);
  f.pathFollowing = path_.has_value();
  return test_.converged(f);
}

double Analysis::largestResidual(int& node, int& dof) const {
  node = dof = -1;
  double largest = 0;
  const DofMap& dofs = assembler_.dofs();
  for (int i = 0; i < dofs.numNodes() * kNodeDofs; ++i) {
    const int eq = dofs.eq(i);
    if (eq < 0 || eq >= R_.size() || std::abs(R_[eq]) <= largest) continue;
    largest = std::abs(R_[eq]);
    node = i / kNodeDofs;
    dof = i % kNodeDofs;
  }
  return largest;
}

Status Analysis::formResidual(double& norm) {
  if (assembler_.patternVersion() != model_.topologyVersion()) topologyChanged();
  const StepRule rule = stepRule();
  Status st = assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
  if (!st) return st;
  assembler_.toEquations(assembler_.nodalResidual(), R_);
  R_ = -R_;
  norm = R_.norm();
  return Status::success();
}

Status Analysis::solveOnly(IterationInfo& info) {
  info = IterationInfo{};
  info.iteration = static_cast<int>(history_.size()) + 1;
  info.residual = R_.norm();
  if (analyzedVersion_ != assembler_.structureVersion())
    return Status::failure("SOLV without a factored tangent (use TANG first)");
  Status st = solver_->solve(R_, du_);
  if (!st) return st;
  info.energy = std::abs(du_.dot(R_));
  if (info.iteration == 1) energy0_ = info.energy;
  applyIncrement(du_, 1.0);
  dirty_ = true;
  info.converged = convergedAt(info.energy, info.iteration);
  if (info.converged) syncRates();
  converged_ = info.converged;
  history_.push_back(info);
  return Status::success();
}

}  // namespace c2d
