// The analysis's state in restart files (SAVE / REST): what a run needs to
// continue bit for bit, written and read in one order.
#include <string>

#include "core/io/Checkpoint.h"
#include "solvers/Analysis.h"

namespace c2d {

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
  for (const Eigen::VectorXd* x : {&state_.u, &state_.v, &state_.a, &state_.un, &state_.vn,
                                   &state_.an, &state_.crush, &state_.owed, &state_.stretch})
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
  for (double* x : {&integrator_.beta, &integrator_.gamma, &integrator_.alpha, &integrator_.betaV,
                    &test_.energyTol, &test_.residualTol, &test_.energyZero})
    *x = get<double>(in);
  tables_.assign(getCount(in), std::nullopt);
  for (auto& t : tables_)
    if (getBool(in)) t = ProportionalLoad::read(in);
  path_.reset();
  if (getBool(in)) path_ = PathFollowing::read(in);
  expectTag(in, "STAT");
  for (Eigen::VectorXd* x : {&state_.u, &state_.v, &state_.a, &state_.un, &state_.vn, &state_.an,
                             &state_.crush, &state_.owed, &state_.stretch})
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
  if (state_.crush.size() != model_.numNodes() || state_.owed.size() != model_.numNodes() ||
      state_.stretch.size() != model_.numNodes())
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
