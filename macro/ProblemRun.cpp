#include "macro/ProblemRun.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "core/Checkpoint.h"
#include "core/MemberCrossing.h"
#include "core/SvgDebris.h"
#include "elements/EndHinges.h"
#include "elements/MemberFold.h"
#include "elements/HingeToJoint.h"
#include "elements/Joints.h"
#include "elements/MemberFold.h"
#include "macro/DeckParser.h"
#include "macro/DeckReader.h"
#include "macro/Interrupt.h"
#include "macro/MasslessLoads.h"
#include "macro/MeshBinder.h"
#include "macro/MeshCommands.h"
#include "macro/NumberRanges.h"
#include "macro/OutputCommands.h"
#include "macro/RemovalLog.h"
#include "macro/Report.h"
#include "macro/StaleOutputs.h"
#include "macro/TopologyLog.h"
#include "solvers/ConvergenceTest.h"
#include "solvers/FiniteResults.h"
#include "solvers/ProportionalLoad.h"
#include "solvers/RestartFile.h"

namespace c2d {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// What a MESH re-entry may not change in a material set with elements.
struct MaterialShape {
  Kinematics kinematics = Kinematics::Small;
  bool elastic = false;  // SMALl without HARDening/SOFTening: elastic frame elements
};
void checkMaterialChanges(const std::vector<Macro>& list, std::map<int, MaterialShape>& sets,
                          const std::set<int>& used, const Parameters& params, bool& collapse);

}  // namespace

ProblemRun::ProblemRun(const Problem& problem, Parameters& params, const SolutionCommands& table,
                       RunOptions options, std::ostream& log)
    : problem_(problem),
      params_(params),
      table_(table),
      options_(std::move(options)),
      log_(log),
      outputs_(std::make_unique<RunOutputs>(options_.outDir, options_.stem, problem_.title,
                                            options_.label)) {
  outputs_->setPictures(options_.pictures);
}

// A run that ends by an exception leaves no progress line for the message to run into.
ProblemRun::~ProblemRun() { progress(true); }

void ProblemRun::bind(bool echo) {
  MeshFacts mesh;
  mesh.warnings = options_.warnings;
  const SampleDraws* sample = options_.sample;
  if (sample && sample->jitter)
    mesh.beforeElements = [sample](Model& m) {
      jitterNodes(m, *sample->jitter, sample->seed, sample->sample);
    };
  model_ = buildModel(problem_, params_, echo ? &log_ : nullptr, &mesh);
  if (sample && sample->detonators)
    drawnBlastTimes_ = scatterBlasts(model_, *sample->detonators, sample->seed, sample->sample);
  installJoints(model_);
  boundParams_ = params_;
  batches_.clear();
  BindFacts facts;
  facts.warnings = options_.warnings;
  for (const BatchBlock& b : problem_.batches)
    batches_.push_back(bindBatch(b.commands, b.data, table_, boundParams_, &facts));
  checkPlotColumns(batches_, boundParams_);
  warnMasslessFloorLoads(problem_, batches_, options_.warnings);
  // A table that no PROP defines would silently stay at 1 (a restart file brings its own).
  for (const auto& [table, ref] : mesh.loadTables)
    if (!facts.restart && !facts.loadTables.count(table)) {
      const auto& [rec, field] = ref;
      throw DeckError(rec.fieldLoc(field),
                      "proportional load table " + std::to_string(table) +
                          " is defined by no PROP command of this problem",
                      rec.excerpt(rec.fieldLoc(field)),
                      "add PROP,," + std::to_string(table) + " to a BATCh block");
    }
  std::map<int, MaterialShape> sets;
  for (const auto& [number, mat] : model_.materials())
    sets[number] = {mat.kinematics,
                    mat.kinematics == Kinematics::Small && !mat.hardening && !mat.softening};
  std::set<int> used;
  for (const auto& e : model_.elements())
    if (e) used.insert(e->materialNumber());
  bool collapse = false;
  for (const auto& batch : batches_) checkMaterialChanges(batch, sets, used, boundParams_, collapse);
}

void ProblemRun::run() {
  start_ = lastProgress_ = std::chrono::steady_clock::now();
  removeStaleOutputs(options_.outDir, options_.stem);
  analysis_ = std::make_unique<Analysis>(model_);
  if (!analysis_->setLinearSolver(options_.solver))
    throw AnalysisError("unknown linear solver '" + options_.solver + "'");
  hingeStep_.assign(model_.numElements(), 0);
  input_ = ModelFingerprint::of(model_);  // before any solution command changes the model
  analysis_->onCommit = [this] { onCommit(); };
  analysis_->onHingeActivated = [this](int e, const HingeInfo& h) {
    log_ << "  " << (h.fracture ? "bars   element " : "hinge  element ") << e + 1
         << " activated at t = " << fmt("%.6e", analysis_->state().t)
         << (h.fracture ? ": fracture strain" : ", M = " + fmt("%.6e", h.moment)) << "\n";
  };
  analysis_->topologyEvents().onEvent = [this](const TopologyEvent& ev) {
    hingeStep_.resize(model_.numElements(), 0);
    if (ev.kind == TopologyEvent::Kind::HingeOpened && hingeStep_[ev.element] == 0)
      hingeStep_[ev.element] = analysis_->state().step;
    logTopologyEvent(log_, model_, analysis_->state().t, ev, topology_);
  };
  analysis_->removals().onEvent = [this](const RemovalEvent& ev) {
    removed_ += static_cast<int>(ev.elements.size());
    const RemovalLog line = removalLog(ev);
    blastsNotMade_ += line.warning ? 1 : 0;
    log_ << line.text;
  };
  cursor_.reset(batches_);
  for (const auto& batch : batches_)
    if (execList(batch, true) == Flow::Stop) break;
  const Status st = analysis_->commit();
  if (!st) throw AnalysisError("final commit: " + st.why);
  if (history_) {
    history_->record(*analysis_, true);
    history_->finish();
  }
  outputs_->finish(model_, analysis_->state(), history_.get());
  if (model_.ground()) reportDebris();
  reportCrossings();
  reportFolds();
  // A blast plan the run did not reach is not silently dropped.
  for (const Blast& b : model_.blasts())
    if (!b.done) {
      ++blastsNotMade_;
      log_ << "  warning: the blast at t = " << fmt("%.6e", b.time)
           << " did not happen: the run ended at t = " << fmt("%.6e", analysis_->state().t)
           << "\n";
    }
  progress(true);
}

