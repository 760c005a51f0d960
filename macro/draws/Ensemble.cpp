#include "macro/draws/Ensemble.h"

#include <cmath>
#include <cstdio>

#include "macro/deck/Limits.h"
#include "macro/draws/CounterRandom.h"

namespace c2d {

namespace {

[[noreturn]] void failAt(const Record& r, std::size_t i, const std::string& msg,
                         const std::string& hint = {}) {
  throw DeckError(r.fieldLoc(i), msg, r.excerpt(r.fieldLoc(i)), hint);
}

bool written(const Record& r, std::size_t i) { return i < r.size() && !r[i].text.empty(); }

double value(const Expression& e, const Parameters& p) { return e.eval(p); }

// Every draw lies between the law's quantiles at the least and the largest
// uniform number (a quantile grows with u): both must be finite numbers (a
// LOGNormal's positive), or some sample draws inf, NaN or 0 (UNIForm -1e308
// 1e308, LOGNormal 0.4 1e300, NORMal 1e308 1e308).
void checkLawRange(const DrawRecord& d, const Distribution& law) {
  const double lo = law.quantile(0x1.0p-54), hi = law.quantile(std::nextafter(1.0, 0.0));
  if (std::isfinite(lo) && std::isfinite(hi) && (law.law != Law::LogNormal || lo > 0)) return;
  char range[96];
  std::snprintf(range, sizeof range, "from %g to %g", lo, hi);
  failAt(d.record, 3,
         "the law of '" + d.name + "' (" + law.text() + ") draws values " + range +
             ": beyond the numbers a run can compute with",
         "a law whose draws stay finite (and positive for LOGNormal)");
}

}  // namespace


EnsembleSpec evaluateEnsemble(const TopEnsemble& e, const Parameters& p) {
  EnsembleSpec s;
  const Record& h = e.head;
  const int n = e.samples.evalInt(p, "number of samples");
  if (n < 1 || n > DeckLimits::kMaxRuns)
    failAt(h, 2,
           "the number of samples of an ensemble is between 1 and " +
               std::to_string(DeckLimits::kMaxRuns) + ", got " + std::to_string(n));
  s.samples = n;
  if (written(h, 3)) {
    const int seed = e.seed.evalInt(p, "seed");
    if (seed < 0) failAt(h, 3, "the seed of an ensemble is 0 or more, got " + std::to_string(seed));
    s.seed = static_cast<std::uint64_t>(seed);
  }
  for (const DrawRecord& d : e.draws) {
    NamedDraw nd{d.name, {}};
    const double a = value(d.a, p), b = value(d.b, p);
    if (!std::isfinite(a) || !std::isfinite(b))
      failAt(d.record, std::isfinite(a) ? 3 : 2,
             "the law of '" + d.name + "' needs finite numbers");
    if (d.law == "norm") {
      if (b < 0) failAt(d.record, 3, "the standard deviation of '" + d.name + "' is negative");
      nd.law = {Law::Normal, a, b};
    } else if (d.law == "logn") {
      if (a <= 0)
        failAt(d.record, 2, "the median of a LOGNormal '" + d.name + "' must be positive");
      if (b < 0)
        failAt(d.record, 3, "the coefficient of variation of '" + d.name + "' is negative");
      nd.law = {Law::LogNormal, a, b};
    } else {
      if (b < a) failAt(d.record, 3, "UNIForm lo hi of '" + d.name + "' has hi below lo");
      nd.law = {Law::Uniform, a, b};
    }
    checkLawRange(d, nd.law);
    s.draws.push_back(nd);
  }
  if (e.jitter) {
    const Record& r = *e.jitter;
    JitterSpec j;
    if (written(r, 2)) j.dx = Expression::parse(r[2]).eval(p);
    if (written(r, 3)) j.fdt = Expression::parse(r[3]).eval(p);
    if (!(j.dx >= 0) || !std::isfinite(j.dx)) failAt(r, 2, "JITTer's dx is 0 or more");
    if (!(j.fdt >= 0 && j.fdt < 1)) failAt(r, 3, "JITTer's fdt is in [0, 1)");
    s.jitter = j;
  }
  if (e.detonators) {
    const Record& r = *e.detonators;
    DetonatorSpec d;
    if (written(r, 1) && keywordMatches(r[1].text, "ELECtronic"))
      d.sd = DetonatorSpec::kElectronicSd;
    if (written(r, 1) && keywordMatches(r[1].text, "PYROtechnic"))
      d.cov = DetonatorSpec::kPyrotechnicCov;
    if (written(r, 2)) d.sd = Expression::parse(r[2]).eval(p);
    if (written(r, 3)) d.cov = Expression::parse(r[3]).eval(p);
    if (!written(r, 1) && !written(r, 2) && !written(r, 3))
      failAt(r, 1, "DETOnators needs a kind or a scatter",
             "DETOnators,PYROtechnic, DETOnators,ELECtronic or DETOnators,,sd,cov");
    if (!(d.sd >= 0) || !std::isfinite(d.sd)) failAt(r, 2, "DETOnators' sd is 0 or more");
    if (!(d.cov >= 0) || !std::isfinite(d.cov)) failAt(r, 3, "DETOnators' cov is 0 or more");
    s.detonators = d;
  }
  return s;
}

void EnsemblePairing::check(const TopEnsemble& e, const EnsembleSpec& spec, int plan) {
  if (!seen_) {
    seen_ = true;
    samples_ = spec.samples;
    seed_ = spec.seed;
    plan_ = plan;
    return;
  }
  const bool samples = spec.samples != samples_;
  if (!samples && spec.seed == seed_) return;
  const std::string what = samples ? "samples" : "seed";
  const auto mine = samples ? std::to_string(spec.samples) : std::to_string(spec.seed);
  const auto first = samples ? std::to_string(samples_) : std::to_string(seed_);
  failAt(e.head, samples ? 2 : 3,
         "plan " + std::to_string(plan) + " takes " + what + " " + mine + " and plan " +
             std::to_string(plan_) + " " + first +
             ": the plans are compared on paired runs (sample k of every plan takes the draws "
             "of (seed, k)), so every plan takes the same n and seed",
         "give n and seed values that do not depend on a swept parameter; plans on draws of "
         "their own are separate decks");
}

SampleDraws drawSample(const EnsembleSpec& spec, int sample) {
  SampleDraws d;
  d.sample = sample;
  d.seed = spec.seed;
  for (const NamedDraw& nd : spec.draws)
    d.values.emplace_back(
        nd.name, nd.law.quantile(counterUniform(spec.seed, static_cast<std::uint64_t>(sample),
                                                drawnStream(nd.name), 0)));
  d.jitter = spec.jitter;
  d.detonators = spec.detonators;
  if (spec.jitter) d.stepFactor = stepFactor(*spec.jitter, spec.seed, sample);
  return d;
}


}  // namespace c2d
