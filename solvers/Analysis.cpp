#include "solvers/Analysis.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Checkpoint.h"

namespace c2d {

Analysis::Analysis(Model& model) : model_(model), assembler_(model) {
  setLinearSolver("auto");
  state_.prop = state_.propn = 1.0;  // FEAP: loads at full value until a PROP table is given
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
  path_ = std::move(p);
  if (path_ && state_.arcLambda == 0 && state_.arcLambdan == 0) {
    state_.arcLambda = state_.arcLambdan = 0;
  }
}

void Analysis::topologyChanged() {
  state_.resize(model_.numNodes());
  assembler_.refresh();
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
  rRest_n_.setZero(nd);
  dPrescribed_.setZero(nd);
  coordScale_ = 0;
  for (int n = 0; n < model_.numNodes(); ++n)
    coordScale_ = std::max(coordScale_, model_.coord(n).cwiseAbs().maxCoeff());
  analyzedVersion_ = -1;
  tableOf_.assign(static_cast<size_t>(nd), 1);
  for (int n = 0; n < model_.numNodes(); ++n)
    for (int d = 0; d < kNodeDofs; ++d)
      tableOf_[static_cast<size_t>(n) * kNodeDofs + d] = std::max(1, model_.loadTable(n)[d]);
  collectHingeCarriers();
}

void Analysis::collectHingeCarriers() {
  hinges_.clear();
  for (int e = 0; e < model_.numElements(); ++e)
    if (auto* h = dynamic_cast<HingeCarrier*>(&model_.element(e))) hinges_.emplace_back(e, h);
  hingesVersion_ = model_.topologyVersion();
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
  const StepRule rule = integrator_.rule(state_.dt);
  if (!rule.dynamic()) {
    state_.v.setZero();
    state_.a.setZero();
    return;
  }
  state_.v = rule.cv * (state_.u - state_.un) + rule.vv * state_.vn + rule.va * state_.an;
  state_.a = rule.ca * (state_.u - state_.un) + rule.av * state_.vn + rule.aa * state_.an;
}

Status Analysis::advance() {
  Status st = commit();
  if (!st) return st;
  // A commit with nothing to do skips its refresh; the topology may still have
  // changed since (HINGE2JOINT right after a converged step).
  if (assembler_.patternVersion() != model_.topologyVersion()) topologyChanged();
  beginStep(state_.tn + state_.dt, 1.0, true);
  return Status::success();
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
  const StepRule rule = integrator_.rule(state_.dt);
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
  symmetric = symmetric && integrator_.kind != TimeIntegrator::Kind::MidPoint;
  Status st;
  if (analyzedVersion_ != assembler_.patternVersion() || analyzedSymmetric_ != symmetric) {
    st = solver_->analyze(assembler_.tangent(), symmetric);
    if (!st) return st;
    analyzedVersion_ = assembler_.patternVersion();
    analyzedSymmetric_ = symmetric;
  }
  st = solver_->factorize(assembler_.tangent());
  if (!st) return Status::failure("singular tangent: " + st.why);
  ++totalFactorizations_;
  return Status::success();
}

void Analysis::applyIncrement(const Eigen::VectorXd& du, double scale) {
  const DofMap& dofs = assembler_.dofs();
  const Eigen::Index nd = state_.u.size();
  for (Eigen::Index i = 0; i < nd; ++i) {
    const int eq = dofs.eq(static_cast<int>(i));
    if (eq >= 0) state_.u[i] += scale * du[eq];
  }
  stepInc_ += scale * du;
  updateRates();
}

double Analysis::maxHingeDemand(int& element) {
  if (hingesVersion_ != model_.topologyVersion()) collectHingeCarriers();
  double demand = 0;
  for (const auto& [e, h] : hinges_) demand = std::max(demand, h->hingeDemand());
  // Demands equal to round-off (a uniform moment) go to the lowest element
  // number, so that the place where the hinge opens does not depend on the
  // last bits of the solution.
  element = -1;
  for (const auto& [e, h] : hinges_)
    if (demand > 0 && h->hingeDemand() >= demand * (1 - 1e-12)) {
      element = e;
      break;
    }
  return demand;
}

Status Analysis::solveFraction(double fraction, double tEnd, bool lineSearch) {
  // Elements keep their trial flags (a hinge just activated); their trial
  // history follows from the committed one at the next evaluation.
  state_.u = state_.un;
  state_.v = state_.vn;
  state_.a = state_.an;
  state_.arcLambda = state_.arcLambdan;
  beginStep(state_.tn + fraction * (tEnd - state_.tn), fraction, false);
  IterationInfo it;
  for (int k = 0; k < 60; ++k) {
    const Status st = iterate(lineSearch, true, it);
    if (!st) return st;
    if (it.converged) break;
  }
  if (!it.converged)
    return Status::failure("no convergence while locating the load level where a hinge opens");
  // Element states at the converged displacements.
  const StepRule rule = integrator_.rule(state_.dt);
  return assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
}

Status Analysis::locateHingeEvent(IterationInfo& info, bool lineSearch) {
  // The demand is piecewise linear in the load level: regula falsi (Illinois)
  // on the step fraction for max demand in [1, 1 + 1e-12]. From above, so that
  // every element is at or past its ultimate moment when the hinge opens: the
  // opening element's hinge is then at its capacity and takes the softening
  // branch (InelasticFrame freezes its bulk at the plastic curvature of Mu,
  // which from a state below Mu would lower the moment by EI/Kh times the gap
  // and leave the hinge rigid), and the others, on their yield surface, take
  // the elastic one.
  constexpr double kBand = 1e-12;
  locating_ = true;
  const double tEnd = state_.t;
  int element = -1;
  double sLo = 0, dLo = committedDemand_, sHi = 1, dHi = maxHingeDemand(element);
  double s = 0;
  bool found = dLo >= 1.0;  // the committed state is already at Mu: open there
  Status st;
  int side = 0;
  for (int k = 0; k < 60 && !found; ++k) {
    s = sLo + (1.0 + 0.5 * kBand - dLo) * (sHi - sLo) / (dHi - dLo);
    s = std::clamp(s, sLo + 1e-6 * (sHi - sLo), sHi - 1e-6 * (sHi - sLo));
    st = solveFraction(s, tEnd, lineSearch);
    if (!st) break;
    const double d = maxHingeDemand(element);
    found = d >= 1.0 && d <= 1.0 + kBand;
    if (found) break;
    if (d > 1.0) {
      sHi = s;
      dHi = d;
      if (side == -1) dLo = 1.0 - 0.5 * (1.0 - dLo);
      side = -1;
    } else {
      sLo = s;
      dLo = d;
      if (side == 1) dHi = 1.0 + 0.5 * (dHi - 1.0);
      side = 1;
    }
  }
  // Not located within the band: open at the closest level found past Mu.
  if (st && !found) s = sHi;
  if (st && (!found || s == 0)) st = solveFraction(s, tEnd, lineSearch);
  if (st) st = commit();  // the sub-step up to the hinge's ultimate moment
  if (st) {
    maxHingeDemand(element);
    for (const auto& [e, h] : hinges_)
      if (e == element) {
        h->activateHinge();
        if (onHingeActivated) onHingeActivated(e, h->hinge());
      }
    info.hingeActivated = element;
    // At the ultimate moment the open hinge has no jump yet (to 1e-12): the
    // committed state is already the equilibrium; evaluate the elements with the
    // hinge active.
    dirty_ = true;
    const StepRule rule = integrator_.rule(state_.dt);
    st = assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
  }
  if (st) st = commit();
  locating_ = false;
  if (!st) return st;
  // The rest of the step.
  beginStep(tEnd, 1.0 - s, false);
  info.converged = false;
  return Status::success();
}

int Analysis::activateCriticalHinge() {
  if (hingesVersion_ != model_.topologyVersion()) collectHingeCarriers();
  int best = -1;
  double demand = 1.0 + 1e-9;
  for (const auto& [e, h] : hinges_) {
    const double d = h->hingeDemand();
    if (d > demand) {
      demand = d;
      best = e;
    }
  }
  if (best < 0) return -1;
  for (const auto& [e, h] : hinges_)
    if (e == best) {
      h->activateHinge();
      if (onHingeActivated) onHingeActivated(e, h->hinge());
    }
  return best;
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
  const StepRule rule = integrator_.rule(state_.dt);
  ElementKinematics kin;
  ElemVec re, dp;
  ElemMat ke;
  Status st;
  for (int e = 0; e < model_.numElements() && st; ++e) {
    Element& el = model_.element(e);
    const auto nodes = el.nodes();
    for (int a = 0; a < 2; ++a)
      dp.segment<kNodeDofs>(a * kNodeDofs) =
          dPrescribed_.segment<kNodeDofs>(static_cast<Eigen::Index>(nodes[a]) * kNodeDofs);
    if (dp.isZero(0)) continue;
    for (int a = 0; a < 2; ++a) {
      const Eigen::Index base = static_cast<Eigen::Index>(nodes[a]) * kNodeDofs;
      kin.d.segment<kNodeDofs>(a * kNodeDofs) = state_.u.segment<kNodeDofs>(base);
      kin.dn.segment<kNodeDofs>(a * kNodeDofs) = state_.un.segment<kNodeDofs>(base);
      kin.vn.segment<kNodeDofs>(a * kNodeDofs) = state_.vn.segment<kNodeDofs>(base);
      kin.an.segment<kNodeDofs>(a * kNodeDofs) = state_.an.segment<kNodeDofs>(base);
    }
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
  if (predicted_ &&
      (!st || (!info.converged && info.iteration >= 2 && !(info.energy <= energy0_)))) {
    for (auto& el : model_.elements()) el->revert();
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
      analyzedVersion_ == assembler_.patternVersion() &&
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
  }
  if (path_) {
    const StepRule rule = integrator_.rule(state_.dt);
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
  if (lineSearch && !path_ && info.iteration > 1 && info.energy > 0) {
    // Search on g(s) = du . R(u + s du), accepted when |g(s)| <= 0.8 |g(0)|. For
    // a convex incremental potential (hardening) g falls monotonically through
    // zero: once g(s) changes sign the root is bracketed and regula falsi
    // (Illinois) keeps it so; before that the secant extrapolates (up to s = 4).
    // With a kinked law (Kh2/EI = 1/285 in the paper's data) the full Newton
    // step from an overshooting iterate can land past the reverse yield
    // surface, and plain Newton then cycles; the bracketed search does not.
    const StepRule rule = integrator_.rule(state_.dt);
    const double g0 = du_.dot(R_);
    auto g = [&](double step, double& out) -> Status {
      applyIncrement(du_, step);
      Status s2 = assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
      Eigen::VectorXd& Rt = duF_;  // reuse work vector
      assembler_.toEquations(assembler_.nodalResidual(), Rt);
      out = -du_.dot(Rt);
      applyIncrement(du_, -step);
      return s2;
    };
    double g1 = 0;
    if (g(1.0, g1) && std::abs(g1) > 0.8 * std::abs(g0)) {
      double sLo = 0, gLo = g0, sHi = 1, gHi = g1, sn = 1, gn = g1;
      int side = 0;
      for (int k = 0; k < 10 && std::abs(gn) > 0.8 * std::abs(g0); ++k) {
        const bool bracketed = (gLo > 0) != (gHi > 0);
        if (bracketed) {
          sn = sHi - gHi * (sHi - sLo) / (gHi - gLo);
        } else if (gHi != gLo && std::abs(gHi) < std::abs(gLo)) {
          sn = std::min(4.0, sHi - gHi * (sHi - sLo) / (gHi - gLo));
        } else {
          break;  // g grows along the direction: no better step to find here
        }
        if (!g(sn, gn)) break;
        if (!bracketed) {
          sLo = sHi;
          gLo = gHi;
          sHi = sn;
          gHi = gn;
        } else if ((gn > 0) == (gLo > 0)) {
          sLo = sn;
          gLo = gn;
          if (side == 1) gHi *= 0.5;
          side = 1;
        } else {
          sHi = sn;
          gHi = gn;
          if (side == -1) gLo *= 0.5;
          side = -1;
        }
      }
      s = sn;
    }
  }
  applyIncrement(du_, s);
  dirty_ = true;
  ++totalIterations_;

  info.converged = convergedAt(info.energy, info.iteration);
  if (info.converged && !locating_ && !hinges_.empty()) {
    if (!integrator_.dynamic()) {
      // The demand of the converged state, then the event when a hinge passed Mu.
      const StepRule rule = integrator_.rule(state_.dt);
      st = assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
      if (!st) return st;
      int e = -1;
      // Past Mu by more than the location band: elements left at their
      // ultimate moment by a located event (demand up to 1 + 1e-12) do not
      // open a second hinge in a step that does not load them further.
      if (maxHingeDemand(e) > 1.0 + 1e-9) {
        st = locateHingeEvent(info, lineSearch);
        if (!st) return st;
        converged_ = false;
        return Status::success();  // the rest of the step starts a new iteration history
      }
    } else {
      const int h = activateCriticalHinge();
      if (h >= 0) {
        info.converged = false;
        info.hingeActivated = h;
      }
    }
  }
  converged_ = info.converged;
  history_.push_back(info);
  return Status::success();
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
  // FEAP's energy test, and a residual already at round-off level (a step that
  // changes nothing has no meaningful first energy to compare with).
  const double e0 = iteration == 1 ? energy : energy0_;
  const double roundoff = 1e-10 * assembler_.forceScale();
  // Stagnation at round-off: the energy no longer falls (less than tenfold in an
  // iteration) although it is already 1e-10 of the first one: the residual has
  // reached the precision the model can be evaluated with.
  const bool stagnated = !history_.empty() && iteration >= 3 && energy <= 1e-10 * e0 &&
                         energy >= 0.1 * history_.back().energy;
  // A correction below the resolution of the nodal positions (a free body in
  // uniform motion predicted exactly: its residual is round-off of zero forces).
  const double positions = coordScale_ + (state_.u.size() ? state_.u.cwiseAbs().maxCoeff() : 0.0);
  const bool unresolvable = du_.size() > 0 && du_.cwiseAbs().maxCoeff() <= 1e-15 * positions;
  return e0 == 0 || energy <= tol_ * e0 || stagnated || unresolvable ||
         (!path_ && R_.size() > 0 && R_.cwiseAbs().maxCoeff() <= roundoff);
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
  const StepRule rule = integrator_.rule(state_.dt);
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
  if (analyzedVersion_ != assembler_.patternVersion())
    return Status::failure("SOLV without a factored tangent (use TANG first)");
  Status st = solver_->solve(R_, du_);
  if (!st) return st;
  info.energy = std::abs(du_.dot(R_));
  if (info.iteration == 1) energy0_ = info.energy;
  applyIncrement(du_, 1.0);
  dirty_ = true;
  info.converged = convergedAt(info.energy, info.iteration);
  converged_ = info.converged;
  history_.push_back(info);
  return Status::success();
}

void Analysis::back() {
  for (auto& el : model_.elements()) el->revert();
  state_.revert();
  history_.clear();
  energy0_ = 0;
  converged_ = false;
  stepInc_.setZero();
  stepDlambda_ = 0;
  if (path_) path_->beginStep();
  dirty_ = false;
}

Status Analysis::commit() {
  if (!dirty_) return Status::success();
  if (assembler_.patternVersion() != model_.topologyVersion()) topologyChanged();
  const StepRule rule = integrator_.rule(state_.dt);
  Status st = assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
  if (!st) return st;
  // Loads at the step's load point: the mid-point's, or the trapezoidal mean.
  if (rule.scheme != Scheme::MidPoint) {
    dofFactors(state_.tn, path_ ? state_.arcLambdan : 1.0, lamn_);
    lam_ = 0.5 * (lam_ + lamn_);
  }
  // External work of the step: loads at the step's load point, reactions on the
  // prescribed dofs (mid-point: the algorithmic ones; otherwise the trapezoidal rule).
  const Eigen::VectorXd& r = assembler_.nodalResidual();
  const DofMap& dofs = assembler_.dofs();
  double work = 0;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const double du = state_.u[i] - state_.un[i];
    work += du * (lam_[i] * assembler_.referenceLoad()[i] + assembler_.gravityLoad()[i]);
    const int n = static_cast<int>(i / kNodeDofs), d = static_cast<int>(i % kNodeDofs);
    if (dofs.used(n) && dofs.restrained(n, d)) {
      const double rr = rule.scheme == Scheme::MidPoint ? r[i] : 0.5 * (r[i] + rRest_n_[i]);
      work += du * rr;
      rRest_n_[i] = r[i];
    }
  }
  externalWork_ += work;
  for (auto& el : model_.elements()) el->commit();
  {
    int e = -1;
    committedDemand_ = maxHingeDemand(e);
  }
  if (path_) {
    path_->endStep(stepInc_, stepDlambda_);
    path_->setStepScale(1.0);
  }
  state_.commit();
  dirty_ = false;
  if (onCommit) onCommit();
  return Status::success();
}

Status Analysis::reactions(Eigen::VectorXd& r) {
  if (assembler_.patternVersion() != model_.topologyVersion()) topologyChanged();
  const StepRule rule = integrator_.rule(state_.dt);
  Status st = assembler_.assemble(state_, rule, stepLoadFactors(rule), false);
  if (!st) return st;
  r = assembler_.nodalResidual();
  return Status::success();
}

Energy Analysis::energy() {
  Energy e;
  e.kinetic = assembler_.kineticEnergy(state_);
  e.strain = assembler_.strainEnergy();
  e.contact = assembler_.contactEnergy(state_);
  e.external = externalWork_;
  return e;
}

// ------------------------------------------------------------ restart files

void Analysis::writeState(std::ostream& out) const {
  using namespace checkpoint;
  putTag(out, "ANLS");
  putString(out, solverName_);
  put(out, integrator_.kind);
  for (double x : {integrator_.beta, integrator_.gamma, integrator_.alpha, integrator_.betaV, tol_})
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
       {&state_.u, &state_.v, &state_.a, &state_.un, &state_.vn, &state_.an})
    putVector(out, *x);
  for (double x : {state_.t, state_.tn, state_.dt, state_.prop, state_.propn, state_.arcLambda,
                   state_.arcLambdan})
    put(out, x);
  put(out, state_.step);
  putTag(out, "BOOK");
  for (double x : {externalWork_, committedDemand_, stepDlambda_, energy0_}) put(out, x);
  putVector(out, rRest_n_);
  putVector(out, stepInc_);
  putBool(out, converged_);
  putBool(out, dirty_);
  putBool(out, predicted_);
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
       {&integrator_.beta, &integrator_.gamma, &integrator_.alpha, &integrator_.betaV, &tol_})
    *x = get<double>(in);
  tables_.assign(getCount(in), std::nullopt);
  for (auto& t : tables_)
    if (getBool(in)) t = ProportionalLoad::read(in);
  path_.reset();
  if (getBool(in)) path_ = PathFollowing::read(in);
  expectTag(in, "STAT");
  for (Eigen::VectorXd* x : {&state_.u, &state_.v, &state_.a, &state_.un, &state_.vn, &state_.an})
    *x = getVector(in);
  for (double* x : {&state_.t, &state_.tn, &state_.dt, &state_.prop, &state_.propn,
                    &state_.arcLambda, &state_.arcLambdan})
    *x = get<double>(in);
  state_.step = get<int>(in);
  const Eigen::Index nd = static_cast<Eigen::Index>(model_.numNodes()) * kNodeDofs;
  for (const Eigen::VectorXd* x :
       {&state_.u, &state_.v, &state_.a, &state_.un, &state_.vn, &state_.an})
    if (x->size() != nd) throw CheckpointError("state vectors do not match the model's node count");
  topologyChanged();
  expectTag(in, "BOOK");
  for (double* x : {&externalWork_, &committedDemand_, &stepDlambda_, &energy0_})
    *x = get<double>(in);
  rRest_n_ = getVector(in);
  stepInc_ = getVector(in);
  if (rRest_n_.size() != nd || stepInc_.size() != assembler_.dofs().numEquations())
    throw CheckpointError("analysis vectors do not match the model");
  converged_ = getBool(in);
  dirty_ = getBool(in);
  predicted_ = getBool(in);
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