void ProblemRun::reportCrossings() {
  // Members that passed through each other (core/MemberCrossing.h).
  const std::vector<MemberCrossing> crossings = findCrossings(model_, analysis_->state());
  crossings_ = static_cast<int>(crossings.size());
  const std::size_t shown = std::min<std::size_t>(crossings.size(), 20);
  for (std::size_t i = 0; i < shown; ++i) {
    const MemberCrossing& c = crossings[i];
    log_ << (i == 0 ? "\n" : "") << "  warning: members " << c.first + 1 << " and " << c.second + 1
         << " cross at t = " << fmt("%.6e", analysis_->state().t) << ", at ("
         << fmt("%.3f", c.point.x()) << ", " << fmt("%.3f", c.point.y()) << ") m: "
         << fmt("%.3f", c.fromNode[0]) << " m from node " << c.nearNode[0] + 1 << " and "
         << fmt("%.3f", c.fromNode[1]) << " m from node " << c.nearNode[1] + 1 << "\n";
  }
  if (crossings.size() > shown)
    log_ << "  warning: " << crossings.size() - shown << " more pairs of members cross\n";
  // Members that went through each other during the run, whatever the end.
  if (const Assembler& a = analysis_->assembler(); a.pushedThrough() > 0)
    log_ << "  warning: " << a.pushedThrough()
         << " times a node in contact with a member was pushed past its centre line ("
         << fmt("%.3e", a.pushedThroughEnergy())
         << " kJ of contact energy released): the member contact is too soft for the impact, or "
            "the pieces of a ruptured joint slid through each other\n";
}

void ProblemRun::reportFolds() {
  // RC members folded beyond what a member does whole (elements/MemberFold.h).
  const std::vector<MemberFold> folds = foldedMembers(model_, analysis_->state());
  folded_ = static_cast<int>(folds.size());
  for (std::size_t i = 0; i < std::min<std::size_t>(folds.size(), 20); ++i)
    log_ << (i == 0 && crossings_ == 0 ? "\n" : "") << "  warning: member " << folds[i].element + 1
         << " is bent through " << fmt("%.3f", folds[i].fold) << " rad between its ends (nodes "
         << folds[i].nodes[0] + 1 << " and " << folds[i].nodes[1] + 1
         << ") at t = " << fmt("%.6e", analysis_->state().t)
         << ": more than a quarter turn, which no RC member bends whole\n";
}

RunSummary ProblemRun::summary() const {
  RunSummary s;
  if (!analysis_) return s;
  s.steps = analysis_->state().step;
  s.iterations = analysis_->totalIterations();
  s.factorizations = analysis_->totalFactorizations();
  s.cuts = cuts_;
  s.hinges = hingeCount_ + topology_.hinges;
  s.energyError = energyError_;
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  s.dynamic = dynamicSeen_;
  s.maxMomentRatio = maxMomentRatio_;
  s.jointsFormed = topology_.jointsFormed;
  s.jointsRuptured = topology_.jointsRuptured;
  s.removed = removed_;
  s.crossings = crossings_;
  s.folded = folded_;
  s.sunk = debris_ && debris_->sunk() ? 1 : 0;
  s.memberContact = crossings_ > 0 && model_.memberContact().has_value();
  s.blastsNotMade = blastsNotMade_;
  s.debrisRuns = debris_ ? 1 : 0;
  s.outsideRuns = debris_ && debris_->outside() ? 1 : 0;
  s.movingRuns = debris_ && !debris_->atRest() ? 1 : 0;
  if (debris_) s.kineticRatio = debris_->kineticRatio;
  return s;
}

std::vector<std::filesystem::path> ProblemRun::keepOutputs(std::string_view tag) noexcept {
  std::vector<std::filesystem::path> kept;
  try {
    if (history_) kept.push_back(history_->keep(tag));
  } catch (...) {
    // The history cannot be written either (a full disk): nothing to keep.
  }
  try {
    for (const auto& f : outputs_->keep(tag)) kept.push_back(f);
  } catch (...) {
  }
  return kept;
}

// ------------------------------------------------------------------ control flow

void ProblemRun::safePoint() {
  if (options_.safePoint) options_.safePoint();
  if (history_) history_->check();
  if (pendingInterrupt() != 0) {
    const State& s = analysis_->state();
    throwIfInterrupted("step " + std::to_string(s.step) + " (t = " + fmt("%.6e", s.t) + ")");
  }
}

Flow ProblemRun::execList(const std::vector<Macro>& list, bool topLevel, int pass, int passes) {
  const RunCursor::Scope scope(cursor_, list, pass >= 0, pass, passes);
  for (const Macro& m : list) {
    cursor_.at(static_cast<std::size_t>(&m - list.data()));
    safePoint();
    current_ = &m;
    const Flow f = m.command->run(m, *this);
    // Outside any loop a converged iteration or a reached tmax has no loop to leave.
    if (f == Flow::Stop || (f == Flow::ExitLoop && !topLevel)) return f;
  }
  return Flow::Next;
}

Flow ProblemRun::runLoop(const Macro& m) {
  const int n = m.has(0) ? m.numbers[0].evalInt(params_, "loop count") : 1;
  const bool newton = m.newtonLoop();
  diverged_ = stalled_ = false;
  lastFailure_.clear();
  for (int i = 0, part = parts_; i < n; ++i) {
    const Flow f = execList(m.body, false, i, n);
    if (f == Flow::Stop) return f;
    if (f == Flow::ExitLoop || diverged_) break;
    if (newton && parts_ != part) i = -1, part = parts_;
  }
  if (newton && !analysis_->stepConverged()) {
    const std::string why = diverged_  ? "diverged" + (lastFailure_.empty() ? std::string()
                                                                             : " (" + lastFailure_ + ")")
                            : stalled_ ? "stalled (its energy repeats)"
                                       : "did not converge in " + std::to_string(n) + " iterations";
    return retryWithCut(m, why);
  }
  return Flow::Next;
}

