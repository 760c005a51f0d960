#pragma once
// The analysis driver: one Newton loop for static, path-following and dynamic
// analysis, behind FEAP's solution commands. TIME is advance(), TANG,,1 is
// iterate(), FORM is formResidual(), BACK is back().
//
// Pieces: the Assembler (core) evaluates the model; the TimeIntegrator gives the
// step rule; the LinearSolver factors the tangent (pattern analysed once per
// topology version); PathFollowing, when set, makes the load factor an unknown.
#include <functional>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/Assembler.h"
#include "core/Hinge.h"
#include "core/Model.h"
#include "core/State.h"
#include "solvers/ConvergenceTest.h"
#include "solvers/EnergyAccount.h"
#include "solvers/HingeEvents.h"
#include "solvers/InfillEvents.h"
#include "solvers/ImpactSteps.h"
#include "solvers/linear/LinearSolver.h"
#include "solvers/MemberRemoval.h"
#include "solvers/PathFollowing.h"
#include "solvers/ProportionalLoad.h"
#include "solvers/TimeIntegrator.h"
#include "solvers/TopologyEvents.h"

namespace c2d {

struct IterationInfo {
  int iteration = 0;    // within the step, 1-based
  double energy = 0;    // |du . R|
  double residual = 0;  // ||R|| before the update
  bool converged = false;
  int hingeActivated = -1;  // element index of a hinge activated at this iteration
  bool restarted = false;   // the step was started again from the committed state
  // Plain Newton cycled (energy or residual repeating with a period of one to
  // six) at this iteration: the line search takes over from the next one (a
  // static step starts again from the committed state).
  bool globalized = false;
  // The converged step was committed at a landing time, or taken again
  // shorter through an impact (solvers/ImpactSteps.h): a new part of the step
  // begins (not converged, not a restart).
  bool subStep = false;
  double shortened = 0;  // the length the step is taken again with (0: it stood)
};

class Analysis {
  friend class HingeEvents;  // locates events inside a step: sub-steps from the committed state
  friend class MemberRemoval;  // removes elements at a committed state

 public:
  explicit Analysis(Model& model);

  Model& model() { return model_; }
  State& state() { return state_; }
  const State& state() const { return state_; }
  Assembler& assembler() { return assembler_; }

  // Configuration.
  bool setLinearSolver(const std::string& name);  // false: unknown name
  const std::string& linearSolverName() const { return solverName_; }
  void setIntegrator(const TimeIntegrator& ti) { integrator_ = ti; }
  const TimeIntegrator& integrator() const { return integrator_; }
  void setTolerance(double tol) { test_.energyTol = tol; }
  double tolerance() const { return test_.energyTol; }
  // TOL,,etol,rtol and TOL,ENER,value: the whole convergence test.
  void setConvergenceTest(const ConvergenceTest& t) { test_ = t; }
  const ConvergenceTest& convergenceTest() const { return test_; }
  void setDt(double dt) { state_.dt = dt; }
  // Proportional load table `table` (PROP,,n) as a function of time; dofs follow
  // table 1 unless FPROportional says otherwise; a table never given is 1 (FEAP).
  void setLoadFunction(int table, const ProportionalLoad& f);
  void setPathFollowing(std::optional<PathFollowing> p);
  PathFollowing* pathFollowing() { return path_ ? &*path_ : nullptr; }

  // TIME: commit the converged step and advance the time by dt.
  Status advance();
  // TANG,,1 (UTAN when !symmetric): one Newton iteration with update.
  // Dynamic steps start from the constant-velocity prediction u_n + dt v_n
  // (free dofs; prescribed ones take their values): the inertia term vanishes
  // there and a smooth motion leaves a residual of order dt^2, not dt. When an
  // iteration from the prediction fails or its energy grows past the first
  // one, the step starts again from u_n (info.restarted, not converged);
  // under keepPrediction(true) only when it fails.
  Status iterate(bool lineSearch, bool symmetric, IterationInfo& info);
  // A rise of the energy from the prediction is no reason to start again from
  // u_n (the step is at its smallest: from u_n its inertia residual would be
  // 2 M v_n / dt, of the whole velocity, the larger the shorter the step).
  void keepPrediction(bool on) { keepPrediction_ = on; }
  // FORM: residual at the current state; returns its norm over the free dofs.
  Status formResidual(double& norm);
  // SOLV: solve with the current factors for the current residual and update.
  Status solveOnly(IterationInfo& info);
  // BACK: return to the last committed state (optionally with a new dt).
  void back();

