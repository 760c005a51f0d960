#include "macro/run/ProblemRun.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "elements/Joints.h"
#include "macro/mesh/BlastOfRemoved.h"
#include "macro/mesh/MasslessLoads.h"
#include "macro/run/PlotColumns.h"
#include "macro/deck/DeckParser.h"
#include "macro/mesh/MeshBinder.h"
#include "macro/run/HingesToJoints.h"
#include "macro/run/Interrupt.h"
#include "macro/run/MeshReentry.h"
#include "macro/run/RemoveOrder.h"
#include "macro/run/StaleOutputs.h"
#include "solvers/FiniteResults.h"

namespace c2d {

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
ProblemRun::~ProblemRun() { progress_.erase(); }

void ProblemRun::bind(bool echo) {
  MeshFacts mesh;
  mesh.warnings = options_.warnings;
  const SampleDraws* sample = options_.sample;
  if (sample && sample->jitter)
    mesh.beforeElements = [sample](Model& m) {
      jitterNodes(m, *sample->jitter, sample->seed, sample->sample);
    };
  model_ = buildModel(problem_, params_, echo ? &log_ : nullptr, &mesh);
  if (sample && sample->detonators) {
    nominalBlastTimes_.clear();
    for (const Blast& b : model_.blasts()) nominalBlastTimes_.push_back(b.time);
    drawnBlastTimes_ = scatterBlasts(model_, *sample->detonators, sample->seed, sample->sample);
  }
  installJoints(model_);
  boundParams_ = params_;
  batches_.clear();
  BindFacts facts;
  facts.warnings = options_.warnings;
  for (const BatchBlock& b : problem_.batches)
    batches_.push_back(bindBatch(b.commands, b.data, table_, boundParams_, &facts));
  checkPlotColumns(batches_, boundParams_);
  warnMasslessFloorLoads(problem_, batches_, options_.warnings);
  warnBlastsOfRemovedElements(problem_, model_, batches_, boundParams_, options_.warnings);
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
  checkMeshReentries(problem_, model_, params_, boundParams_, batches_);
}

void ProblemRun::run() {
  start_ = std::chrono::steady_clock::now();
  progress_.start();
  removeStaleOutputs(options_.outDir, options_.stem);
  analysis_ = std::make_unique<Analysis>(model_);
  if (!analysis_->setLinearSolver(options_.solver))
    throw AnalysisError("unknown linear solver '" + options_.solver + "'");
  steps_.attach(*analysis_);
  watches_.attach(*analysis_);
  input_ = ModelFingerprint::of(model_);  // before any solution command changes the model
  analysis_->onCommit = [this] { onCommit(); };
  analysis_->onHingeActivated = [this](int e, const HingeInfo& h) {
    watches_.hingeActivated(e, h);
  };
  analysis_->topologyEvents().onEvent = [this](const TopologyEvent& ev) {
    watches_.topologyEvent(ev);
  };
  analysis_->infillEvents().onEvent = [this](const InfillEvent& ev) {
    log_ << "  infill panel " << ev.panel << " crushed at t = " << fmt("%.6e", ev.time)
         << ": strut element " << ev.element + 1 << " gone, element " << ev.partner + 1
         << " goes once unloaded; the panel no longer braces its bay\n";
  };
  analysis_->removals().onEvent = [this](const RemovalEvent& ev) {
    refuseScatteredIntoStatics(ev);
    watches_.removal(ev);
  };
  cursor_.reset(batches_);
  for (const auto& batch : batches_)
    if (execList(batch, true) == Flow::Stop) break;
  const Status st = analysis_->commit();
  // Located at the last command run, with the step (as every commit's failure).
  if (!st) failAtCommit("the final commit: " + st.why);
  if (history_) {
    history_->record(*analysis_, true);
    history_->finish();
  }
  outputs_->finish(model_, analysis_->state(), history_.get());
  if (model_.ground()) reportDebris();
  watches_.reportEnd();
  progress_.erase();
}

RunSummary ProblemRun::summary() const {
  if (!analysis_) return {};
  return watches_.summary(
      steps_.cuts(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
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

int ProblemRun::loopCount(const Macro& loop) const {
  return loop.has(0) ? loop.numbers[0].evalInt(params_, "loop count") : 1;
}

Flow ProblemRun::loopPasses(const Macro& loop, int passes, bool newton) {
  for (int i = 0, part = steps_.parts(); i < passes; ++i) {
    const Flow f = execList(loop.body, false, i, passes);
    if (f == Flow::Stop) return f;
    if (f == Flow::ExitLoop || steps_.diverged()) break;
    if (newton && steps_.parts() != part) i = -1, part = steps_.parts();
  }
  return Flow::Next;
}

Flow ProblemRun::runLoop(const Macro& m) {
  const int n = loopCount(m);
  const bool newton = m.newtonLoop();
  steps_.loopBegins();
  if (loopPasses(m, n, newton) == Flow::Stop) return Flow::Stop;
  if (newton && !analysis_->stepConverged())
    return steps_.retry(m, steps_.unconverged(n), n,
                        [&] { return loopPasses(m, loopCount(m), true); });
  return Flow::Next;
}

void ProblemRun::fail(const Macro& m, const std::string& what) const {
  const State& s = analysis_->state();
  throw AnalysisError(m.record.fieldLoc(0).str() + ": error: " + m.record.text(0) + " in step " +
                      std::to_string(s.step + 1) + " (t = " + fmt("%.6e", s.t) + "): " + what);
}

void ProblemRun::refuseScatteredIntoStatics(const RemovalEvent& ev) const {
  const auto k = static_cast<std::size_t>(ev.blast);
  if (ev.blast < 0 || k >= nominalBlastTimes_.size() || analysis_->integrator().dynamic()) return;
  const std::string record =
      ev.origin.file.empty() ? "blast " + std::to_string(k + 1) : "BLASt record " + ev.origin.str();
  failAtCommit("the " + record +
               ", scattered by DETOnators from t = " + fmt("%.6e", nominalBlastTimes_[k]) +
               " to t = " + fmt("%.6e", model_.blasts()[k].time) +
               ", falls in a static step (before DYNAmic): this sample is not the deck's plan; a "
               "smaller scatter (DETOnators,,sd,cov) or a later blast keeps it in the dynamic "
               "phase");
}

void ProblemRun::failAtCommit(const std::string& what) const {
  const State& s = analysis_->state();
  const std::string where =
      current_ ? current_->record.fieldLoc(0).str() + ": error: " + current_->record.text(0)
               : std::string("error:");
  throw AnalysisError(where + " at the commit of step " + std::to_string(s.step) +
                      " (t = " + fmt("%.6e", s.t) + "): " + what);
}

void ProblemRun::reenterMesh(const Macro& m) {
  const std::vector<MeshItem> items = meshReentryItems(m);
  const Status st = analysis_->commit();
  if (!st) fail(m, st.why);
  applyMeshReentry(items, params_, model_, *analysis_, log_);
  watches_.elementsChanged();
}

void ProblemRun::hingesToJoints(const Macro& m, MemberLaws laws) {
  const Status st = analysis_->commit();
  if (!st) fail(m, st.why);
  turnHingesToJoints(model_, *analysis_, laws, log_);
  watches_.elementsChanged();
}

void ProblemRun::removeMembers(const Macro& m) {
  const RemoveOrder order = readRemoveOrder(m, params_, model_.numElements());
  if (!order.error.empty()) fail(m, order.error);
  const Status st = analysis_->removeElements(order.elements, order.release);
  if (!st) fail(m, st.why);
  watches_.elementsChanged();
}

void ProblemRun::printNodal(const Macro& m) {
  if (const Status st = tables_.nodal(m, params_, model_, *analysis_); !st) fail(m, st.why);
}

void ProblemRun::printStresses(const Macro& m) {
  if (const Status st = tables_.stresses(m, params_, model_, *analysis_); !st) fail(m, st.why);
}

void ProblemRun::printHinges() { tables_.hinges(model_, *analysis_, watches_.hingeSteps()); }

void ProblemRun::reportDebris() {
  const DebrisFigures d = watches_.debrisNow(analysis_->state());
  if (d.leftNode < 0) return;
  watches_.setDebris(d);
  if (debrisReport_.write(log_, d)) plotDebris();
}

void ProblemRun::plotDebris() {
  const State& s = outputState();
  debrisReport_.plot(log_, model_, s, watches_.debrisNow(s));
}

void ProblemRun::onCommit() {
  if (!model_.joints().empty()) syncSlaveNodes(model_, analysis_->state());
  const State& s = analysis_->state();
  const Energy en = analysis_->energy();
  if (const std::string bad =
          nonFiniteResult(model_, s, analysis_->assembler().nodalResidual(), en);
      !bad.empty())
    failAtCommit("a result is not a finite number: " + bad);
  watches_.observeHinges();
  if (history_) history_->record(*analysis_);
  watches_.observeMotion(en);
  outputs_->onCommit(model_, analysis_->state());
  progress_.show(*analysis_, watches_.hinges(), steps_.cuts());
}

}  // namespace c2d
