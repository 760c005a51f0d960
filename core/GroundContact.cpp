#include "core/GroundContact.h"

#include <cmath>

namespace c2d {

ContactForce groundContact(const Ground& g, double yn, double y, const StepRule& rule) {
  ContactForce out;
  const double p1 = penetration(g, y);
  if (rule.scheme != Scheme::MidPoint) {
    if (p1 > 0) {
      out.force = g.k * p1;
      out.tangent = g.k;
    }
    return out;
  }
  // Discrete gradient of U(p) = k <p>^2 / 2 between p0 and p1.
  const double p0 = penetration(g, yn);
  const double dp = p1 - p0;
  const double u1 = p1 > 0 ? 0.5 * g.k * p1 * p1 : 0.0;
  const double u0 = p0 > 0 ? 0.5 * g.k * p0 * p0 : 0.0;
  const double scale = g.k * (std::abs(p0) + std::abs(p1) + 1e-300);
  if (std::abs(dp) * g.k > 1e-10 * scale) {
    out.force = (u1 - u0) / dp;
    // d/dp1 of (U(p1) - U(p0))/(p1 - p0)
    const double dU1 = p1 > 0 ? g.k * p1 : 0.0;
    out.tangent = (dU1 - out.force) / dp;
  } else {
    const double pm = 0.5 * (p0 + p1);
    out.force = pm > 0 ? g.k * pm : 0.0;
    out.tangent = pm > 0 ? 0.5 * g.k : 0.0;
  }
  const double alpha = g.alpha >= 0 ? g.alpha : rule.alpha;
  if (alpha > 0 && (p1 > 0 || p0 > 0)) {
    out.force += alpha * g.k * dp;
    out.tangent += alpha * g.k;
  }
  return out;
}

}  // namespace c2d