  // Commit the trial state (elements, history, energy bookkeeping); idempotent.
  Status commit();

  // Reactions (residual at the current state, every node dof).
  Status reactions(Eigen::VectorXd& r);
  Energy energy();
  double kineticEnergy();  // of the state now (no pass over the contacts)
  double loadFactor() const;  // multiplier of table-1 FORCe at t_n+1 (with the arc-length factor)
  double tableFactor(int table, double time) const;
  // The highest load table number in use (FPROportional or PROP,,n); 1 at least.
  int tableCount() const;
  const std::vector<IterationInfo>& stepHistory() const { return history_; }
  // The elements that can carry a softening hinge: (element index, ability).
  const std::vector<std::pair<int, HingeCarrier*>>& hingeCarriers() { return hinges_.carriers(); }
  // Node and dof (0-based) of the largest residual component of the last iteration.
  double largestResidual(int& node, int& dof) const;
  int totalIterations() const { return totalIterations_; }
  int totalFactorizations() const { return totalFactorizations_; }
  bool stepConverged() const { return converged_; }

  // Form and factor the tangent at the current state (TANG without update).
  Status formTangent(bool symmetric) {
    const Status st = assemble();
    return st ? factor(symmetric) : st;
  }

  // Called for every hinge activated in a Newton iteration: element index (0-based).
  std::function<void(int element, const HingeInfo&)> onHingeActivated;
  // Called after every commit, with the committed state in place.
  std::function<void()> onCommit;
  // Joints formed and ruptured during the run (after a commit; set onEvent to hear of them).
  TopologyEvents& topologyEvents() { return topology_; }

  // Infill panels crushed during the run (after a commit; set onEvent to hear of them).
  InfillEvents& infillEvents() { return infill_; }

  // The step control through impacts (on by default in dynamics).
  ImpactSteps& impactSteps() { return impacts_; }
  const ImpactSteps& impactSteps() const { return impacts_; }

  // Members removed during the run (BLASt at their times; REMOve through
  // removeElements); set removals().onEvent to hear of them.
  MemberRemoval& removals() { return removal_; }
  // REMOve: commits the converged state and removes these elements (0-based)
  // there, their forces released over `release`.
  Status removeElements(const std::vector<int>& elements, double release);

  // Topology change (MESH re-entry, HINGE2JOINT): carry the state to the new node count.
  void topologyChanged();

  // Restart files (core/io/Checkpoint.h): the state, the integrator and its
  // parameters, the tolerance, the load tables, the path following state, the
  // energy bookkeeping and the linear solver's name: what a continuation needs
  // to repeat the uninterrupted run bit for bit. readState() expects the model
  // the state belongs to (already restored) and throws CheckpointError.
  void writeState(std::ostream& out) const;
  void readState(std::istream& in);

