#include "core/contact/ContactDamper.h"

#include <algorithm>

namespace c2d {

DamperForce damperForce(double c, double ps, double p0, double p1, double rate, double rateSlope,
                        const StepRule& rule) {
  DamperForce out;
  if (c <= 0 || (p1 <= ps && (rule.scheme != Scheme::MidPoint || p0 <= ps))) return out;
  if (rule.scheme == Scheme::MidPoint) {
    out.force = c * (std::max(p1 - ps, 0.0) - std::max(p0 - ps, 0.0)) / rule.h;
    if (p1 > ps) out.slope = c / rule.h;
  } else if (rule.scheme == Scheme::Newmark) {
    out.force = c * rate;
    out.slope = c * rateSlope;
  }
  return out;
}

double damperDissipation(double c, double ps, double p0, double p1, const StepRule& rule) {
  if (c <= 0 || rule.scheme != Scheme::MidPoint || (p0 <= ps && p1 <= ps)) return 0.0;
  return c * (std::max(p1 - ps, 0.0) - std::max(p0 - ps, 0.0)) * (p1 - p0) / rule.h;
}

}  // namespace c2d
