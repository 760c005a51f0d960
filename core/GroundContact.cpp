#include "core/GroundContact.h"

#include <algorithm>
#include <cmath>

namespace c2d {

namespace {
double groundAlpha(const Ground& g, const StepRule& rule) {
  return g.alpha >= 0 ? g.alpha : rule.alpha;
}

bool crushes(const Ground& g) { return g.restitution < 1; }

// The crushing law at the loading point q: f = k p beyond q, k/e^2 (p - ps)
// between the set ps = q (1 - e^2) and q, 0 below ps.
struct Crushing {
  double k, ku, q, ps;
  Crushing(const Ground& g, double loading)
      : k(g.k),
        ku(g.k / (g.restitution * g.restitution)),
        q(loading),
        ps(loading * (1 - g.restitution * g.restitution)) {}
  double force(double p) const { return p >= q ? k * p : p > ps ? ku * (p - ps) : 0.0; }
  double slope(double p) const { return p >= q ? k : p > ps ? ku : 0.0; }
};

// The mid-point force of the crushing law: its work on the straight path from
// p0 to p1 divided by p1 - p0, summed over the law's linear pieces (the
// trapezoid rule is exact on each), and its derivative with respect to p1,
// sum_i [l_i sum_{j>i} c_j l_j + c_i l_i^2 / 2] / dp^2 for pieces of slope c_i
// and signed length l_i: every term >= 0, so nothing cancels as dp -> 0.
void crushingMidPoint(const Crushing& law, double p0, double p1, ContactForce& out) {
  double pts[4];
  int n = 0;
  pts[n++] = p0;
  const double kinks[2] = {law.ps, law.q};
  for (int i = 0; i < 2; ++i) {
    const double kink = p1 > p0 ? kinks[i] : kinks[1 - i];
    if (kink > std::min(p0, p1) && kink < std::max(p0, p1) && kink != pts[n - 1]) pts[n++] = kink;
  }
  pts[n++] = p1;
  if (n == 2) {  // one piece: the mean of the end forces
    out.force = 0.5 * (law.force(p0) + law.force(p1));
    out.tangent = 0.5 * law.slope(0.5 * (p0 + p1));
    return;
  }
  double work = 0, stiffness = 0, tail = 0;
  for (int i = n - 2; i >= 0; --i) {
    const double a = pts[i], b = pts[i + 1], l = b - a, c = law.slope(0.5 * (a + b));
    work += 0.5 * (law.force(a) + law.force(b)) * l;
    stiffness += l * tail + 0.5 * c * l * l;
    tail += c * l;
  }
  const double dp = p1 - p0;
  out.force = work / dp;
  out.tangent = stiffness / (dp * dp);
}
}  // namespace

double contactEnergy(const Ground& g, double q, double y) {
  const double p = penetration(g, y);
  if (p <= 0) return 0.0;
  if (!crushes(g)) return 0.5 * g.k * p * p;
  const Crushing law(g, std::max(q, p));
  const double f = law.force(p);
  return 0.5 * f * f / law.ku;
}

double loadingPoint(const Ground& g, double q, double y) {
  const double p = penetration(g, y);
  return p > 0 ? std::max(q, p) : 0.0;
}

ContactForce groundContact(const Ground& g, double q, double yn, double y, const StepRule& rule) {
  ContactForce out;
  const double p1 = penetration(g, y);
  if (rule.scheme != Scheme::MidPoint) {
    if (p1 > 0) {
      const Crushing law(g, crushes(g) ? std::max(q, penetration(g, yn)) : 0.0);
      out.force = out.normal = law.force(p1);
      out.tangent = out.normalTangent = law.slope(p1);
    }
    return out;
  }
  // Discrete gradient of U(p) = k <p>^2 / 2 between p0 and p1, in closed form
  // on each branch: dividing U1 - U0 by p1 - p0 would lose all digits when the
  // step hardly moves a resting node (force error eps*p/dp, tangent eps*p^2/dp^2).
  const double p0 = penetration(g, yn);
  const double dp = p1 - p0;
  if (crushes(g)) {
    if (p0 > 0 || p1 > 0) crushingMidPoint(Crushing(g, std::max(q, p0)), p0, p1, out);
  } else if (p0 > 0 && p1 > 0) {
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

FrictionForce groundFriction(const Ground& g, const ContactForce& c, double a, double xn, double x,
                             const StepRule& rule) {
  FrictionForce out;
  out.anchor = x;
  const double N = std::max(c.normal, 0.0);
  if (g.mu <= 0) return out;
  if (N <= 0) {  // off the ground: the spring lets go
    out.slipped = frictionEnergy(g, xn - a);
    return out;
  }
  const double k = g.k, L = g.mu * N / k;  // the spring's reach
  // d(force)/dN -> d/dy_n+1: N depends on y through the penetration y0 - y.
  const double dNdy = -c.normalTangent;
  if (rule.scheme != Scheme::MidPoint) {  // return mapping at t_n+1
    const double trial = k * (x - a);
    if (std::abs(trial) <= g.mu * N) {
      out.force = -trial;
      out.dx = -k;
      out.anchor = a;
    } else {
      const double s = trial > 0 ? 1.0 : -1.0;
      out.force = -s * g.mu * N;
      out.dy = -s * g.mu * dNdy;
      out.anchor = x - s * L;
      out.slipped = g.mu * N * std::abs(out.anchor - a);
    }
    return out;
  }
  // A spring beyond the step's reach slides at once (sigma: its side).
  const double e = xn - a;
  const bool clamped = std::abs(e) > L;
  const double sigma = e > 0 ? 1.0 : -1.0;
  const double a0 = clamped ? xn - sigma * L : a;
  if (clamped) out.slipped = 0.5 * k * (e * e - L * L);
  const double dx = x - xn;
  const double s = dx >= 0 ? 1.0 : -1.0;
  const double xe = a0 + s * L;  // where sliding starts on the way to x
  if (dx == 0 || s * (x - xe) <= 0) {  // elastic all the way
    out.force = -0.5 * k * (x + xn - 2 * a0);
    out.dx = -0.5 * k;
    if (clamped) out.dy = -sigma * g.mu * dNdy;  // a0 = xn - sigma mu N / k
    out.anchor = a0;
    return out;
  }
  // Elastic from xn to xe, then sliding at s mu N: the work over dx.
  const double we = (xe - xn) / dx, ws = (x - xe) / dx;  // weights >= 0, sum 1
  const double F = we * 0.5 * k * (xe + xn - 2 * a0) + ws * s * g.mu * N;
  out.force = -F;
  out.dx = -0.5 * k * we * we;
  // dW/dN: the sliding stretch's force, and the reach's shift of xe (and of
  // a0 when the spring slid at once).
  const double dWdN = g.mu * (s * (x - a0) - L) + (clamped ? g.mu * L * (s * sigma - 1) : 0.0);
  out.dy = -(dWdN / dx) * dNdy;
  out.anchor = x - s * L;
  out.slipped += g.mu * N * std::abs(x - xe);
  return out;
}

double groundDissipation(const Ground& g, double q, double a, double xn, double yn, double x,
                         double y, const StepRule& rule) {
  const ContactForce c = groundContact(g, q, yn, y, rule);
  const double p0 = penetration(g, yn), p1 = penetration(g, y);
  double d = 0;
  // Crushing: the loading work beyond q less what the stiffer unloading stores.
  if (const double q0 = std::max(q, p0); crushes(g) && p1 > q0)
    d += 0.5 * g.k * (1 - g.restitution * g.restitution) * (p1 - q0) * (p1 + q0);
  if (rule.scheme == Scheme::MidPoint)
    d += groundAlpha(g, rule) * g.k * (std::max(p1, 0.0) - std::max(p0, 0.0)) * (p1 - p0);
  d += groundFriction(g, c, a, xn, x, rule).slipped;
  return d;
}

}  // namespace c2d