 private:
  void applyPrescribed();
  // One Newton iteration (iterate() without the restart of a predicted step).
  Status newtonIteration(bool lineSearch, bool symmetric, IterationInfo& info);
  // Its steps: the correction du_ for the residual (assembled, factored or the
  // earlier factors reused, solved); with path following, the load factor's
  // part of it and the energy; the line search's scale of du_; a converged
  // dynamic step shortened through an impact (true), or committed at a
  // removal's landing time; plain Newton cycling handed to the line search.
  Status newtonCorrection(bool symmetric, IterationInfo& info);
  Status followPath(IterationInfo& info);
  double lineSearchScale(bool lineSearch, const IterationInfo& info);
  bool shortenedForImpact(IterationInfo& info);
  Status commitAtRemoval(IterationInfo& info);
  void globalize(IterationInfo& info);
  // Start a step (or part of one) at `time` from the committed state: load
  // factors, prescribed values, rates, a fresh iteration history; the path
  // following takes pathScale of its nominal increment. With `predict`, a
  // dynamic step's free dofs start from the constant-velocity prediction.
  void beginStep(double time, double pathScale, bool predict);
  void updateRates();
  void syncRates() {
    if (ratesStale_) updateRates();
  }
  // Residual and tangent at the current state; factorization of the tangent.
  Status assemble();
  Status factor(bool symmetric);
  // The node of each equation (the grouping handed to the linear solver).
  std::vector<int> nodeOfEquation() const;
  // du_ for the residual R_ and the tangent just assembled, with the factors of
  // an earlier tangent of the step; false when they are too far off.
  bool solveWithEarlierFactors();
  // du_ from fresh factors solves K du = R, refined or factored again with
  // pivoting if need be (solvers/linear/CheckedSolve); otherwise the tangent is
  // singular or too ill-conditioned (the failure says which, and names the
  // node and dof where the correction is largest).
  Status checkSolve();
  // The convergence tests for an iteration whose correction has this energy |du.R|.
  bool convergedAt(double energy, int iteration) const;
  // The step's iterations repeat with a period of one to six (plain Newton
  // cycling), or a static step's residuals run away.
  bool cycling() const;
  void applyIncrement(const Eigen::VectorXd& du, double scale);
  // Under the Cayley rule a rotation's increment stays below pi in one step: a
  // correction scale s that would take one past it is cut to reach halfway
  // from the increment to pi (a joint's local solve does the same).
  double rotationStepLimit(const Eigen::VectorXd& du, double s) const;
  // Tangent predictor of a static step with prescribed displacements: moves the
  // restrained dofs back to their committed values (true when any had moved,
  // their increments kept in dPrescribed_), so that the first tangent is the one
  // of the converged state; addPrescribedIncrement() then puts the increments
  // adds their effect -K_fp*du_p to the right-hand side (the caller puts the
  // increments back).
  bool holdPrescribed();
  Status addPrescribedIncrement();
  // The step rule of the current step (its length t - t_n; dt before the first step).
  StepRule stepRule() const;
  // Evaluates the elements at the current state (no tangent).
  Status evaluateState();
  // After a commit: members removed (blasts due), joints formed and ruptured;
  // the analysis follows the model's new topology. Idempotent.
  Status afterCommitEvents();
  // The end of the next step or sub-step from t_n: stepEnd_, or a landing
  // time of the member removal before it.
  double nextStepTime() const;
  // The part of commit() after the evaluation and the energy booking: the
  // elements commit their trial states as last evaluated.
  Status commitEvaluated();
  // Per node dof: the factor of its load table at `time` (times the arc-length factor).
  void dofFactors(double time, double arc, Eigen::VectorXd& out) const;
  // Factors at the step rule's load point (t_n+1, or the mid-point).
  const Eigen::VectorXd& stepLoadFactors(const StepRule& rule);

  Model& model_;
  State state_;
  Assembler assembler_;
  std::unique_ptr<LinearSolver> solver_;
  std::string solverName_ = "auto";
  int analyzedVersion_ = -1;
  bool analyzedSymmetric_ = true;
  TimeIntegrator integrator_;
  std::vector<std::optional<ProportionalLoad>> tables_;  // index: table number
  std::vector<int> tableOf_;                             // per node dof
  Eigen::VectorXd lam_, lamn_;                           // work vectors of dofFactors
  std::optional<PathFollowing> path_;
  ConvergenceTest test_;

  // Work vectors (sized per topology: nothing allocated inside the Newton loop).
  Eigen::VectorXd R_, du_, duF_, F_, stepInc_, rNodal_;
  Eigen::VectorXd rho_, drho_;   // linear residual and its correction (solveWithEarlierFactors)
  Eigen::VectorXd dPrescribed_;  // per node dof: increments of the prescribed values in the step
  double energy0_ = 0;
  double coordScale_ = 0;  // largest nodal coordinate magnitude
  std::vector<IterationInfo> history_;
  int totalIterations_ = 0;
  int totalFactorizations_ = 0;
  bool converged_ = false;
  bool dirty_ = false;  // trial differs from committed
  // The velocities and accelerations lag the Newton increments (nothing in an
  // iteration reads them): brought up to date at a converged state, a commit
  // and the energy (syncRates).
  bool ratesStale_ = false;
  double stepDlambda_ = 0;
  EnergyAccount account_;
  HingeEvents hinges_;
  TopologyEvents topology_;
  MemberRemoval removal_;
  InfillEvents infill_;
  ImpactSteps impacts_;
  double stepEnd_ = 0;  // end of the step TIME began (sub-steps end on landing times before it)
  bool predicted_ = false;      // the current step started from the prediction
  bool keepPrediction_ = false;  // an energy rise from it does not restart the step
  bool globalized_ = false;     // the step's plain Newton cycled: line search from then on
};

}  // namespace c2d
