#include "core/contact/SpringFriction.h"

#include <algorithm>
#include <cmath>

#include "core/contact/ContactDamper.h"

namespace c2d {

double frictionStickDamping(double k, double m) { return damperCoefficient(1.0, k, m); }

SpringFrictionForce springFriction(double k, double c, double mu, double N, double a, double xn,
                                   double x, double h, bool midPoint) {
  SpringFrictionForce out;
  out.anchor = x;
  if (mu <= 0) return out;
  if (N <= 0) {  // out of contact: the spring lets go
    out.slipped = springFrictionEnergy(k, xn - a);
    return out;
  }
  if (!(h > 0) || !(c > 0)) c = 0;
  const double L = mu * N / k;  // the stretch at which the spring alone carries mu N
  // A spring beyond the step's reach slides at once to it (sigma: its side).
  const double e = xn - a;
  const bool clamped = std::abs(e) > L;
  const double sigma = e > 0 ? 1.0 : -1.0;
  const double e0 = clamped ? sigma * L : e;
  if (clamped) out.slipped = 0.5 * k * (e * e - L * L);
  const double dx = x - xn;
  // Along the path in the frame of the motion (s: its sign, d: its length):
  // stick while k e + c d/h < k L, i.e. for the first xi of d.
  const double s = dx >= 0 ? 1.0 : -1.0, d = std::abs(dx);
  const double rate = c > 0 ? c / h : 0.0;  // the dashpot's force per unit of d
  const double es = s * e0;                 // the stretch at t_n in that frame
  const double xi = std::max(0.0, L - rate * d / k - es);
  const double dNclamp = clamped ? sigma * mu : 0.0;  // d(k e0)/dN
  double e1 = 0;                                      // the stretch at t_n+1 in the frame
  double W = 0;                                       // the element's work over the step
  if (xi >= d) {  // sticks all the way: F = k e + c d/h
    e1 = es + d;
    W = k * d * (es + 0.5 * d) + rate * d * d;
    if (midPoint) {
      out.force = -(k * (e0 + 0.5 * dx) + rate * dx);
      out.dx = -(0.5 * k + rate);
    } else {
      out.force = -(k * (e0 + dx) + rate * dx);
      out.dx = -(k + rate);
    }
    out.dN = -dNclamp;
  } else {  // sticks over xi, then slides at mu N while e relaxes towards L
    const double T = h * (d - xi) / d;  // the sliding part's duration
    const double E = c > 0 ? std::exp(-k * T / c) : 0.0;
    e1 = L - (L - (es + xi)) * E;
    W = k * xi * (es + 0.5 * xi) + rate * d * xi + k * L * (d - xi);
    if (midPoint) {
      out.force = -s * W / d;
      // W is stationary in xi (k (es + xi) + c d/h = k L where xi > 0).
      out.dx = -k * xi * (0.5 * xi + rate * d / k) / (d * d);
      const double dWdL = k * (d - xi) + (clamped ? k * xi * s * sigma : 0.0);
      out.dN = -s * dWdL * (mu / k) / d;
    } else {
      out.force = -s * mu * N;
      out.dN = -s * mu;
    }
  }
  out.anchor = x - s * e1;
  out.slipped += std::max(0.0, W - 0.5 * k * (e1 * e1 - e0 * e0));
  return out;
}

}  // namespace c2d