std::string ProblemRun::historyText() const {
  std::ostringstream os;
  os << "    iteration      residual   energy |du.R|\n";
  for (const IterationInfo& i : analysis_->stepHistory()) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "    %9d  %12.5e  %12.5e\n", i.iteration, i.residual, i.energy);
    os << buf;
  }
  int node = -1, dof = -1;
  const double r = analysis_->largestResidual(node, dof);
  if (node >= 0)
    os << "    largest residual " << fmt("%.5e", r) << " at node " << node + 1 << ", dof "
       << dof + 1 << "\n";
  return os.str();
}

std::string ProblemRun::advice(const std::string& why, bool lineSearch, int iterations) const {
  std::ostringstream os;
  os << "    to try:";
  if (why.find("singular") != std::string::npos) {
    os << " the model may be a mechanism or have lost all stiffness somewhere: check the "
          "BOUNdary codes, joints and released hinges near the node named;";
  }
  if (analysis_->pathFollowing())
    os << " a smaller path increment (ARCL data)";
  else
    os << " a smaller step (DT,,dt)";
  if (!cutting_)
    os << ", step cutting (AUTO,CUT,dtmin)";
  else
    os << ", a smaller dtmin (AUTO,CUT,dtmin)";
  if (!lineSearch && !analysis_->pathFollowing()) os << ", a line search (TANG,LINE,1)";
  if (iterations > 0) os << ", more iterations (LOOP,," << 2 * iterations << ")";
  os << ", a looser tolerance (TOL,,etol,rtol)\n";
  return os.str();
}

namespace {

// The loop's Newton command uses the line search (TANG,LINE,1).
bool usesLineSearch(const Macro& loop) {
  for (const Macro& b : loop.body)
    if ((b.is("tang") || b.is("utan")) && b.option.rfind("line", 0) == 0) return true;
  return false;
}

}  // namespace

Flow ProblemRun::retryWithCut(const Macro& loop, const std::string& why) {
  const State& s = analysis_->state();
  std::ostringstream msg;
  msg << "Newton iteration " << why << " in step " << s.step + 1 << " (t = " << fmt("%.6e", s.t)
      << ", dt = " << fmt("%.4e", s.dt) << ")";
  log_ << "  *** " << msg.str() << "\n" << historyText();
  const int iterations = loop.has(0) ? loop.numbers[0].evalInt(params_, "loop count") : 1;
  const bool unconverged = why.rfind("did not converge", 0) == 0;
  if (!cutting_)
    throw AnalysisError(loop.record.fieldLoc(0).str() + ": error: " + msg.str() + "\n" +
                        historyText() +
                        advice(why, usesLineSearch(loop), unconverged ? iterations : 0));
  for (;;) {
    const double dt = 0.5 * analysis_->state().dt;
    if (dt < dtMin_)
      throw AnalysisError(loop.record.fieldLoc(0).str() + ": error: " + msg.str() +
                          "; step cutting gave up at the minimum step " + fmt("%.4e", dtMin_) +
                          "\n" + historyText() +
                          advice(why, usesLineSearch(loop), unconverged ? iterations : 0));
    ++cuts_;
    stepsSinceCut_ = 0;
    analysis_->back();
    analysis_->setDt(dt);
    scalePathIncrement();
    log_ << "  cut    step to dt = " << fmt("%.4e", dt) << "\n";
    const Status st = analysis_->advance();
    if (!st) throw AnalysisError(loop.record.fieldLoc(0).str() + ": error: " + st.why);
    const int n = loop.has(0) ? loop.numbers[0].evalInt(params_, "loop count") : 1;
    diverged_ = stalled_ = false;
    for (int i = 0, part = parts_; i < n; ++i) {
      const Flow f = execList(loop.body, false, i, n);
      if (f == Flow::Stop) return f;
      if (f == Flow::ExitLoop || diverged_) break;
      if (parts_ != part) i = -1, part = parts_;
    }
    if (analysis_->stepConverged()) return Flow::Next;
  }
}

void ProblemRun::fail(const Macro& m, const std::string& what) const {
  const State& s = analysis_->state();
  throw AnalysisError(m.record.fieldLoc(0).str() + ": error: " + m.record.text(0) + " in step " +
                      std::to_string(s.step + 1) + " (t = " + fmt("%.6e", s.t) + "): " + what);
}

void ProblemRun::failAtCommit(const std::string& what) const {
  const State& s = analysis_->state();
  const std::string where =
      current_ ? current_->record.fieldLoc(0).str() + ": error: " + current_->record.text(0)
               : std::string("error:");
  throw AnalysisError(where + " at the commit of step " + std::to_string(s.step) +
                      " (t = " + fmt("%.6e", s.t) + "): " + what);
}

