#include "core/GroundContact.h"

#include <algorithm>
#include <cmath>

#include "core/CrushingLaw.h"
#include "core/SpringFriction.h"

namespace c2d {

namespace {
double groundAlpha(const Ground& g, const StepRule& rule) {
  return g.alpha >= 0 ? g.alpha : rule.alpha;
}

bool crushes(const Ground& g) { return g.restitution < 1; }

CrushingLaw crushing(const Ground& g, double loading) {
  return CrushingLaw(g.k, g.restitution, loading);
}
}  // namespace

double contactEnergy(const Ground& g, double q, double y) {
  return crushingEnergy(g.k, g.restitution, q, penetration(g, y));
}

double loadingPoint(const Ground& g, double q, double y) {
  return crushingLoadingPoint(q, penetration(g, y));
}

ContactForce groundContact(const Ground& g, double q, double yn, double y, const StepRule& rule) {
  ContactForce out;
  const double p1 = penetration(g, y);
  if (rule.scheme != Scheme::MidPoint) {
    if (p1 > 0) {
      const CrushingLaw law = crushing(g, std::max(q, penetration(g, yn)));
      out.force = out.normal = law.force(p1);
      out.tangent = out.normalTangent = law.slope(p1);
    }
    return out;
  }
  // The law's discrete derivative between p0 and p1 (core/CrushingLaw.h).
  const double p0 = penetration(g, yn);
  if (p0 > 0 || p1 > 0) crushing(g, std::max(q, p0)).midPoint(p0, p1, out.force, out.tangent);
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

FrictionForce groundFriction(const Ground& g, const ContactForce& c, double a, double xn, double x,
                             const StepRule& rule) {
  const SpringFrictionForce f = springFriction(g.k, g.mu, std::max(c.normal, 0.0), a, xn, x,
                                              rule.scheme == Scheme::MidPoint);
  // N depends on y through the penetration y0 - y.
  return {f.force, f.dx, -f.dN * c.normalTangent, f.anchor, f.slipped};
}

double groundDissipation(const Ground& g, double q, double a, double xn, double yn, double x,
                         double y, const StepRule& rule) {
  const ContactForce c = groundContact(g, q, yn, y, rule);
  const double p0 = penetration(g, yn), p1 = penetration(g, y);
  double d = 0;
  // Crushing: the loading work beyond q less what the stiffer unloading stores.
  if (crushes(g)) d += crushing(g, q).dissipated(p0, p1);
  if (rule.scheme == Scheme::MidPoint)
    d += groundAlpha(g, rule) * g.k * (std::max(p1, 0.0) - std::max(p0, 0.0)) * (p1 - p0);
  d += groundFriction(g, c, a, xn, x, rule).slipped;
  return d;
}

}  // namespace c2d
