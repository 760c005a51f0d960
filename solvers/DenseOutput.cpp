#include "solvers/DenseOutput.h"

#include <algorithm>
#include <cmath>

#include "elements/Joints.h"

namespace c2d {

namespace {

// t within a relative tolerance of the step's end: the step ends on it.
bool endsOn(const State& s, double t) {
  return std::abs(s.t - t) <= 1e-10 * std::max(1.0, std::abs(t));
}

}  // namespace

State denseState(const State& state, double t, const TimeIntegrator& integrator) {
  State out = state;
  const double h = state.t - state.tn;
  if (!(h > 0) || state.un.size() != state.u.size()) return out;
  const double s = std::clamp((t - state.tn) / h, 0.0, 1.0);
  out.t = std::clamp(t, state.tn, state.t);
  const double r = 1 - s;
  out.prop = r * state.propn + s * state.prop;
  out.arcLambda = r * state.arcLambdan + s * state.arcLambda;
  out.a = r * state.an + s * state.a;
  const bool rates =
      integrator.dynamic() && state.vn.size() == state.u.size() && state.v.size() == state.u.size();
  if (!rates) {
    out.u = r * state.un + s * state.u;
    out.v = r * state.vn + s * state.v;
    return out;
  }
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = 3 * s2 - 2 * s3,
               h11 = s3 - s2;
  out.u = h00 * state.un + (h10 * h) * state.vn + h01 * state.u + (h11 * h) * state.v;
  // d/dt = (1/h) d/ds.
  const double d00 = (6 * s2 - 6 * s) / h, d10 = 3 * s2 - 4 * s + 1, d01 = -d00,
               d11 = 3 * s2 - 2 * s;
  out.v = d00 * state.un + d10 * state.vn + d01 * state.u + d11 * state.v;
  return out;
}

DenseOutput::Committed DenseOutput::committed(const State& state) {
  return {state.tn, state.propn, state.arcLambdan, state.un, state.vn, state.an};
}

void DenseOutput::stepBegins(const State& state) {
  // Every step: the first entry's vectors are reused (no allocation per step).
  parts_.resize(1);
  Committed& c = parts_.front();
  c.t = state.tn, c.prop = state.propn, c.arcLambda = state.arcLambdan;
  c.u = state.un, c.v = state.vn, c.a = state.an;
}

void DenseOutput::partCommitted(const State& state) {
  // A part taken again (a cut step) replaces the commits it comes before.
  while (!parts_.empty() && parts_.back().t >= state.tn) parts_.pop_back();
  if (!parts_.empty()) parts_.push_back(committed(state));
}

void DenseOutput::schedule(const State& state, double t) {
  time_.reset();
  sample_.reset();
  bracket_.reset();
  if (endsOn(state, t) || !(state.t > t)) return;
  time_ = t;
  t_ = state.t;
  tn_ = state.tn;
  step_ = state.step;
  // t before the last part's start: between the commits that bracket it.
  if (t >= state.tn || parts_.size() < 2 || parts_.front().t > t) return;
  std::size_t k = 0;
  while (k + 1 < parts_.size() && parts_[k + 1].t <= t) ++k;
  if (k + 1 >= parts_.size()) return;
  const Committed& a = parts_[k];
  const Committed& b = parts_[k + 1];
  if (a.u.size() != state.u.size() || b.u.size() != state.u.size()) return;
  State s = state;
  s.tn = a.t, s.propn = a.prop, s.arcLambdan = a.arcLambda;
  s.un = a.u, s.vn = a.v, s.an = a.a;
  s.t = b.t, s.prop = b.prop, s.arcLambda = b.arcLambda;
  s.u = b.u, s.v = b.v, s.a = b.a;
  bracket_ = std::move(s);
}

std::optional<double> DenseOutput::scheduled(const State& state) const {
  if (!time_ || state.t != t_ || state.tn != tn_ || state.step != step_) return std::nullopt;
  return time_;
}

const State& DenseOutput::outputState(const Model& model, State& state,
                                      const TimeIntegrator& integrator) {
  if (!model.joints().empty()) syncSlaveNodes(model, state);
  const std::optional<double> t = scheduled(state);
  if (!t) {
    sample_.reset();
    return state;
  }
  if (!sample_) {
    sample_ = denseState(bracket_ ? *bracket_ : state, *t, integrator);
    if (bracket_) {
      // The elements' quantities stay the step's (the sample moves no element);
      // the committed part is the state's.
      State& out = *sample_;
      out.tn = state.tn, out.un = state.un, out.vn = state.vn, out.an = state.an;
      out.propn = state.propn, out.arcLambdan = state.arcLambdan;
    }
  }
  return *sample_;
}

}  // namespace c2d
