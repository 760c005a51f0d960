#include "core/contact/CrushingLaw.h"

#include <algorithm>
#include <cmath>

namespace c2d {

// Summed over the law's linear pieces between p0 and p1 (the trapezoid rule is
// exact on each); the derivative with respect to p1 is
// sum_i [l_i sum_{j>i} c_j l_j + c_i l_i^2 / 2] / dp^2 for pieces of slope c_i
// and signed length l_i: every term >= 0, so nothing cancels as dp -> 0.
void CrushingLaw::midPoint(double p0, double p1, double& outForce, double& outTangent) const {
  if (ku == k) {
    // Elastic (e = 1): the discrete derivative of k <p>^2 / 2 in closed form on
    // each branch (dividing U1 - U0 by p1 - p0 would lose all digits when the
    // step hardly moves a resting contact: force error eps p/dp, tangent
    // eps p^2/dp^2).
    const double dp = p1 - p0;
    outForce = outTangent = 0;
    if (p0 > 0 && p1 > 0) {
      outForce = 0.5 * k * (p0 + p1);
      outTangent = 0.5 * k;
    } else if (p1 > 0) {  // entering: (k p1^2/2)/(p1 - p0), p0 <= 0 < p1
      outForce = 0.5 * k * p1 * p1 / dp;
      outTangent = k * p1 / dp - 0.5 * k * p1 * p1 / (dp * dp);
    } else if (p0 > 0) {  // leaving: (k p0^2/2)/(p0 - p1), p1 <= 0 < p0
      outForce = -0.5 * k * p0 * p0 / dp;
      outTangent = 0.5 * k * p0 * p0 / (dp * dp);
    }
    return;
  }
  double pts[4];
  int n = 0;
  pts[n++] = p0;
  const double kinks[2] = {ps, q};
  for (int i = 0; i < 2; ++i) {
    const double kink = p1 > p0 ? kinks[i] : kinks[1 - i];
    if (kink > std::min(p0, p1) && kink < std::max(p0, p1) && kink != pts[n - 1]) pts[n++] = kink;
  }
  pts[n++] = p1;
  if (n == 2) {  // one piece: the mean of the end forces
    outForce = 0.5 * (force(p0) + force(p1));
    outTangent = 0.5 * slope(0.5 * (p0 + p1));
    return;
  }
  double work = 0, stiffness = 0, tail = 0;
  for (int i = n - 2; i >= 0; --i) {
    const double a = pts[i], b = pts[i + 1], l = b - a, c = slope(0.5 * (a + b));
    work += 0.5 * (force(a) + force(b)) * l;
    stiffness += l * tail + 0.5 * c * l * l;
    tail += c * l;
  }
  const double dp = p1 - p0;
  outForce = work / dp;
  outTangent = stiffness / (dp * dp);
}

double CrushingLaw::dissipated(double p0, double p1) const {
  const double q0 = std::max(q, p0);
  if (p1 <= q0 || ku <= k) return 0.0;
  return 0.5 * (k - k * k / ku) * (p1 - q0) * (p1 + q0);
}

double crushingPeak(double k, double e, double m, double p, double r) {
  if (!(e < 1) || !(m > 0 && std::isfinite(m)) || k <= 0 || p <= 0 || r >= 0) return p;
  const double a = 1 - e * e;
  // Out of the crushed surface: the set holds p.
  const double free = std::abs(r) * std::sqrt(m / k) / e;
  if (p <= a * free) return free;
  // On the unloading branch: (1 - 2 e^2) q^2 - 2 a p q + p^2 + c0 = 0, c0 = m e^2 r^2 / k,
  // its root in [p, p / a] (where the left side falls from c0 > 0),
  // written without the difference that cancels near e^2 = 1/2.
  const double c0 = m * e * e * r * r / k;
  const double d = std::max(0.0, e * e * e * e * p * p - (1 - 2 * e * e) * c0);
  return std::max(p, (p * p + c0) / (a * p + std::sqrt(d)));
}

double crushingLoadingPoint(double k, double e, double q, double m, double p1, double r0,
                            double r1) {
  const double after = crushingLoadingPoint(q, p1);
  if (p1 <= 0 || !(r0 > 0 && r1 < 0)) return after;
  return std::max(after, crushingPeak(k, e, m, p1, r1));
}

double crushingRaised(double k, double e, double q, double p, double extra) {
  if (!(e < 1) || p <= 0 || q <= p || !(extra > 0)) return q;
  const double a = 1 - e * e, ku = k / (e * e);
  const double u = crushingEnergy(k, e, q, p) + extra;
  if (u >= 0.5 * e * e * k * p * p) return p;
  // (k / e^2)(p - a q')^2 / 2 = u on the unloading branch.
  return std::clamp((p - std::sqrt(2 * u / ku)) / a, p, q);
}

double crushingEnergy(double k, double e, double q, double p) {
  if (p <= 0) return 0.0;
  if (e >= 1) return 0.5 * k * p * p;
  return CrushingLaw(k, e, std::max(q, p)).energy(p);
}

}  // namespace c2d
