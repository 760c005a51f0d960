#include "macro/run/StepControl.h"

#include <algorithm>
#include <sstream>

#include "macro/deck/Macro.h"
#include "macro/output/NumberText.h"
#include "macro/run/NewtonReport.h"
#include "solvers/Analysis.h"

namespace c2d {

namespace {

// The loop's Newton command uses the line search (TANG,LINE,1).
bool usesLineSearch(const Macro& loop) {
  for (const Macro& b : loop.body)
    if ((b.is("tang") || b.is("utan")) && b.option.rfind("line", 0) == 0) return true;
  return false;
}

}  // namespace

void StepControl::set(bool on, double dtMin, bool cutDivergingPrediction) {
  cutting_ = on;
  cutPrediction_ = on && cutDivergingPrediction;
  dtNominal_ = analysis_->state().dt;
  dtMin_ = dtMin > 0 ? dtMin : dtNominal_ / 1024;
  log_ << "  AUTO   step cutting " << (on ? "on, dtmin = " + formatNumber("%.4e", dtMin_) : "off")
       << (cutPrediction_ ? ", a diverging predicted start cuts the step" : "") << "\n";
}

void StepControl::restore(const Saved& s) {
  cutting_ = s.cutting;
  dtMin_ = s.dtMin;
  dtNominal_ = s.dtNominal;
  stepsSinceCut_ = s.stepsSinceCut;
  cuts_ = s.cuts;
}

void StepControl::growBack() {
  const State& s = analysis_->state();
  if (cutting_ && s.dt < dtNominal_ && ++stepsSinceCut_ >= 2) {
    analysis_->setDt(std::min(2 * s.dt, dtNominal_));
    stepsSinceCut_ = 0;
  }
}

void StepControl::scalePathIncrement() {
  PathFollowing* p = analysis_->pathFollowing();
  if (!p) return;
  const double dt = analysis_->state().dt;
  p->setIncrementScale(cutting_ && dtNominal_ > 0 && dt < dtNominal_ ? dt / dtNominal_ : 1.0);
}

Status StepControl::cut(double dt) {
  ++cuts_;
  stepsSinceCut_ = 0;
  analysis_->back();
  analysis_->setDt(dt);
  analysis_->impactSteps().cut(dt);
  scalePathIncrement();
  log_ << "  cut    step to dt = " << formatNumber("%.4e", dt) << "\n";
  return analysis_->advance();
}

Status StepControl::cutUntilCommitted(Status st) {
  const State& s = analysis_->state();
  while (!st && cutting_) {
    const double dt = 0.5 * s.dt;
    log_ << "  *** step " << s.step + 1 << " not committed: " << st.why << "\n";
    if (dt < dtMin_)
      return Status::failure(st.why + "; step cutting gave up at the minimum step " +
                             formatNumber("%.4e", dtMin_));
    st = cut(dt);
  }
  return st;
}

void StepControl::loopBegins() {
  verdict_ = NewtonVerdict::Iterating;
  lastFailure_.clear();
}

bool StepControl::iterationFailed(const std::string& why) {
  if (!cutting_) return false;
  log_ << "  *** " << why << "\n";
  lastFailure_ = why;
  verdict_ = NewtonVerdict::Diverged;
  return true;
}

bool StepControl::cutsDivergingPrediction() {
  // From u_n the inertia residual of a fast fall is that of the whole velocity
  // (first energies 1e3-1e4 against 1e1-1e2 from the prediction), and after
  // a hinge event or a joint Newton's method often wanders from there until
  // the loop ends and the step is cut anyway: a half step from the prediction
  // is cheaper. At the smallest step Newton goes on from the prediction
  // (atSmallestPredictedStep): from u_n a step of 1e-6 s starts with the
  // inertia residual 2 M v_n / dt of a body falling at v_n, where the
  // prediction is all but the committed state.
  if (!(cutting_ && cutPrediction_ && 0.5 * analysis_->state().dt >= dtMin_)) return false;
  lastFailure_ = "the predicted start diverges";
  verdict_ = NewtonVerdict::Diverged;
  return true;
}

namespace {
// A step this far below the nominal one is predicted to its square.
constexpr double kFarBelowNominal = 1e-3;
}  // namespace

bool StepControl::atSmallestPredictedStep() const {
  // A step at dtmin that is itself a fair part of the nominal one keeps its
  // restart from u_n, the last resort where the prediction is far off.
  const double dt = analysis_->state().dt;
  return cutting_ && cutPrediction_ && !(0.5 * dt >= dtMin_) && dt <= kFarBelowNominal * dtNominal_;
}

Flow StepControl::ends(NewtonVerdict verdict) {
  verdict_ = verdict;
  return Flow::ExitLoop;
}

std::string StepControl::unconverged(int iterations) const {
  if (verdict_ == NewtonVerdict::Diverged)
    return "diverged" + (lastFailure_.empty() ? std::string() : " (" + lastFailure_ + ")");
  if (verdict_ == NewtonVerdict::Stalled) return "stalled (its energy repeats)";
  return "did not converge in " + std::to_string(iterations) + " iterations";
}

std::string StepControl::failure(const Macro& loop, const std::string& what,
                                 const std::string& why, int iterations) const {
  const bool unconverged = why.rfind("did not converge", 0) == 0;
  return loop.record.fieldLoc(0).str() + ": error: " + what + "\n" +
         newtonHistoryText(*analysis_) +
         newtonAdvice(*analysis_, energy_, cutting_, why, usesLineSearch(loop),
                      unconverged ? iterations : 0);
}

Flow StepControl::retry(const Macro& loop, const std::string& why, int iterations,
                        const std::function<Flow()>& passes) {
  const State& s = analysis_->state();
  std::ostringstream msg;
  msg << "Newton iteration " << why << " in step " << s.step + 1
      << " (t = " << formatNumber("%.6e", s.t) << ", dt = " << formatNumber("%.4e", s.dt) << ")";
  log_ << "  *** " << msg.str() << "\n" << newtonHistoryText(*analysis_);
  if (!cutting_) throw AnalysisError(failure(loop, msg.str(), why, iterations));
  for (;;) {
    const double dt = 0.5 * analysis_->state().dt;
    if (dt < dtMin_)
      throw AnalysisError(failure(loop,
                                  msg.str() + "; step cutting gave up at the minimum step " +
                                      formatNumber("%.4e", dtMin_),
                                  why, iterations));
    const Status st = cut(dt);
    if (!st) throw AnalysisError(loop.record.fieldLoc(0).str() + ": error: " + st.why);
    verdict_ = NewtonVerdict::Iterating;
    if (passes() == Flow::Stop) return Flow::Stop;
    if (analysis_->stepConverged()) return Flow::Next;
  }
}

}  // namespace c2d
