#include "solvers/Analysis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <string>

#include "core/output/Checkpoint.h"
#include "solvers/linear/CheckedSolve.h"
#include "solvers/LineSearch.h"

namespace c2d {

Analysis::Analysis(Model& model)
    : model_(model), assembler_(model), hinges_(*this), removal_(*this) {
  setLinearSolver("auto");
  state_.prop = state_.propn = 1.0;  // FEAP: loads at full value until a PROP table is given
  history_.reserve(64);  // a step's iterations: a longer step than any before allocates nothing
  topologyChanged();
}

bool Analysis::setLinearSolver(const std::string& name) {
  auto s = makeLinearSolver(name);
  if (!s) return false;
  solver_ = std::move(s);
  solverName_ = name;
  analyzedVersion_ = -1;
  return true;
}

void Analysis::setLoadFunction(int table, const ProportionalLoad& f) {
  if (table < 1) table = 1;
  if (static_cast<int>(tables_.size()) <= table) tables_.resize(table + 1);
  tables_[table] = f;
  state_.prop = tableFactor(1, state_.t);
}

double Analysis::tableFactor(int table, double time) const {
  if (table < 1) table = 1;
  if (table < static_cast<int>(tables_.size()) && tables_[table]) return (*tables_[table])(time);
  return 1.0;
}

int Analysis::tableCount() const {
  int n = std::max(1, static_cast<int>(tables_.size()) - 1);
  for (int t : tableOf_) n = std::max(n, t);
  return n;
}

void Analysis::dofFactors(double time, double arc, Eigen::VectorXd& out) const {
  constexpr int kCached = 16;
  double values[kCached];
  const int nt = std::min<int>(kCached, std::max<int>(2, static_cast<int>(tables_.size())));
  for (int k = 0; k < nt; ++k) values[k] = arc * tableFactor(k, time);
  out.resize(static_cast<Eigen::Index>(tableOf_.size()));
  for (size_t i = 0; i < tableOf_.size(); ++i)
    out[static_cast<Eigen::Index>(i)] =
        tableOf_[i] < nt ? values[tableOf_[i]] : arc * tableFactor(tableOf_[i], time);
}

const Eigen::VectorXd& Analysis::stepLoadFactors(const StepRule& rule) {
  dofFactors(state_.t, path_ ? state_.arcLambda : 1.0, lam_);
  if (rule.scheme == Scheme::MidPoint) {
    dofFactors(state_.tn, path_ ? state_.arcLambdan : 1.0, lamn_);
    lam_ = 0.5 * (lam_ + lamn_);
  }
  return lam_;
}

void Analysis::setPathFollowing(std::optional<PathFollowing> p) {
  const bool wasOn = path_.has_value();
  path_ = std::move(p);
  // Switched on after load-controlled steps: the load level reached stays
  // applied (factor 1), and the path following moves it from there.
  if (path_ && !wasOn && state_.step > 0) state_.arcLambda = state_.arcLambdan = 1.0;
}

void Analysis::topologyChanged() {
  state_.resize(model_.numNodes());
  assembler_.refresh();
  assembler_.openContacts(state_);
  topology_.index(model_);
  const int neq = assembler_.dofs().numEquations();
  const Eigen::Index nd = static_cast<Eigen::Index>(model_.numNodes()) * kNodeDofs;
  R_.setZero(neq);
  du_.setZero(neq);
  rho_.setZero(neq);
  drho_.setZero(neq);
  duF_.setZero(neq);
  F_.setZero(neq);
  stepInc_.setZero(neq);
  rNodal_.setZero(nd);
  account_.resize(model_.numNodes());
  dPrescribed_.setZero(nd);
  coordScale_ = 0;
  for (int n = 0; n < model_.numNodes(); ++n)
    coordScale_ = std::max(coordScale_, model_.coord(n).cwiseAbs().maxCoeff());
  analyzedVersion_ = -1;
  tableOf_.assign(static_cast<size_t>(nd), 1);
  for (int n = 0; n < model_.numNodes(); ++n)
    for (int d = 0; d < kNodeDofs; ++d)
      tableOf_[static_cast<size_t>(n) * kNodeDofs + d] = std::max(1, model_.loadTable(n)[d]);
  // A material change (MESH re-entry) may have given the hinges new ultimate moments.
  hinges_.committed();
}

double Analysis::loadFactor() const { return state_.prop * (path_ ? state_.arcLambda : 1.0); }

void Analysis::applyPrescribed() {
  const DofMap& dofs = assembler_.dofs();
  dofFactors(state_.t, 1.0, lamn_);
  for (int n = 0; n < model_.numNodes(); ++n) {
    if (!dofs.used(n)) continue;
    for (int d = 0; d < kNodeDofs; ++d) {
      const int i = n * kNodeDofs + d;
      if (dofs.restrained(n, d)) state_.u[i] = lamn_[i] * model_.disp(n)[d];
    }
  }
}

void Analysis::updateRates() {
  ratesStale_ = false;
  const StepRule rule = stepRule();
  if (!rule.dynamic()) {
    state_.v.setZero();
    state_.a.setZero();
    return;
  }
  state_.v = rule.cv * (state_.u - state_.un) + rule.vv * state_.vn + rule.va * state_.an;
  state_.a = rule.ca * (state_.u - state_.un) + rule.av * state_.vn + rule.aa * state_.an;
  if (!rule.rotationsByCayley()) return;
  for (Eigen::Index i = 2; i < state_.u.size(); i += kNodeDofs) {  // rotations: their rate measure
    const double r = rule.rotationRate(state_.u[i] - state_.un[i]);
    state_.v[i] = rule.velocity(r, state_.vn[i], state_.an[i]);
    state_.a[i] = rule.acceleration(r, state_.vn[i], state_.an[i]);
  }
}

Status Analysis::advance() {
  const bool committing = dirty_;
  Status st = commit();
  if (!st) return st;
  // A commit with nothing to do skips its refresh; the topology may still have
  // changed since (HINGE2JOINT right after a converged step).
  if (assembler_.patternVersion() != model_.topologyVersion()) topologyChanged();
  // Nothing committed: a blast due at the committed time that no commit has
  // made yet (one at the start of the run).
  if (!committing) {
    st = afterCommitEvents();
    if (!st) return st;
  }
  stepEnd_ = state_.tn + state_.dt;
  const double t = nextStepTime();
  beginStep(t, state_.dt > 0 ? (t - state_.tn) / state_.dt : 1.0, true);
  return Status::success();
}

double Analysis::nextStepTime() const {
  if (path_) return stepEnd_;  // path following: blasts at the first commit past their time
  const double land = removal_.nextLanding(state_.tn);
  double end = land < stepEnd_ - MemberRemoval::tolerance(state_.dt) ? land : stepEnd_;
  // Through an impact: the step its last part proposed (solvers/ImpactSteps.h).
  const double proposed = state_.tn + impacts_.proposal();
  if (impacts_.proposal() > 0 && proposed < end - MemberRemoval::tolerance(state_.dt))
    end = proposed;
  return end;
}

Status Analysis::removeElements(const std::vector<int>& elements, double release) {
  // A step begun (TIME) and not solved to convergence has no state to remove at.
  if (dirty_ && !converged_)
    return Status::failure("the current step has not converged: remove members after it does");
  Status st = commit();
  if (!st) return st;
  st = removal_.removeNow(elements, release);
  if (!st) return st;
  topologyChanged();
  if (!integrator_.dynamic()) st = evaluateState();
  return st;
}

void Analysis::beginStep(double time, double pathScale, bool predict) {
  state_.t = time;
  state_.prop = tableFactor(1, time);
  applyPrescribed();
  predicted_ = predict && integrator_.dynamic() && state_.vn.size() == state_.u.size();
  if (predicted_) {
    const DofMap& dofs = assembler_.dofs();
    const double h = time - state_.tn;
    for (Eigen::Index i = 0; i < state_.u.size(); ++i)
      if (dofs.eq(static_cast<int>(i)) >= 0) state_.u[i] = state_.un[i] + h * state_.vn[i];
  }
  updateRates();
  history_.clear();
  energy0_ = 0;
  converged_ = false;
  globalized_ = false;
  stepInc_.setZero();
  stepDlambda_ = 0;
  if (path_) {
    path_->setStepScale(pathScale);
    path_->beginStep();
  }
  dirty_ = true;
}

Status Analysis::assemble() {
  if (assembler_.patternVersion() != model_.topologyVersion() ||
      R_.size() != assembler_.dofs().numEquations())
    topologyChanged();
  const StepRule rule = stepRule();
  Status st = assembler_.assemble(state_, rule, stepLoadFactors(rule), true);
  if (!st) return st;
  assembler_.toEquations(assembler_.nodalResidual(), R_);
  R_ = -R_;
  if (!R_.allFinite()) return Status::failure("non-finite residual");
  return Status::success();
}

Status Analysis::factor(bool symmetric) {
  // The mid-point scheme's algorithmic internal force has an unsymmetric tangent:
  // TANG then gets an unsymmetric factorization, as UTAN would.
  // Ground friction makes it unsymmetric in every scheme.
  symmetric = symmetric && integrator_.kind != TimeIntegrator::Kind::MidPoint &&
              assembler_.symmetricTangent();
  Status st;
  if (analyzedVersion_ != assembler_.structureVersion() || analyzedSymmetric_ != symmetric) {
    solver_->groupEquations(nodeOfEquation());
    st = solver_->analyze(assembler_.tangent(), symmetric);
    if (!st) return st;
    analyzedVersion_ = assembler_.structureVersion();
    analyzedSymmetric_ = symmetric;
  }
  st = solver_->factorize(assembler_.tangent());
  if (!st) {
    // Where the pivot vanished: a dof of the mechanism, or one without stiffness.
    const int eq = solver_->singularEquation();
    const DofMap& dofs = assembler_.dofs();
    for (int i = 0; eq >= 0 && i < dofs.numNodes() * kNodeDofs; ++i)
      if (dofs.eq(i) == eq)
        return Status::failure("singular tangent: no stiffness at node " +
                               std::to_string(i / kNodeDofs + 1) + ", dof " +
                               std::to_string(i % kNodeDofs + 1) +
                               " (a mechanism, or a dof nothing holds): " + st.why);
    return Status::failure("singular tangent: " + st.why);
  }
  ++totalFactorizations_;
  return Status::success();
}

std::vector<int> Analysis::nodeOfEquation() const {
  // A shared joint's slave has only its rotation: its translations are the
  // master's equations, grouped with the master.
  const DofMap& dofs = assembler_.dofs();
  std::vector<int> node(dofs.numEquations(), -1);
  for (int n = 0; n < dofs.numNodes(); ++n)
    for (int d = dofs.aliased(n) ? 2 : 0; d < kNodeDofs; ++d)
      if (const int eq = dofs.eq(n, d); eq >= 0) node[eq] = n;
  return node;
}

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
      (!st || (!info.converged && info.iteration >= 2 && !(info.energy <= energy0_)))) {
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
  if (path_) {
    const StepRule rule = stepRule();
    dofFactors(state_.t, rule.loadWeight(), lamn_);
    lamn_ = lamn_.cwiseProduct(assembler_.referenceLoad());
    assembler_.toEquations(lamn_, F_);
    st = solver_->solve(F_, duF_);
    if (!st) return Status::failure("linear solve failed: " + st.why);
    double dlambda = 0;
    st = path_->correction(stepInc_, du_, duF_, dlambda);
    if (!st) return Status::failure("path following: " + st.why);
    du_ += dlambda * duF_;
    state_.arcLambda += dlambda;
    stepDlambda_ += dlambda;
    // K du = R + dlambda F: the energy of the whole increment.
    info.energy = std::abs(du_.dot(R_) + dlambda * du_.dot(F_));
  } else {
    info.energy = std::abs(du_.dot(R_));
  }
  if (!std::isfinite(info.energy)) return Status::failure("non-finite solution increment");
  if (info.iteration == 1) energy0_ = info.energy;

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
  applyIncrement(du_, rotationStepLimit(du_, s));
  dirty_ = true;
  ++totalIterations_;

  info.converged = convergedAt(info.energy, info.iteration);
  // Through an impact the step may be too long for a contact: taken again
  // shorter from the committed state (solvers/ImpactSteps.h).
  if (info.converged && integrator_.dynamic() && !path_ && !hinges_.locating()) {
    syncRates();
    const double h = impacts_.check(assembler_, state_, stepRule(), state_.dt);
    if (h > 0) {
      for (auto& el : model_.elements())
        if (el) el->revert();
      state_.u = state_.un;
      beginStep(state_.tn + h, state_.dt > 0 ? h / state_.dt : 1.0, true);
      info.converged = false;
      info.subStep = true;
      info.shortened = h;
      converged_ = false;
      return Status::success();
    }
  }
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
      state_.t < stepEnd_ - MemberRemoval::tolerance(state_.dt)) {
    st = commit();
    if (!st) return st;
    const double t = nextStepTime();
    beginStep(t, state_.dt > 0 ? (t - state_.tn) / state_.dt : 1.0, true);
    info.converged = false;
    info.subStep = true;
    converged_ = false;
    return Status::success();
  }
  converged_ = info.converged;
  history_.push_back(info);
  // Plain Newton cycling (on the kinks of a hardening law, of the contact
  // laws): the line search of TANG,LINE takes over. A static step starts
  // again from the committed state, so that a step TANG,LINE converges
  // converges here too, through the same iterates; a dynamic one goes on from
  // the iterate it reached (from u_n the inertia residual is that of the
  // whole velocity: the line search took 9-10 iterations more from there on
  // the main example with member contact).
  if (!info.converged && !lineSearch && !globalized_ && !path_ && cycling()) {
    if (!integrator_.dynamic()) {
      for (auto& el : model_.elements())
        if (el) el->revert();
      state_.u = state_.un;
      beginStep(state_.t, 1.0, false);
    }
    globalized_ = true;
    info.globalized = true;
  }
  return Status::success();
}

