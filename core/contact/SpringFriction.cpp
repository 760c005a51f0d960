#include "core/contact/SpringFriction.h"

#include <cmath>

namespace c2d {

SpringFrictionForce springFriction(double k, double mu, double N, double a, double xn, double x,
                                   bool midPoint) {
  SpringFrictionForce out;
  out.anchor = x;
  if (mu <= 0) return out;
  if (N <= 0) {  // out of contact: the spring lets go
    out.slipped = springFrictionEnergy(k, xn - a);
    return out;
  }
  const double L = mu * N / k;  // the spring's reach
  if (!midPoint) {              // return mapping at t_n+1
    const double trial = k * (x - a);
    if (std::abs(trial) <= mu * N) {
      out.force = -trial;
      out.dx = -k;
      out.anchor = a;
    } else {
      const double s = trial > 0 ? 1.0 : -1.0;
      out.force = -s * mu * N;
      out.dN = -s * mu;
      out.anchor = x - s * L;
      out.slipped = mu * N * std::abs(out.anchor - a);
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
  const double xe = a0 + s * L;        // where sliding starts on the way to x
  if (dx == 0 || s * (x - xe) <= 0) {  // elastic all the way
    out.force = -0.5 * k * (x + xn - 2 * a0);
    out.dx = -0.5 * k;
    if (clamped) out.dN = -sigma * mu;  // a0 = xn - sigma mu N / k
    out.anchor = a0;
    return out;
  }
  // Elastic from xn to xe, then sliding at s mu N: the work over dx.
  const double we = (xe - xn) / dx, ws = (x - xe) / dx;  // weights >= 0, sum 1
  const double F = we * 0.5 * k * (xe + xn - 2 * a0) + ws * s * mu * N;
  out.force = -F;
  out.dx = -0.5 * k * we * we;
  // dW/dN: the sliding stretch's force, and the reach's shift of xe (and of a0
  // when the spring slid at once).
  const double dWdN = mu * (s * (x - a0) - L) + (clamped ? mu * L * (s * sigma - 1) : 0.0);
  out.dN = -dWdN / dx;
  out.anchor = x - s * L;
  out.slipped += mu * N * std::abs(x - xe);
  return out;
}

}  // namespace c2d