Flow ProblemRun::newtonIteration(const Macro& m, bool update, bool lineSearch, bool symmetric) {
  if (!update) {
    const Status st = analysis_->formTangent(symmetric);
    if (!st) fail(m, st.why);
    log_ << "  TANG   tangent formed\n";
    return Flow::Next;
  }
  IterationInfo info;
  const Status st = analysis_->iterate(lineSearch, symmetric, info);
  const State& s = analysis_->state();
  if (!st) {
    if (cutting_) {
      log_ << "  *** " << st.why << "\n";
      lastFailure_ = st.why;
      diverged_ = true;
      return Flow::ExitLoop;
    }
    fail(m, st.why + "\n" + historyText() + advice(st.why, lineSearch, 0));
  }
  // From u_n the inertia residual of a fast fall is that of the whole velocity
  // (first energies 1e3-1e4 against 1e1-1e2 from the prediction), and after
  // a hinge event or a joint Newton's method often wanders from there until
  // the loop ends and the step is cut anyway: a half step from the prediction
  // is cheaper. At the smallest step the restart stays the last resort.
  if (info.restarted && cutting_ && cutPrediction_ && 0.5 * s.dt >= dtMin_) {
    lastFailure_ = "the predicted start diverges";
    diverged_ = true;
    return Flow::ExitLoop;
  }
  if (info.restarted) {
    log_ << "  " << (symmetric ? "TANG " : "UTAN ") << "  step " << s.step + 1
         << ": the predicted start diverges; the step starts again from the committed state\n";
    return Flow::Next;
  }
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "  %-5s  step %5d  t = %12.5e  it %3d  |R| = %11.4e  |du.R| = %11.4e%s\n",
                symmetric ? "TANG" : "UTAN", s.step + 1, s.t, info.iteration, info.residual,
                info.energy, info.converged || info.subStep ? "  converged" : "");
  log_ << buf;
  // A part of the step begins: committed at a landing time, or taken again
  // shorter through an impact (solvers/ImpactSteps.h).
  if (info.subStep) {
    ++parts_;
    sample_.partCommitted(s);
    if (info.shortened > 0)
      log_ << "  " << (symmetric ? "TANG " : "UTAN ") << "  step " << s.step + 1
           << ": a contact needs a shorter step through its impact: taken again with h = "
           << fmt("%.4e", info.shortened) << "\n";
    return Flow::Next;
  }
  const auto& h = analysis_->stepHistory();
  if (h.size() > 4 && info.energy > 1e30 * h.front().energy) {
    diverged_ = true;
    return Flow::ExitLoop;
  }
  if (info.globalized)
    log_ << "  " << (symmetric ? "TANG " : "UTAN ") << "  step " << s.step + 1
         << ": Newton's iterates cycle (energy or residual repeating with a period of one to "
            "six); the line search of TANG,LINE takes over\n";
  // Stalled: the energy repeats with period one or two (a fixed point or a
  // two-cycle of Newton's method that the line search did not break): no later
  // iteration of the loop converges, so the step is cut (or reported) now.
  if (!info.converged && h.size() >= 6) {
    double energies[6];
    const std::size_t n = std::min<std::size_t>(h.size(), 6);
    for (std::size_t k = 0; k < n; ++k) energies[k] = h[h.size() - n + k].energy;
    if (repeatsWithPeriod(energies, n, 2, 3)) {
      stalled_ = true;
      return Flow::ExitLoop;
    }
  }
  return info.converged ? Flow::ExitLoop : Flow::Next;
}

Flow ProblemRun::formResidual(const Macro& m) {
  double norm = 0;
  const Status st = analysis_->formResidual(norm);
  if (!st) fail(m, st.why);
  log_ << "  FORM   |R| = " << fmt("%.6e", norm) << "\n";
  return Flow::Next;
}

Flow ProblemRun::solveOnly(const Macro& m) {
  IterationInfo info;
  const Status st = analysis_->solveOnly(info);
  if (!st) fail(m, st.why);
  log_ << "  SOLV   it " << info.iteration << "  |du.R| = " << fmt("%.4e", info.energy)
       << (info.converged ? "  converged\n" : "\n");
  return info.converged ? Flow::ExitLoop : Flow::Next;
}

Flow ProblemRun::advanceTime(const Macro& m, std::optional<double> tmax, std::optional<Rest> rest) {
  State& s = analysis_->state();
  if (tmax && s.t >= *tmax - 1e-10 * std::max(1.0, std::abs(*tmax))) {
    sample_.schedule(s, *tmax);
    return Flow::ExitLoop;
  }
  if (rest) {
    if (!analysis_->integrator().dynamic())
      fail(m, "TIME,REST needs a dynamic analysis (DYNAmic): a static one has no motion to come "
              "to rest");
    // A new ratio is watched from now on.
    if (rest->ratio != restRatio_) {
      restRatio_ = rest->ratio;
      lastMoving_ = s.t;
    }
    const double kinetic = analysis_->kineticEnergy();
    if (peakKinetic_ > 0 && kinetic <= restRatio_ * peakKinetic_ &&
        s.t - lastMoving_ >= rest->hold) {
      if (!restLogged_)
        log_ << "  TIME   at rest at t = " << fmt("%.6e", s.t) << ": the kinetic energy "
             << fmt("%.4e", kinetic) << " has stayed at most " << fmt("%.1e", restRatio_)
             << " of its peak " << fmt("%.4e", peakKinetic_) << " since t = "
             << fmt("%.6e", lastMoving_) << "\n";
      restLogged_ = true;
      restTime_ = s.t;
      return Flow::ExitLoop;
    }
  }
  if (cutting_ && s.dt < dtNominal_ && ++stepsSinceCut_ >= 2) {
    analysis_->setDt(std::min(2 * s.dt, dtNominal_));
    stepsSinceCut_ = 0;
  }
  // The last step of a phase ends on tmax; a picture loop's never (RunCursor.h).
  if (cutting_ && tmax && s.t + s.dt > *tmax && RunCursor::lands(cursor_.afterLoop(params_)))
    analysis_->setDt(*tmax - s.t);
  if (arcLengthFromDt_) {
    analysis_->setPathFollowing(PathFollowing::arcLength(s.dt));
    arcLengthFromDt_ = false;
  }
  scalePathIncrement();
  sample_.stepBegins(s);
  Status st = analysis_->advance();
  // The converged step could not be committed (an element cannot be evaluated
  // at it): with step cutting it is dropped and taken again in halves.
  while (!st && cutting_) {
    const double dt = 0.5 * s.dt;
    log_ << "  *** step " << s.step + 1 << " not committed: " << st.why << "\n";
    if (dt < dtMin_)
      fail(m, st.why + "; step cutting gave up at the minimum step " + fmt("%.4e", dtMin_));
    ++cuts_;
    stepsSinceCut_ = 0;
    analysis_->back();
    analysis_->setDt(dt);
    scalePathIncrement();
    log_ << "  cut    step to dt = " << fmt("%.4e", dt) << "\n";
    st = analysis_->advance();
  }
  if (!st) fail(m, st.why);
  log_ << "  TIME   t = " << fmt("%.6e", s.t) << "  prop = " << fmt("%.6e", analysis_->loadFactor())
       << "\n";
  return Flow::Next;
}

