#pragma once
// One problem of a deck (FEAP ... END, BATCh blocks) bound and run: the mesh
// built into a Model, the BATCh blocks bound into command trees (every deck
// error found before computing), then executed against an Analysis.
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "macro/output/Debris.h"
#include "core/Model.h"
#include "macro/deck/Deck.h"
#include "macro/run/DebrisReport.h"
#include "macro/run/PrintedTables.h"
#include "macro/run/ProgressLine.h"
#include "macro/run/RunOptions.h"
#include "macro/run/RunCursor.h"
#include "macro/run/RunOutputs.h"
#include "macro/run/RunWatches.h"
#include "macro/run/RunSummary.h"
#include "macro/run/StepControl.h"
#include "macro/output/NumberText.h"
#include "macro/deck/SolutionCommand.h"
#include "macro/run/TimeHistory.h"
#include "elements/HingeToJoint.h"
#include "macro/deck/Warnings.h"
#include "macro/draws/Ensemble.h"
#include "solvers/Analysis.h"
#include "solvers/DenseOutput.h"
#include "solvers/ModelFingerprint.h"

namespace c2d {

class ProblemRun {
 public:
  ProblemRun(const Problem& problem, Parameters& params, const SolutionCommands& table,
             RunOptions options, std::ostream& log);
  ~ProblemRun();

  // Build the mesh and bind every BATCh block (no computing): throws DeckError.
  void bind(bool echo);
  // The parameter table as binding left it: PARA commands of the BATCh blocks
  // applied in deck order (what a later top-level LOOP count sees).
  const Parameters& boundParams() const { return boundParams_; }
  // Execute the bound BATCh blocks; throws AnalysisError when the analysis fails.
  void run();
  RunSummary summary() const;
  // The run failed or was interrupted: its time history and ParaView collection
  // kept under names tagged `tag` ("failed", "interrupted"). Never throws;
  // returns the files kept.
  std::vector<std::filesystem::path> keepOutputs(std::string_view tag) noexcept;

  // --- used by the solution commands ---
  Model& model() { return model_; }
  Analysis& analysis() { return *analysis_; }
  Parameters& params() { return params_; }
  std::ostream& log() { return log_; }
  RunOutputs& outputs() { return *outputs_; }
  const RunOutputs& outputs() const { return *outputs_; }
  const TimeHistory* history() const { return history_.get(); }
  // The state pictures and ParaView frames show: the analysis state, or the
  // motion at the tmax of a loop whose last step passed it (solvers/DenseOutput.h).
  const State& outputState() {
    return sample_.outputState(model_, analysis_->state(), analysis_->integrator());
  }
  // TIME,REST ended a loop at rest and no step has been taken since.
  bool atRest() const { return watches_.atRest(); }

  Flow runLoop(const Macro& m);
  Flow newtonIteration(const Macro& m, bool update, bool lineSearch, bool symmetric);
  Flow formResidual(const Macro& m);
  Flow solveOnly(const Macro& m);
  // TIME,REST: the motion is at rest when the kinetic energy has stayed at or
  // below `ratio` of its peak (in this run's dynamic analysis) for `hold`
  // time units; then the loop ends without a step.
  using Rest = RunWatches::Rest;
  Flow advanceTime(const Macro& m, std::optional<double> tmax, std::optional<Rest> rest = {});
  void setDt(double dt);
  void setIntegrator(const Macro& m, const TimeIntegrator& ti);
  // AUTO,CUT,dtmin,pred: with pred a dynamic step whose predicted start
  // diverges is cut (dt halved, from the prediction again) rather than started
  // again from the committed state.
  void setStepCutting(bool on, double dtMin, bool cutDivergingPrediction = false);
  void setPathFollowing(const Macro& m);
  void setTimeHistory(const Macro& m);
  void reenterMesh(const Macro& m);
  void hingesToJoints(const Macro& m, MemberLaws laws);
  // REMOve,ELEMents,n1,n2,inc,td.
  void removeMembers(const Macro& m);
  // SAVE[,name]: commit the converged step and write <outDir>/<name>.rst (default
  // name: the run's stem). REST[,name]: replace the model and the analysis state
  // by the ones saved there; the following commands continue from them.
  void saveRestart(const Macro& m);
  void restoreRestart(const Macro& m);
  void printNodal(const Macro& m);
  // FORM,LONG / FORM,SHORt: the digits of the nodal tables (FEAP's fmt_long).
  void setLongFormat(bool on) { tables_.setLongFormat(on); }
  void printStresses(const Macro& m);
  void printHinges();
  // PLOT,DEBRis: <stem>_debris.svg of the current state, drawn again with the
  // final state at the end of the run.
  void plotDebris();
  // The debris figures of a run that ended with ground contact.
  const std::optional<DebrisFigures>& debris() const { return watches_.debris(); }
  // The BLASt times of an ensemble's sample with DETOnators (one per record).
  const std::vector<double>& drawnBlastTimes() const { return drawnBlastTimes_; }