bool Analysis::cycling() const {
  // The energy (or the residual) of the last iterations repeats. Statics:
  // period one or two to 1e-6 (the kinks of the hardening laws; the paper's
  // decks keep their located events). Dynamics: a period of one to six to
  // 1 % (ConvergenceTest.h stopsProgressing: the contact laws' kinks).
  const bool dynamic = integrator_.dynamic();
  constexpr std::size_t kWindow = 12;
  const std::size_t n = std::min(history_.size(), dynamic ? kWindow : 4);
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
  const int periods = dynamic ? 6 : 2;
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

void Analysis::back() {
  for (auto& el : model_.elements())
    if (el) el->revert();
  state_.revert();
  ratesStale_ = false;
  history_.clear();
  energy0_ = 0;
  converged_ = false;
  globalized_ = false;
  stepInc_.setZero();
  stepDlambda_ = 0;
  if (path_) path_->beginStep();
  dirty_ = false;
}

StepRule Analysis::stepRule() const {
  // A sub-step (a located hinge event, the rest of a step) has its own length.
  const double h = state_.t - state_.tn;
  return integrator_.rule(h > 0 ? h : state_.dt);
}

Status Analysis::evaluateState() {
  const StepRule rule = stepRule();
  return assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
}

Status Analysis::commit() {
  if (!dirty_) return Status::success();
  syncRates();
  if (assembler_.patternVersion() != model_.topologyVersion()) topologyChanged();
  const StepRule rule = stepRule();
  Status st = assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
  if (!st) return st;
  dofFactors(state_.tn, path_ ? state_.arcLambdan : 1.0, lamn_);
  account_.commitStep(assembler_, state_, rule, lam_, lamn_);
  return commitEvaluated();
}

Status Analysis::commitEvaluated() {
  syncRates();
  for (auto& el : model_.elements())
    if (el) el->commit();
  hinges_.committed();
  account_.released(assembler_.commitContact(state_));
  if (path_) {
    path_->endStep(stepInc_, stepDlambda_);
    path_->setStepScale(1.0);
  }
  state_.commit();
  dirty_ = false;
  if (Status st = afterCommitEvents(); !st) return st;
  if (onCommit) onCommit();
  return Status::success();
}

Status Analysis::afterCommitEvents() {
  // Until nothing changes: a change can make another (a joint formed at a
  // failed hinge can find its neighbour's hinge failed, or rupture at once).
  bool removed = false, joints = false;
  const MemberContact* members = assembler_.memberContact();  // replaced at a topology change
  const bool hadMembers = members != nullptr;
  const double membersBefore = hadMembers ? members->committedEnergy(model_, state_) : 0.0;
  for (int pass = 0; pass < 16; ++pass) {
    bool r = false;
    if (Status st = removal_.afterCommit(r); !st) return st;
    const bool j = topology_.afterCommit(model_, state_);
    if (!r && !j) break;
    removed = removed || r;
    joints = joints || j;
  }
  if (!removed && !joints) return Status::success();
  // The new elements at the committed state, so that the reactions and
  // section forces reported for this step are current (statics: a dynamic
  // evaluation at t_n would move the joints' relative rates).
  topologyChanged();
  if (!integrator_.dynamic())
    if (Status ev = evaluateState(); !ev) return ev;
  // Joints: a jump the change made shows in the balance (removals book theirs),
  // but for member contacts that a new joint made part of one piece: their
  // energy is released (pairs set free start at zero force: no change).
  if (joints && !removed && hadMembers) {
    const MemberContact* now = assembler_.memberContact();
    account_.released(membersBefore - (now ? now->energy(model_, state_) : 0.0));
  }
  if (joints) account_.restartFrom(energy());
  return Status::success();
}

Status Analysis::reactions(Eigen::VectorXd& r) {
  if (assembler_.patternVersion() != model_.topologyVersion()) topologyChanged();
  const StepRule rule = stepRule();
  Status st = assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
  if (!st) return st;
  r = assembler_.nodalResidual();
  return Status::success();
}

Energy Analysis::energy() {
  syncRates();
  return account_.energy(assembler_, state_);
}

double Analysis::kineticEnergy() {
  syncRates();
  return assembler_.kineticEnergy(state_);
}

// ------------------------------------------------------------ restart files

void Analysis::writeState(std::ostream& out) const {
  using namespace checkpoint;
  putTag(out, "ANLS");
  putString(out, solverName_);
  put(out, integrator_.kind);
  for (double x : {integrator_.beta, integrator_.gamma, integrator_.alpha, integrator_.betaV,
                   test_.energyTol, test_.residualTol, test_.energyZero})
    put(out, x);
  putCount(out, tables_.size());
  for (const auto& t : tables_) {
    putBool(out, t.has_value());
    if (t) t->write(out);
  }
  putBool(out, path_.has_value());
  if (path_) path_->write(out);
  putTag(out, "STAT");
  for (const Eigen::VectorXd* x :
       {&state_.u, &state_.v, &state_.a, &state_.un, &state_.vn, &state_.an, &state_.crush,
        &state_.stretch})
    putVector(out, *x);
  putCount(out, state_.pairs.size());
  for (const PairMemory& m : state_.pairs) {
    put(out, m.key);
    put(out, m.q);
    put(out, m.offset);
    put(out, m.stretch);
    put(out, m.h);
    put(out, m.side);
  }
  for (double x : {state_.t, state_.tn, state_.dt, state_.prop, state_.propn, state_.arcLambda,
                   state_.arcLambdan})
    put(out, x);
  put(out, state_.step);
  putTag(out, "BOOK");
  for (double x : {hinges_.committedDemand(), stepDlambda_, energy0_, stepEnd_}) put(out, x);
  account_.write(out);
  impacts_.write(out);
  putVector(out, stepInc_);
  putBool(out, converged_);
  putBool(out, dirty_);
  putBool(out, predicted_);
  putBool(out, globalized_);
  put(out, totalIterations_);
  put(out, totalFactorizations_);
  putCount(out, history_.size());
  for (const IterationInfo& i : history_) {
    put(out, i.iteration);
    put(out, i.energy);
    put(out, i.residual);
    putBool(out, i.converged);
    put(out, i.hingeActivated);
  }
}

void Analysis::readState(std::istream& in) {
  using namespace checkpoint;
  expectTag(in, "ANLS");
  const std::string solver = getString(in);
  if (!setLinearSolver(solver)) throw CheckpointError("unknown linear solver '" + solver + "'");
  integrator_.kind = get<TimeIntegrator::Kind>(in);
  if (integrator_.kind != TimeIntegrator::Kind::Static &&
      integrator_.kind != TimeIntegrator::Kind::Newmark &&
      integrator_.kind != TimeIntegrator::Kind::MidPoint)
    throw CheckpointError("unknown time integrator");
  for (double* x :
       {&integrator_.beta, &integrator_.gamma, &integrator_.alpha, &integrator_.betaV,
        &test_.energyTol, &test_.residualTol, &test_.energyZero})
    *x = get<double>(in);
  tables_.assign(getCount(in), std::nullopt);
  for (auto& t : tables_)
    if (getBool(in)) t = ProportionalLoad::read(in);
  path_.reset();
  if (getBool(in)) path_ = PathFollowing::read(in);
  expectTag(in, "STAT");
  for (Eigen::VectorXd* x :
       {&state_.u, &state_.v, &state_.a, &state_.un, &state_.vn, &state_.an, &state_.crush,
        &state_.stretch})
    *x = getVector(in);
  state_.pairs.resize(getCount(in));
  for (PairMemory& m : state_.pairs) {
    m.key = get<std::uint64_t>(in);
    m.q = get<double>(in);
    m.offset = get<double>(in);
    m.stretch = get<double>(in);
    m.h = get<double>(in);
    m.side = get<int>(in);
  }
  for (double* x : {&state_.t, &state_.tn, &state_.dt, &state_.prop, &state_.propn,
                    &state_.arcLambda, &state_.arcLambdan})
    *x = get<double>(in);
  state_.step = get<int>(in);
  const Eigen::Index nd = static_cast<Eigen::Index>(model_.numNodes()) * kNodeDofs;
  for (const Eigen::VectorXd* x :
       {&state_.u, &state_.v, &state_.a, &state_.un, &state_.vn, &state_.an})
    if (x->size() != nd) throw CheckpointError("state vectors do not match the model's node count");
  if (state_.crush.size() != model_.numNodes() || state_.stretch.size() != model_.numNodes())
    throw CheckpointError("state vectors do not match the model's node count");
  topologyChanged();
  expectTag(in, "BOOK");
  hinges_.setCommittedDemand(get<double>(in));
  for (double* x : {&stepDlambda_, &energy0_, &stepEnd_}) *x = get<double>(in);
  account_.read(in);
  impacts_.read(in);
  stepInc_ = getVector(in);
  account_.resize(model_.numNodes());
  if (stepInc_.size() != assembler_.dofs().numEquations())
    throw CheckpointError("analysis vectors do not match the model");
  converged_ = getBool(in);
  dirty_ = getBool(in);
  predicted_ = getBool(in);
  globalized_ = getBool(in);
  totalIterations_ = get<int>(in);
  totalFactorizations_ = get<int>(in);
  history_.resize(getCount(in));
  for (IterationInfo& i : history_) {
    i.iteration = get<int>(in);
    i.energy = get<double>(in);
    i.residual = get<double>(in);
    i.converged = getBool(in);
    i.hingeActivated = get<int>(in);
  }
}

}  // namespace c2d