void ProblemRun::scalePathIncrement() {
  // A cut step is a cut path increment too (displacement increment or arc
  // length): otherwise the retried step would repeat the same Newton history.
  PathFollowing* p = analysis_->pathFollowing();
  if (!p) return;
  const double dt = analysis_->state().dt;
  p->setIncrementScale(cutting_ && dtNominal_ > 0 && dt < dtNominal_ ? dt / dtNominal_ : 1.0);
}

void ProblemRun::setDt(double dt) {
  // An ensemble's JITTer scales the steps of the motion; a static path is a
  // load path (its steps reach the deck's load levels), not a motion.
  if (options_.sample && analysis_->integrator().dynamic()) dt *= options_.sample->stepFactor;
  analysis_->setDt(dt);
  dtNominal_ = dt;
}

void ProblemRun::setStepCutting(bool on, double dtMin, bool cutDivergingPrediction) {
  cutting_ = on;
  cutPrediction_ = on && cutDivergingPrediction;
  dtNominal_ = analysis_->state().dt;
  dtMin_ = dtMin > 0 ? dtMin : dtNominal_ / 1024;
  log_ << "  AUTO   step cutting "
       << (on ? "on, dtmin = " + fmt("%.4e", dtMin_) : "off")
       << (cutPrediction_ ? ", a diverging predicted start cuts the step" : "") << "\n";
}

void ProblemRun::setIntegrator(const Macro& m, const TimeIntegrator& ti) {
  // A converged step ends under the rule it was solved with (its energy, the
  // forces a blast at its time releases), not under the new one. A step that
  // TIME began and no iteration has solved yet (DYNAmic inside the time loop)
  // is no state to commit: it begins again under the new rule.
  const State& s = analysis_->state();
  const bool begun = s.t > s.tn && analysis_->stepHistory().empty();
  if (begun) {
    analysis_->back();
  } else if (const Status st = analysis_->commit(); !st) {
    fail(m, "committing the last step: " + st.why);
  }
  analysis_->setIntegrator(ti);
  log_ << "  DYNA   " << ti.describe() << "\n";
  if (!begun) return;
  if (const Status st = analysis_->advance(); !st) fail(m, st.why);
  log_ << "  DYNA   the step to t = " << fmt("%.6e", s.t) << " begins again under it\n";
}

void ProblemRun::setProportionalLoad(const Macro& m) {
  const Record& first = m.data.front();
  const int table =
      m.has(0) && !m.record.text(2).empty() ? m.numbers[0].evalInt(params_, "table number") : 1;
  if (first.blank()) {
    analysis_->setLoadFunction(table, ProportionalLoad::ramp());
    log_ << "  PROP   table " << table << ": ramp p = t\n";
    return;
  }
  auto value = [&](const Record& r, std::size_t i) {
    return i < r.size() ? Expression::parse(r[i]).eval(params_) : 0.0;
  };
  const int type = static_cast<int>(value(first, 0));
  if (type == 1) {
    std::array<double, 5> a{};
    for (int i = 0; i < 5; ++i) a[i] = value(first, 4 + i);
    const int k = static_cast<int>(value(first, 1));
    analysis_->setLoadFunction(
        table, ProportionalLoad::formula(k == 0 ? 1 : k, value(first, 2), value(first, 3), a));
    log_ << "  PROP   table " << table << ": type 1\n";
    return;
  }
  std::vector<std::pair<double, double>> pts;
  for (std::size_t r = 1; r < m.data.size(); ++r)
    for (std::size_t i = 0; i + 1 < m.data[r].size(); i += 2)
      pts.emplace_back(value(m.data[r], i), value(m.data[r], i + 1));
  analysis_->setLoadFunction(table, ProportionalLoad::table(std::move(pts)));
  log_ << "  PROP   table " << table << ": type 2\n";
}

void ProblemRun::setPathFollowing(const Macro& m) {
  // The converged step belongs to the control it was computed under: committed
  // (and written to TPLOt) before the switch, as TIME would have done.
  if (const Status st = analysis_->commit(); !st) fail(m, st.why);
  arcLengthFromDt_ = false;
  if (m.option == "off") {
    analysis_->setPathFollowing(std::nullopt);
    log_ << "  ARCL   off\n";
    return;
  }
  const int kfl =
      m.has(0) && !m.record.text(2).empty() ? m.numbers[0].evalInt(params_, "ARCL kfl") : 0;
  if (kfl < 4 && m.data.empty()) {
    // FEAPpv's arc length: the first step's load increment is its time step,
    // known when that step starts (advanceTime).
    arcLengthFromDt_ = true;
    log_ << "  ARCL   arc length (first load increment: the first step's dt)\n";
    return;
  }
  const Record& rec = m.data.front();
  auto value = [&](std::size_t i) { return Expression::parse(rec[i]).eval(params_); };
  if (kfl >= 4) {
    const int node = Expression::parse(rec[0]).evalInt(params_, "node number");
    const int dof = Expression::parse(rec[1]).evalInt(params_, "dof");
    if (node < 1 || node > model_.numNodes() || dof < 1 || dof > 3)
      throw DeckError(rec.loc,
                      "ARCL: no node " + std::to_string(node) + " dof " + std::to_string(dof),
                      rec.lineText());
    analysis_->assembler().refresh();
    const int eq = analysis_->assembler().dofs().eq(node - 1, dof - 1);
    if (eq < 0)
      throw DeckError(rec.loc,
                      "ARCL: node " + std::to_string(node) + " dof " + std::to_string(dof) +
                          " is restrained (displacement control needs a free dof)",
                      rec.lineText());
    analysis_->setPathFollowing(PathFollowing::displacementControl(eq, value(2)));
    log_ << "  ARCL   displacement control of node " << node << " dof " << dof << "\n";
  } else {
    // 'dlambda0' alone or 'ndamp dlambda0': the last value.
    analysis_->setPathFollowing(PathFollowing::arcLength(value(rec.size() - 1)));
    log_ << "  ARCL   arc length\n";
  }
}