 private:
  // A number in the log: printf's format f (one conversion).
  static std::string fmt(const char* f, double v) { return formatNumber(f, v); }
  // pass (0-based) of passes: a loop's body (runLoop), else a BATCh block.
  Flow execList(const std::vector<Macro>& list, bool topLevel = false, int pass = -1,
                int passes = 1);
  void safePoint();
  // A LOOP's count of passes.
  int loopCount(const Macro& loop) const;
  // The passes of a loop's body; a Newton loop's count starts again with each
  // part of a step its iterations begin (StepControl::parts).
  Flow loopPasses(const Macro& loop, int passes, bool newton);
  [[noreturn]] void fail(const Macro& m, const std::string& what) const;
  // At a commit: the command that made it (current_), the step and time.
  [[noreturn]] void failAtCommit(const std::string& what) const;
  // A blast that DETOnators scattered into a static step (before DYNAmic): the
  // sample would go on as a plan the deck does not give (a structure without
  // its columns held statically, whose Newton loop then fails without a word
  // of the blast), so the run fails there, naming the blast and both times.
  void refuseScatteredIntoStatics(const RemovalEvent& ev) const;
  void onCommit();
  // The debris figures at the end of a run with ground contact, reported.
  void reportDebris();
  std::filesystem::path restartPath(const Macro& m) const;

  const Problem& problem_;
  Parameters& params_;
  const SolutionCommands& table_;
  RunOptions options_;
  std::ostream& log_;

  Model model_;
  Parameters boundParams_;
  std::unique_ptr<Analysis> analysis_;
  std::vector<std::vector<Macro>> batches_;
  const Macro* current_ = nullptr;  // the solution command running
  std::unique_ptr<TimeHistory> history_;
  std::unique_ptr<RunOutputs> outputs_;  // PLOT and PVIEw files

  ModelFingerprint input_;  // the model as the deck's mesh input built it (SAVE / REST)

  bool arcLengthFromDt_ = false;  // ARCL without dlambda0: set up when the first step starts
  int extraHistories_ = 0;        // TPLOt commands of the run after the first

  RunWatches watches_{log_, model_};  // the run's watches and counters: its summary
  StepControl steps_{log_, watches_.energy()};  // step cutting (AUTO,CUT), the loops' verdicts
  RunCursor cursor_;    // where the run is in its commands (TIME,,tmax: land on it or not)
  DenseOutput sample_;  // outputs at the tmax a picture loop's last step passed
  DebrisReport debrisReport_{options_, problem_.title};
  PrintedTables tables_{log_};  // DISP, VELO, ACCE, REAC, STRE
  std::vector<double> drawnBlastTimes_;
  std::vector<double> nominalBlastTimes_;  // the deck's, before DETOnators scattered them
  std::chrono::steady_clock::time_point start_;
  ProgressLine progress_{options_.progress, options_.stem};
};

}  // namespace c2d
