#include "solvers/ImpactSteps.h"

#include <algorithm>
#include <cmath>

#include "core/io/Checkpoint.h"
#include "core/contact/CrushingLaw.h"

namespace c2d {

namespace {

// The length to take again a step of length h in which the contact c touched
// and turned or turned and let go: the unloading time 1/omega_u of its mass
// (the loading time for an elastic contact), within [h/4, h/2].
double eventLength(const ContactMotion& c, double h) {
  double length = 0.25 * h;
  if (c.m > 0 && std::isfinite(c.m) && c.k > 0) length = c.e * std::sqrt(c.m / c.k);
  return std::clamp(length, h / 16, 0.5 * h);
}

}  // namespace

double ImpactSteps::need(const ContactMotion& c, const StepRule& rule, double negligible) {
  const bool newmark = rule.scheme == Scheme::Newmark;
  const bool crushes = c.e<1, damped = c.c> 0;
  // The mid-point scheme's discrete gradient of an elastic law is exact.
  if (!rule.dynamic() || rule.h <= 0 || (!crushes && !damped && !newmark)) return 0;
  const CrushingLaw law(c.k, c.e, std::max(c.q, c.p0));
  // The contact's energy: its mass's motion along it and what it stores.
  const double kinetic =
      c.m > 0 && std::isfinite(c.m) ? 0.5 * c.m * std::max(c.r0 * c.r0, c.r1 * c.r1) : 0.0;
  const double energy = kinetic + std::max(crushingEnergy(c.k, c.e, c.q, c.p0),
                                           crushingEnergy(c.k, c.e, std::max(c.q, c.p0), c.p1));
  // The chatter of a resting body is no impact, nor is a motion whose energy
  // is negligible against the run's.
  if (!(energy > kChatter * c.rest && energy > negligible)) return 0;
  const bool touching0 = c.p0 > law.ps, touching1 = c.p1 > law.ps;
  if ((crushes || damped) &&
      ((touching0 && c.r0 > 0 && !touching1) || (!touching0 && touching1 && c.r1 < 0)))
    return kEvent;
  // A turn inside the step: the peak its mass came back from lies beyond the
  // steps' ends by a share that grows as h^2; beyond the set it let go too.
  double eta = 0;
  if (crushes && c.r0 > 0 && c.r1 < 0 && c.p1 > 0) {
    const double peak = crushingPeak(c.k, c.e, c.m, c.p1, c.r1);
    if (c.p1 <= (1 - c.e * c.e) * peak) return kEvent;
    eta = (peak / std::max({c.q, c.p0, c.p1}) - 1) / (newmark ? kPeakNewmark : kPeak);
    // The mid-point scheme's decay over the turn, beta m (r1 - r0)^2, which the
    // contact gives back as the loading's and the unloading's in shares that
    // only a short step makes exact (core/contact/GroundContact.h).
    if (rule.beta > 0 && c.m > 0 && std::isfinite(c.m))
      eta = std::max(eta, rule.beta * c.m * (c.r1 - c.r0) * (c.r1 - c.r0) /
                              (kTolerance * c.e * c.e * energy));
  }
  const double dp = c.p1 - c.p0;
  double error = 0;
  if (newmark && (c.p0 > 0 || c.p1 > 0) && dp != 0) {
    // The trapezoid of the end forces against the law's work on the path.
    double work = 0, slope = 0;
    law.midPoint(c.p0, c.p1, work, slope);
    error += (0.5 * (law.force(c.p0) + law.force(c.p1)) - work) * dp;
  }
  if (damped && (touching0 || touching1)) {
    const double s0 = std::max(c.p0 - law.ps, 0.0), s1 = std::max(c.p1 - law.ps, 0.0);
    const double share = dp != 0 ? (s1 - s0) / dp : 1.0;  // of the path, touching
    const double exact = c.c * rule.h * share * (c.r0 * c.r0 + c.r0 * c.r1 + c.r1 * c.r1) / 3;
    const double scheme =
        newmark ? 0.5 * c.c * ((touching0 ? c.r0 : 0.0) + (touching1 ? c.r1 : 0.0)) * dp
                : c.c * (s1 - s0) * dp / rule.h;
    error += scheme - exact;
  }
  return std::max(eta, std::abs(error) / (kTolerance * c.e * c.e * energy));
}

double ImpactSteps::check(Assembler& a, const State& s, const StepRule& rule, double dt) {
  const double previous = proposal_;
  proposal_ = 0;
  if (!enabled_ || !rule.dynamic() || rule.h <= 0) return 0;
  a.contactMotions(s, motions_);
  peak_ = std::max(peak_, a.kineticEnergy(s));
  double worst = 0, again = rule.h;
  for (const ContactMotion& c : motions_) {
    const double eta = need(c, rule, kNegligible * peak_);
    if (eta == kEvent)
      again = std::min(again, eventLength(c, rule.h));
    else
      worst = std::max(worst, eta);
  }
  if (worst > 1) again = std::min(again, 0.9 * rule.h / std::sqrt(worst));
  const double floor = kFloor * dt;
  if (again < rule.h && rule.h > floor * (1 + 1e-9)) {
    ++rejected_;
    growing_ = true;
    return std::max(again, floor);
  }
  // After a step taken again, and while a contact's step was near its limit,
  // the next one grows by at most 2 (a jump back to DT's end would only be
  // taken again).
  if (growing_ && rule.h >= dt * (1 - 1e-9)) growing_ = false;
  // (A part that DT's end cut short keeps the proposal it had.)
  if (growing_) proposal_ = std::max(2 * rule.h, previous);
  if (worst > 1e-6) {
    const double length = rule.h * std::min(2.0, 0.9 / std::sqrt(worst));
    proposal_ = proposal_ > 0 ? std::min(proposal_, length) : length;
  }
  return 0;
}

void ImpactSteps::write(std::ostream& out) const {
  using namespace checkpoint;
  putTag(out, "IMPS");
  putBool(out, enabled_);
  putBool(out, growing_);
  put(out, proposal_);
  put(out, peak_);
  put(out, rejected_);
}

void ImpactSteps::read(std::istream& in) {
  using namespace checkpoint;
  expectTag(in, "IMPS");
  enabled_ = getBool(in);
  growing_ = getBool(in);
  proposal_ = get<double>(in);
  peak_ = get<double>(in);
  rejected_ = get<int>(in);
}

}  // namespace c2d