void ProblemRun::setTimeHistory(const Macro& m) {
  std::vector<TimeHistory::Column> cols;
  for (const Record& rec : m.data) {
    const std::string k = commandKey(rec.text(0));
    TimeHistory::Column c{TimeHistory::Kind::Ener};
    if (k == "arcl") c.kind = TimeHistory::Kind::Arcl;
    if (k == "mome") c.kind = TimeHistory::Kind::Mome;
    if (k != "ener" && k != "arcl" && k != "mome") {
      c.kind = k == "disp"   ? TimeHistory::Kind::Disp
               : k == "velo" ? TimeHistory::Kind::Velo
               : k == "acce" ? TimeHistory::Kind::Acce
               : k == "reac" ? TimeHistory::Kind::Reac
                             : TimeHistory::Kind::Stre;
      c.index = Expression::parse(rec[1]).evalInt(params_, "number") - 1;
      c.component = Expression::parse(rec[2]).evalInt(params_, "component") - 1;
      const int limit =
          c.kind == TimeHistory::Kind::Stre ? model_.numElements() : model_.numNodes();
      if (c.index < 0 || c.index >= limit || c.component < 0 || c.component > 2)
        throw DeckError(rec[1].loc,
                        "TPLOt: no such " +
                            std::string(c.kind == TimeHistory::Kind::Stre ? "element" : "node") +
                            " or component",
                        rec.excerpt(rec[1].loc));
    }
    cols.push_back(c);
  }
  const int every =
      m.has(0) && !m.record.text(2).empty() ? m.numbers[0].evalInt(params_, "TPLOt increment") : 1;
  if (every < 1)
    throw DeckError(m.record.fieldLoc(2), "the TPLOt increment must be 1 or more",
                    m.record.excerpt(m.record.fieldLoc(2)));
  // A later TPLOt of the run completes the file of the one before and starts
  // <stem>_tplot_2.csv, ... (two writers of one file lost it).
  std::string name = options_.stem + "_tplot.csv";
  if (history_) {
    history_->record(*analysis_, true);
    history_->finish();
    name = options_.stem + "_tplot_" + std::to_string(++extraHistories_ + 1) + ".csv";
  }
  history_ = std::make_unique<TimeHistory>(options_.outDir / name, std::move(cols), every,
                                           analysis_->tableCount());
  log_ << "  TPLOt  " << name << "\n";
}

namespace {

std::vector<MeshItem> meshReentryItems(const Macro& m) {
  std::vector<Record> records;
  if (!m.optionText.empty()) {
    const std::filesystem::path base = std::filesystem::path(m.record.loc.file).parent_path();
    const std::filesystem::path file = base / m.optionText;
    if (!std::filesystem::exists(file))
      throw DeckError(m.record.fieldLoc(1), "MESH: no file '" + file.string() + "'",
                      m.record.excerpt(m.record.fieldLoc(1)));
    records = DeckReader::readFile(file.string());
  } else {
    records = m.data;
  }
  return parseMeshRecords(std::move(records), m.record.loc.file);
}

// MATErial records of MESH re-entries, in deck order, that would change the
// kinematics of a set whose elements exist, or give HARDening/SOFTening to its
// elastic frame elements (before HINGe2joint, which makes them elastic Reissner
// beams that ignore the laws): refused before any computing (the re-entry checks
// again when it is applied). A re-entry that builds elements is left to that check.
void checkMaterialChanges(const std::vector<Macro>& list, std::map<int, MaterialShape>& sets,
                          const std::set<int>& used, const Parameters& params, bool& collapse) {
  for (const Macro& m : list) {
    checkMaterialChanges(m.body, sets, used, params, collapse);
    if (m.is("hing")) collapse = true;
    if (!m.is("mesh")) continue;
    const std::vector<MeshItem> items = meshReentryItems(m);
    bool builds = false;
    for (const MeshItem& item : items)
      if (const auto* c = std::get_if<MeshCommand>(&item))
        builds = builds || c->head.is("ELEMents") || c->head.is("BLOCk");
    if (builds) continue;
    for (const MeshItem& item : items) {
      const auto* c = std::get_if<MeshCommand>(&item);
      if (!c || !c->head.is("MATErial") || c->head.size() < 2) continue;
      int number = 0;
      try {
        number = Expression::parse(c->head[1]).evalInt(params, "material number");
      } catch (const DeckError&) {
        continue;  // a parameter set later: checked when the re-entry is applied
      }
      Kinematics kin = Kinematics::Small;
      const Record* where = &c->head;
      const Record* law = nullptr;
      for (const Record& r : c->data) {
        if (r.is("SMALl") || r.is("FINIte")) {
          kin = r.is("SMALl") ? Kinematics::Small : Kinematics::Finite;
          where = &r;
        }
        if (!law && (r.is("HARDening") || r.is("SOFTening"))) law = &r;
      }
      auto it = sets.find(number);
      if (it != sets.end() && used.count(number)) {
        if (it->second.kinematics != kin)
          refuseKinematicsChange(*where, number, it->second.kinematics);
        if (it->second.elastic && law && !collapse)
          throw DeckError(law->fieldLoc(0),
                          "material " + std::to_string(number) +
                              " has elastic frame elements (built without HARDening and "
                              "SOFTening): the laws cannot be added in a MESH re-entry",
                          law->excerpt(law->fieldLoc(0).col),
                          "give the laws in the mesh input, where the elements are built");
        continue;  // the elements keep their class
      }
      sets[number] = {kin, kin == Kinematics::Small && !law};
    }
  }
}

}  // namespace

void ProblemRun::reenterMesh(const Macro& m) {
  const std::vector<MeshItem> items = meshReentryItems(m);
  const Status st = analysis_->commit();
  if (!st) fail(m, st.why);
  applyMesh(items, params_, model_, &log_, nullptr, &analysis_->state());
  installJoints(model_);
  model_.bumpTopology();
  analysis_->topologyChanged();
  hingeStep_.resize(model_.numElements(), 0);
  log_ << "  MESH   re-entered: " << model_.numNodes() << " nodes, " << model_.numElements()
       << " elements, " << analysis_->assembler().dofs().numEquations() << " equations\n";
}

