#include "core/contact/GroundContact.h"

#include <algorithm>
#include <cmath>

#include "core/contact/ContactDamper.h"
#include "core/contact/CrushingLaw.h"
#include "core/contact/SpringFriction.h"

namespace c2d {

namespace {
bool crushes(const Ground& g) { return g.restitution < 1; }

CrushingLaw crushing(const Ground& g, double loading) {
  return CrushingLaw(g.k, g.restitution, loading);
}
}  // namespace

double contactEnergy(const Ground& g, double q, double y) {
  return crushingEnergy(g.k, g.restitution, q, penetration(g, y));
}

double loadingPoint(const Ground& g, double q, double m, double y, double vn, double v) {
  // The penetration's rate is -v (it grows as the node moves down).
  return crushingLoadingPoint(g.k, g.restitution, q, m, penetration(g, y), -vn, -v);
}

ImpactOwed groundImpactOwed(const Ground& g, double q, double loading, double owed, double p0,
                            double p1, double m, double vn, double v, const StepRule& rule) {
  if (p1 <= 0 || !crushes(g) || rule.scheme != Scheme::MidPoint || !(rule.beta > 0) ||
      !(m > 0 && std::isfinite(m)))
    return {loading, 0.0, 0.0};
  const double e2 = g.restitution * g.restitution;
  // A node inside its dent at both ends (below the set) is not pushed: its
  // loss is not the contact's.
  const double set = std::max(q, p0) * (1 - e2);
  const double loss = p0 <= set && p1 <= set ? 0.0 : rule.beta * m * (v - vn) * (v - vn);
  if (p1 >= loading) return {loading, std::max(owed, 0.0) + e2 * loss, 0.0};  // loading
  // A turn inside the step (the node's velocity changed sign): the loss is
  // shared between the loading and the unloading as the step's time is, at
  // a constant force |vn| to |v|.
  const bool turned = vn < 0 && v > 0;
  // Below the loading point: a settled contact, or one that reloads, owes nothing.
  if (!turned && (owed == kImpactSettled || p1 > p0)) return {loading, kImpactSettled, 0.0};
  const double share = turned ? (e2 * -vn + v) / (v - vn) : 1.0;
  const double due = std::max(owed, 0.0) + share * loss;
  if (!(due > 0)) return {loading, 0.0, 0.0};
  const double raised = crushingRaised(g.k, g.restitution, loading, p1, due);
  const double given = crushingEnergy(g.k, g.restitution, raised, p1) -
                       crushingEnergy(g.k, g.restitution, loading, p1);
  return {raised, std::max(0.0, due - given), given};
}

ContactForce groundContact(const Ground& g, double q, double yn, double y, const StepRule& rule,
                           const GroundDamper& d) {
  ContactForce out;
  const double p0 = penetration(g, yn), p1 = penetration(g, y);
  const CrushingLaw law = crushing(g, std::max(q, p0));
  if (rule.scheme != Scheme::MidPoint) {
    if (p1 > 0) {
      out.force = out.normal = law.force(p1);
      out.tangent = out.normalTangent = law.slope(p1);
    }
  } else if (p0 > 0 || p1 > 0) {
    // The law's discrete derivative between p0 and p1 (core/contact/CrushingLaw.h).
    law.midPoint(p0, p1, out.force, out.tangent);
    out.normal = out.force;
    out.normalTangent = out.tangent;
  }
  // The dashpot; Newmark's rate of the penetration at t_n+1 is -v_n+1.
  if (d.c > 0) {
    const double rate = -rule.velocity(y - yn, d.vn, d.an);
    const DamperForce f = damperForce(d.c, law.ps, p0, p1, rate, rule.cv, rule);
    out.force += f.force;
    out.tangent += f.slope;
  }
  return out;
}

FrictionForce groundFriction(const Ground& g, const ContactForce& c, double a, double xn, double x,
                             const StepRule& rule, double stick) {
  // N: the contact's whole normal force while it pushes (its dashpot's part
  // too: Coulomb's bound is on what the ground bears), depending on y through
  // the penetration y0 - y.
  const bool pushes = c.force > 0;
  const SpringFrictionForce f =
      springFriction(g.k, stick, g.mu, pushes ? c.force : 0.0, a, xn, x,
                     rule.dynamic() ? rule.h : 0.0, rule.scheme == Scheme::MidPoint);
  return {f.force, f.dx, pushes ? -f.dN * c.tangent : 0.0, f.anchor, f.slipped};
}

double groundDissipation(const Ground& g, double q, double a, double xn, double yn, double x,
                         double y, const StepRule& rule, const GroundDamper& damper,
                         double stick) {
  const double c = damper.c;
  const ContactForce f = groundContact(g, q, yn, y, rule, damper);
  const double p0 = penetration(g, yn), p1 = penetration(g, y);
  const CrushingLaw law = crushing(g, q);
  double d = 0;
  // Crushing: the loading work beyond q less what the stiffer unloading stores.
  if (crushes(g)) d += law.dissipated(p0, p1);
  d += damperDissipation(c, crushing(g, std::max(q, p0)).ps, p0, p1, rule);
  d += groundFriction(g, f, a, xn, x, rule, stick).slipped;
  return d;
}

}  // namespace c2d
