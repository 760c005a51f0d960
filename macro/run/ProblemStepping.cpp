// ProblemRun's time and load stepping (TIME, DT, AUTO, DYNAmic, ARCL,
// TPLOt's set-up): a step begun, its length and its cutting, the integrator,
// the proportional loads, the path following (its records: ArclSetup).
#include <algorithm>
#include <cmath>

#include "macro/run/ArclSetup.h"
#include "macro/run/PrescribedReach.h"
#include "macro/run/ProblemRun.h"

namespace c2d {

Flow ProblemRun::advanceTime(const Macro& m, std::optional<double> tmax, std::optional<Rest> rest) {
  State& s = analysis_->state();
  if (tmax && s.t >= *tmax - 1e-10 * std::max(1.0, std::abs(*tmax))) {
    sample_.schedule(s, *tmax);
    return Flow::ExitLoop;
  }
  if (rest) {
    if (!analysis_->integrator().dynamic())
      fail(m,
           "TIME,REST needs a dynamic analysis (DYNAmic): a static one has no motion to come "
           "to rest");
    if (watches_.atRestNow(*rest)) return Flow::ExitLoop;
  }
  steps_.growBack();
  // The last step of a phase ends on tmax; a picture loop's never (RunCursor.h).
  if (steps_.cutting() && tmax && s.t + s.dt > *tmax && RunCursor::lands(cursor_.afterLoop(params_)))
    analysis_->setDt(*tmax - s.t);
  if (arcLengthFromDt_) {
    analysis_->setPathFollowing(PathFollowing::arcLength(s.dt));
    arcLengthFromDt_ = false;
  }
  steps_.scalePathIncrement();
  sample_.stepBegins(s);
  const Status st = steps_.cutUntilCommitted(analysis_->advance());
  if (!st) fail(m, st.why);
  if (const std::string why = prescribedBeyondReach(model_, *analysis_); !why.empty()) fail(m, why);
  log_ << "  TIME   t = " << fmt("%.6e", s.t) << "  prop = " << fmt("%.6e", analysis_->loadFactor())
       << "\n";
  return Flow::Next;
}

void ProblemRun::setDt(double dt) {
  // An ensemble's JITTer scales the steps of the motion; a static path is a
  // load path (its steps reach the deck's load levels), not a motion.
  if (options_.sample && analysis_->integrator().dynamic()) dt *= options_.sample->stepFactor;
  analysis_->setDt(dt);
  steps_.setNominal(dt);
}

void ProblemRun::setStepCutting(bool on, double dtMin, bool cutDivergingPrediction) {
  steps_.set(on, dtMin, cutDivergingPrediction);
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

void ProblemRun::setPathFollowing(const Macro& m) {
  // The converged step belongs to the control it was computed under: committed
  // (and written to TPLOt) before the switch, as TIME would have done.
  if (const Status st = analysis_->commit(); !st) fail(m, st.why);
  arcLengthFromDt_ = setUpArcl(m, *analysis_, model_, params_, log_);
}

void ProblemRun::setTimeHistory(const Macro& m) {
  std::vector<TimeHistory::Column> cols = TimeHistory::columnsOf(m.data, params_, model_);
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

}  // namespace c2d
