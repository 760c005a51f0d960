#include "core/contact/ContactDamper.h"

#include <algorithm>

namespace c2d {

DamperRamp damperRamp(double ps, double p0, double p1) {
  DamperRamp out;
  if (p1 <= ps) return out;
  // Within one step's motion of the set the force ramps from 0 (w), so that
  // it is continuous where the contact begins or ends (a jump of c v there
  // left Newton's method no root: a bar landing at 1.2 m/s on a critical
  // dashpot cycled at dt = 0.001).
  const double D = std::abs(p1 - p0), over = p1 - ps;
  if (over >= D) {
    out.w = 1.0;
    return out;
  }
  out.w = over / D;
  out.slope = 1 / D - over * (p1 > p0 ? 1.0 : -1.0) / (D * D);
  return out;
}

DamperForce damperForce(double c, double ps, double p0, double p1, double rate, double rateSlope,
                        const StepRule& rule) {
  DamperForce out;
  if (c <= 0 || (p1 <= ps && (rule.scheme != Scheme::MidPoint || p0 <= ps))) return out;
  if (rule.scheme == Scheme::MidPoint) {
    out.force = c * (std::max(p1 - ps, 0.0) - std::max(p0 - ps, 0.0)) / rule.h;
    if (p1 > ps) out.slope = c / rule.h;
  } else if (rule.scheme == Scheme::Newmark) {
    const DamperRamp r = damperRamp(ps, p0, p1);
    const double w = r.w, dw = r.slope;
    out.force = c * rate * w;
    out.slope = c * (rateSlope * w + rate * dw);
  }
  return out;
}

double damperDissipation(double c, double ps, double p0, double p1, const StepRule& rule) {
  if (c <= 0 || rule.scheme != Scheme::MidPoint || (p0 <= ps && p1 <= ps)) return 0.0;
  return c * (std::max(p1 - ps, 0.0) - std::max(p0 - ps, 0.0)) * (p1 - p0) / rule.h;
}

}  // namespace c2d
