// The analysis of one problem: the loads and prescribed values, the steps
// begun and committed, the topology changes, the tangent's assembly and
// factorization, the energy. Its Newton iteration is AnalysisNewton.cpp, its
// state in restart files AnalysisCheckpoint.cpp.
#include "solvers/Analysis.h"

#include <algorithm>
#include <cstdio>
#include <string>

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
  infill_.afterCommit(model_, state_.t);
  hinges_.committed();
  double given = 0;
  account_.released(assembler_.commitContact(state_, stepRule(), &given));
  account_.restored(given);
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
  MemberContact* members = assembler_.memberContact();  // replaced at a topology change
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
    MemberContact* now = assembler_.memberContact();
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

}  // namespace c2d
