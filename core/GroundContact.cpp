#include "core/GroundContact.h"

#include <algorithm>
#include <cmath>

namespace c2d {

namespace {
double groundAlpha(const Ground& g, const StepRule& rule) {
  return g.alpha >= 0 ? g.alpha : rule.alpha;
}
}  // namespace

ContactForce groundContact(const Ground& g, double yn, double y, const StepRule& rule) {
  ContactForce out;
  const double p1 = penetration(g, y);
  if (rule.scheme != Scheme::MidPoint) {
    if (p1 > 0) {
      out.force = out.normal = g.k * p1;
      out.tangent = out.normalTangent = g.k;
    }
    return out;
  }
  // Discrete gradient of U(p) = k <p>^2 / 2 between p0 and p1, in closed form
  // on each branch: dividing U1 - U0 by p1 - p0 would lose all digits when the
  // step hardly moves a resting node (force error eps*p/dp, tangent eps*p^2/dp^2).
  const double p0 = penetration(g, yn);
  const double dp = p1 - p0;
  if (p0 > 0 && p1 > 0) {
    out.force = 0.5 * g.k * (p0 + p1);
    out.tangent = 0.5 * g.k;
  } else if (p1 > 0) {
    // Entering: (k p1^2/2)/(p1 - p0), p0 <= 0 < p1, so dp >= p1 > 0.
    out.force = 0.5 * g.k * p1 * p1 / dp;
    out.tangent = g.k * p1 / dp - 0.5 * g.k * p1 * p1 / (dp * dp);
  } else if (p0 > 0) {
    // Leaving: (k p0^2/2)/(p0 - p1), p1 <= 0 < p0.
    out.force = -0.5 * g.k * p0 * p0 / dp;
    out.tangent = 0.5 * g.k * p0 * p0 / (dp * dp);
  }
  out.normal = out.force;
  out.normalTangent = out.tangent;
  // Dissipation (eq 75) on the change of the penetration while in contact,
  // alpha k (<p1> - <p0>): the paper's alpha k (p1 - p0) when the node is in
  // contact at both ends of the step, and continuous when it enters or leaves
  // (alpha k dp would jump by alpha k |p0| as p1 passes zero, and Newton's
  // method then cycles between the two sides). Its work on the step,
  // -alpha k (<p1> - <p0>) dp, is never positive.
  const double alpha = groundAlpha(g, rule);
  if (alpha > 0) {
    out.force += alpha * g.k * (std::max(p1, 0.0) - std::max(p0, 0.0));
    if (p1 > 0) out.tangent += alpha * g.k;
  }
  return out;
}

double frictionRegularisation(const Ground& g, double mass, double nRef, double dt,
                              double shortest) {
  const double eps = mass > 0 ? 0.5 * g.mu * nRef * dt * dt / mass : 0.0;
  return std::max(eps, 1e-9 * shortest);
}

FrictionForce groundFriction(const Ground& g, const ContactForce& c, double dx, double eps) {
  FrictionForce out;
  if (g.mu <= 0 || c.normal <= 0) return out;
  const double s2 = dx * dx + eps * eps, s = std::sqrt(s2);
  out.force = -g.mu * c.normal * dx / s;
  out.dx = -g.mu * c.normal * eps * eps / (s2 * s);
  // N depends on y through the penetration p = y0 - y.
  out.dy = g.mu * c.normalTangent * dx / s;
  return out;
}

double groundDissipation(const Ground& g, double xn, double yn, double x, double y,
                         const StepRule& rule, double eps) {
  const ContactForce c = groundContact(g, yn, y, rule);
  double d = 0;
  if (rule.scheme == Scheme::MidPoint) {
    const double p0 = penetration(g, yn), p1 = penetration(g, y);
    d += groundAlpha(g, rule) * g.k * (std::max(p1, 0.0) - std::max(p0, 0.0)) * (p1 - p0);
  }
  const double dx = x - xn;
  d -= groundFriction(g, c, dx, eps).force * dx;
  return d;
}

}  // namespace c2d