// ------------------------------------------------------------------ output

std::vector<int> ProblemRun::selection(const Macro& m, int count) const {
  std::vector<int> out;
  const bool all = m.option == "all" || m.numbers.empty() || m.record.text(2).empty();
  if (all) {
    for (int i = 0; i < count; ++i) out.push_back(i);
    return out;
  }
  const int n1 = m.numbers[0].evalInt(params_, "first number");
  int n2 =
      m.has(1) && !m.record.text(3).empty() ? m.numbers[1].evalInt(params_, "last number") : n1;
  int inc = m.has(2) && !m.record.text(4).empty() ? m.numbers[2].evalInt(params_, "increment") : 1;
  if (inc <= 0) inc = 1;
  for (int i : steppedRange(std::max(n1, 1), std::min(n2, count), inc)) out.push_back(i - 1);
  return out;
}

void ProblemRun::printNodal(const Macro& m) {
  const State& s = analysis_->state();
  std::vector<int> nodes;
  for (int n : selection(m, model_.numNodes()))
    if (analysis_->assembler().dofs().used(n) || model_.hasCoord(n)) nodes.push_back(n);
  if (m.is("reac")) {
    Eigen::VectorXd r;
    const Status st = analysis_->reactions(r);
    if (!st) fail(m, st.why);
    printNodalTable(log_, NodalQuantity::Reaction, model_, s, analysis_->loadFactor(), r, nodes,
                    longFormat_);
  } else if (m.is("velo")) {
    printNodalTable(log_, NodalQuantity::Velocity, model_, s, analysis_->loadFactor(), s.v, nodes,
                    longFormat_);
  } else if (m.is("acce")) {
    printNodalTable(log_, NodalQuantity::Acceleration, model_, s, analysis_->loadFactor(), s.a,
                    nodes, longFormat_);
  } else {
    printNodalTable(log_, NodalQuantity::Displacement, model_, s, analysis_->loadFactor(), s.u,
                    nodes, longFormat_);
  }
}

void ProblemRun::printStresses(const Macro& m) {
  Eigen::VectorXd r;
  const Status st = analysis_->reactions(r);  // evaluates every element at the current state
  if (!st) fail(m, st.why);
  printStressTable(log_, model_, analysis_->state(), analysis_->loadFactor(),
                   selection(m, model_.numElements()));
}

void ProblemRun::printHinges() {
  printHingeTable(log_, model_, analysis_->state(), analysis_->loadFactor(), hingeStep_);
}

void ProblemRun::hingesToJoints(const Macro& m, MemberLaws laws) {
  const Status st = analysis_->commit();
  if (!st) fail(m, st.why);
  const std::vector<CreatedJoint> joints = hingeToJoint(model_, analysis_->state(), laws);
  analysis_->topologyChanged();
  hingeStep_.resize(model_.numElements(), 0);
  log_ << "  HINGE2JOINT  " << joints.size() << " hinges became joints, members "
       << (laws == MemberLaws::Elastic ? "elastic" : "keep their laws") << "; " << model_.numNodes()
       << " nodes, " << analysis_->assembler().dofs().numEquations() << " equations\n";
  for (const CreatedJoint& j : joints)
    log_ << "    element " << j.element + 1 << ": joint master " << j.master + 1 << " slave "
         << j.slave + 1 << " (element end " << j.slaveEnd + 1 << "), relative rotation "
         << fmt("%.6e", j.relativeRotation) << "\n";
}

void ProblemRun::removeMembers(const Macro& m) {
  std::vector<int> elements;
  for (int e : selection(m, model_.numElements())) elements.push_back(e);
  if (elements.empty()) fail(m, "no element in the range");
  const double td = m.has(3) && !m.record.text(5).empty() ? m.numbers[3].eval(params_) : 0.0;
  if (!(td >= 0)) fail(m, "the release time td must be zero or positive");
  const Status st = analysis_->removeElements(elements, td);
  if (!st) fail(m, st.why);
  hingeStep_.resize(model_.numElements(), 0);
}

// ------------------------------------------------------------------ restart

std::filesystem::path ProblemRun::restartPath(const Macro& m) const {
  std::string name = m.optionText.empty() ? options_.stem : m.optionText;
  if (std::filesystem::path(name).extension() != ".rst") name += ".rst";
  return options_.outDir / name;
}

std::string ProblemRun::runState() const {
  using namespace checkpoint;
  std::ostringstream out(std::ios::binary);
  putCount(out, hingeStep_.size());
  for (int s : hingeStep_) put(out, s);
  put(out, hingeCount_);
  putBool(out, cutting_);
  for (double x : {dtMin_, dtNominal_, energy0_, energyScale_, energyError_, maxMomentRatio_,
                   peakGroundForce_, peakGroundTime_, peakKinetic_, restRatio_, lastMoving_,
                   deepest_.depth, deepestTime_})
    put(out, x);
  for (int x : {stepsSinceCut_, cuts_, topology_.jointsFormed, topology_.jointsRuptured, removed_,
                deepest_.node, topology_.hinges, topology_.fractures})
    put(out, x);
  putBool(out, energyStarted_);
  putBool(out, dynamicSeen_);
  return out.str();
}

void ProblemRun::setRunState(const std::string& bytes) {
  using namespace checkpoint;
  std::istringstream in(bytes, std::ios::binary);
  hingeStep_.resize(getCount(in));
  for (int& s : hingeStep_) s = get<int>(in);
  if (static_cast<int>(hingeStep_.size()) != model_.numElements())
    throw CheckpointError("hinge steps do not match the element count");
  hingeCount_ = get<int>(in);
  cutting_ = getBool(in);
  for (double* x : {&dtMin_, &dtNominal_, &energy0_, &energyScale_, &energyError_,
                    &maxMomentRatio_, &peakGroundForce_, &peakGroundTime_, &peakKinetic_,
                    &restRatio_, &lastMoving_, &deepest_.depth, &deepestTime_})
    *x = get<double>(in);
  for (int* x : {&stepsSinceCut_, &cuts_, &topology_.jointsFormed, &topology_.jointsRuptured,
                 &removed_, &deepest_.node, &topology_.hinges, &topology_.fractures})
    *x = get<int>(in);
  if (deepest_.node >= model_.numNodes())
    throw CheckpointError("the deepest node is not in the model");
  energyStarted_ = getBool(in);
  dynamicSeen_ = getBool(in);
}

void ProblemRun::saveRestart(const Macro& m) {
  const Status st = analysis_->commit();
  if (!st) fail(m, st.why);
  const std::filesystem::path file = restartPath(m);
  try {
    c2d::saveRestart(file, model_, *analysis_, runState(), input_);
  } catch (const IoError&) {
    throw;
  } catch (const std::exception& e) {
    fail(m, e.what());
  }
  // The linear solver starts afresh here, as it does in a run restarted from this
  // file (a new analysis: CHOLMOD first again, KLU's pivot order chosen anew), so
  // that the two runs stay identical to the last bit.
  analysis_->setLinearSolver(analysis_->linearSolverName());
  analysis_->assembler().restartContactSearch();
  const State& s = analysis_->state();
  log_ << "  SAVE   " << file.string() << ": step " << s.step << ", t = " << fmt("%.6e", s.t)
       << "\n";
}

void ProblemRun::restoreRestart(const Macro& m) {
  const std::filesystem::path file = restartPath(m);
  try {
    const std::string mine = loadRestart(file, model_, *analysis_, &input_);
    try {
      setRunState(mine);
    } catch (const CheckpointError& e) {
      throw CheckpointError("restart file '" + file.string() + "': " + e.what());
    }
  } catch (const CheckpointError& e) {
    throw AnalysisError(m.record.fieldLoc(0).str() + ": error: REST: " + e.what());
  }
  const State& s = analysis_->state();
  log_ << "  REST   " << file.string() << ": step " << s.step << ", t = " << fmt("%.6e", s.t)
       << ", " << model_.numNodes() << " nodes, " << model_.numElements() << " elements, "
       << analysis_->assembler().dofs().numEquations() << " equations\n";
}

void ProblemRun::onCommit() {
  if (!model_.joints().empty()) syncSlaveNodes(model_, analysis_->state());
  const State& s = analysis_->state();
  const Energy en = analysis_->energy();
  if (const std::string bad =
          nonFiniteResult(model_, s, analysis_->assembler().nodalResidual(), en);
      !bad.empty())
    failAtCommit("a result is not a finite number: " + bad);
  for (const auto& [e, h] : analysis_->hingeCarriers()) {
    if (hingeStep_[e] != 0) continue;
    const HingeInfo info = h->hinge();
    if (!info.active) continue;
    hingeStep_[e] = s.step;
    ++hingeCount_;
    log_ << "  hinge  formed in element " << e + 1 << " at step " << s.step
         << " (t = " << fmt("%.6e", s.t) << ", M = " << fmt("%.6e", info.moment) << ")\n";
  }
  for (const auto& [e, h] : analysis_->hingeCarriers()) {
    const HingeInfo info = h->hinge();
    if (info.ultimate > 0)
      maxMomentRatio_ = std::max(maxMomentRatio_, std::abs(info.moment) / info.ultimate);
  }
  maxMomentRatio_ = std::max(maxMomentRatio_, endHingeRatio(model_));
  if (history_) history_->record(*analysis_);
  if (model_.ground()) {
    const double f = groundForce(model_, analysis_->assembler().dofs(), s);
    if (f > peakGroundForce_) {
      peakGroundForce_ = f;
      peakGroundTime_ = s.t;
    }
    if (const GroundDepth d = deepestNode(model_, analysis_->assembler().dofs(), s);
        d.node >= 0 && d.depth > deepest_.depth) {
      deepest_ = d;
      deepestTime_ = s.t;
    }
  }
  dynamicSeen_ = dynamicSeen_ || analysis_->integrator().dynamic();
  {
    const double scale = std::abs(en.kinetic) + std::abs(en.strain) + std::abs(en.contact) +
                         std::abs(en.external) + std::abs(en.dissipated);
    if (!energyStarted_) {
      energy0_ = en.balance();
      energyStarted_ = true;
    }
    energyScale_ = std::max(energyScale_, scale);
    if (energyScale_ > 0)
      energyError_ = std::max(energyError_, std::abs(en.balance() - energy0_) / energyScale_);
    if (analysis_->integrator().dynamic()) {
      peakKinetic_ = std::max(peakKinetic_, en.kinetic);
      if (en.kinetic > restRatio_ * peakKinetic_) lastMoving_ = s.t;
    }
  }
  outputs_->onCommit(model_, analysis_->state());
  progress(false);
}

void ProblemRun::progress(bool final) {
  if (!options_.progress) return;
  // One line on the terminal, rewritten in place (at most every 0.1 s) and
  // erased when the run ends, so that the run's summary takes its place.
  if (final) {
    if (progressShown_) std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    progressShown_ = false;
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (progressShown_ && now - lastProgress_ < std::chrono::milliseconds(100)) return;
  lastProgress_ = now;
  const State& s = analysis_->state();
  const auto& h = analysis_->stepHistory();
  char line[256];
  std::snprintf(line, sizeof line, "%s: step %d  t = %.4g  load %.4g  Newton it %d  hinges %d%s",
                options_.stem.c_str(), s.step, s.t, analysis_->loadFactor(),
                h.empty() ? 0 : h.back().iteration, hingeCount_,
                cuts_ ? ("  cuts " + std::to_string(cuts_)).c_str() : "");
  // A line longer than the terminal would wrap, and '\r' would not return to its start.
  std::size_t width = 80;
  winsize ws{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) width = ws.ws_col;
  std::string text = line;
  if (text.size() >= width) text.resize(width - 1);
  std::fprintf(stderr, "\r\033[K%s", text.c_str());
  std::fflush(stderr);
  progressShown_ = true;
}

}  // namespace c2d
