#pragma once
// How the time integrator relates velocities and the inertia "acceleration" to
// the trial displacement d_{n+1}. Every integrator here makes them affine in the
// increment's rate measure r(d - d_n):
//   v_{n+1} = cv*r + vv*v_n + va*a_n
//   a_eff   = ca*r + av*v_n + aa*a_n
// a_eff is the acceleration that multiplies M in the residual (a_{n+1} for
// Newmark, (v_{n+1} - v_n)/dt for the mid-point scheme). Elements use it for
// their own internal dofs (a joint's relative rotation) with the same formulas.
//
// r is the increment itself for translations and, except under the mid-point
// scheme, for rotations. Under the mid-point scheme a rotation advances by the
// Cayley rule: its rate over the step is 2 tan(dtheta/2)/dt, so that
//   2 tan(dtheta/2) = dt ((1/2 + beta) omega_{n+1} + (1/2 - beta) omega_n).
// With it the geometrically exact beam's algorithmic forces conserve energy and
// angular momentum together (elements/ReissnerFrame.h); with additive rates no
// energy conserving force can (docs/history.md). A rotation increment must
// stay below pi in magnitude within one step.
#include <array>
#include <cmath>
#include <numbers>

#include "core/Types.h"

namespace c2d {

enum class Scheme {
  Static,    // no inertia; internal force at d_{n+1}
  Newmark,   // inertia M a_{n+1}; internal force at d_{n+1}
  MidPoint,  // energy conserving/decaying: algorithmic internal force between d_n and d_{n+1}
};

// The Cayley rate measure c(x) = 2 tan(x/2) of a rotation increment x, its
// slope c'(x) = 1 + c^2/4, and x / c(x) with its slope (even, near 1 for small x;
// series below |x| = 0.1, where the closed forms lose digits).
namespace cayley {
inline double increment(double x) { return 2 * std::tan(0.5 * x); }
inline double slope(double x) {
  const double t = std::tan(0.5 * x);
  return 1 + t * t;
}
inline double ratio(double x) {
  if (std::abs(x) < 0.1) {
    const double y = x * x / 4;  // (x/2)^2; x/c = (x/2) cot(x/2) = 1 - y/3 - y^2/45 - 2y^3/945
    return 1 - y / 3 * (1 + y / 15 * (1 + 2 * y / 21));
  }
  return 0.5 * x / std::tan(0.5 * x);
}
inline double ratioSlope(double x) {
  if (std::abs(x) < 0.1) {
    const double y = x * x / 4;
    return -x / 6 * (1 + 2 * y / 15 * (1 + 3 * y / 21));
  }
  const double h = 0.5 * x, s = std::sin(h);
  return 0.5 * (std::cos(h) / s - h / (s * s));
}
}  // namespace cayley

struct StepRule {
  Scheme scheme = Scheme::Static;
  // Mid-point strain weight: stress resultants from (1/2+alpha) E_{n+1} + (1/2-alpha) E_n.
  double alpha = 0;
  // Mid-point velocity weight: (d_n+1 - d_n)/h = (v_n+1 + v_n)/2 + beta (v_n+1 - v_n),
  // which takes beta m |v_n+1 - v_n|^2 from a mass m in a step.
  double beta = 0;
  // The step's length t_n+1 - t_n (dynamic rules; 0 in statics): rates over
  // the step, a dashpot's.
  double h = 0;
  double cv = 0, vv = 0, va = 0;
  double ca = 0, av = 0, aa = 0;
  bool operator==(const StepRule&) const = default;
  bool dynamic() const { return scheme != Scheme::Static; }
  // Rotations advance by the Cayley rule: under the mid-point scheme.
  bool rotationsByCayley() const { return scheme == Scheme::MidPoint; }
  // Weight of the n+1 state in the residual (1 for static/Newmark, 1/2 for mid-point loads).
  double loadWeight() const { return scheme == Scheme::MidPoint ? 0.5 : 1.0; }

  // Rate measure of a rotation increment and its slope.
  double rotationRate(double dth) const { return rotationsByCayley() ? cayley::increment(dth) : dth; }
  double rotationRateSlope(double dth) const { return rotationsByCayley() ? cayley::slope(dth) : 1.0; }
  // Rate measure of global dof i's increment (dof order u, v, theta per node).
  double rate(long i, double dd) const { return i % kNodeDofs == 2 ? rotationRate(dd) : dd; }
  double rateSlope(long i, double dd) const {
    return i % kNodeDofs == 2 ? rotationRateSlope(dd) : 1.0;
  }
  // The same for an element's increment.
  ElemVec rate(const ElemVec& dd) const {
    ElemVec r = dd;
    for (int i : {2, 2 + kNodeDofs}) r(i) = rotationRate(dd(i));
    return r;
  }

  // Under the Cayley rule a rotation increment of pi or more has no rate: the
  // step that asks for one is too long (elements return a failure).
  bool rotationInRange(double dth) const { return !rotationsByCayley() || std::abs(dth) < std::numbers::pi; }
  bool rotationsInRange(const ElemVec& dd) const {
    return rotationInRange(dd(2)) && rotationInRange(dd(2 + kNodeDofs));
  }
  static constexpr const char* kRotationRangeMessage =
      "a rotation increment of pi or more in one step (the limit of the Cayley rule): the step is too long";

  // v_{n+1} and a_eff from the rate measure r of the increment.
  template <class D>
  auto velocity(const D& r, const D& vn, const D& an) const {
    return cv * r + vv * vn + va * an;
  }
  template <class D>
  auto acceleration(const D& r, const D& vn, const D& an) const {
    return ca * r + av * vn + aa * an;
  }
  double velocity(double r, double vn, double an) const { return cv * r + vv * vn + va * an; }
  double acceleration(double r, double vn, double an) const { return ca * r + av * vn + aa * an; }

  // Inertia of an element's constant mass matrix m: residual m a_eff, tangent ca m diag(r').
  // halfTan: tan(dd/2) of the two rotations when the element has them at hand.
  void addInertia(const ElemMat& m, const ElemVec& dd, const ElemVec& vn, const ElemVec& an,
                  ElemVec& residual, ElemMat* tangent,
                  const std::array<double, 2>* halfTan = nullptr) const {
    ElemVec r = dd;
    if (!rotationsByCayley()) {
      residual += m * acceleration(r, vn, an);
      if (tangent) *tangent += ca * m;
      return;
    }
    ElemVec slope = ElemVec::Ones();
    for (int a = 0; a < 2; ++a) {  // one tangent per rotation: c = 2t, c' = 1 + t^2
      const int i = 2 + a * kNodeDofs;
      const double t = halfTan ? (*halfTan)[a] : std::tan(0.5 * dd(i));
      r(i) = 2 * t;
      slope(i) = 1 + t * t;
    }
    residual += m * acceleration(r, vn, an);
    if (tangent) *tangent += ca * (m * slope.asDiagonal());
  }

  // An element whose internal force f pairs with the additive increment (a
  // geometrically linear one) balances inertia paired with the rate measure:
  // its rotation entries are scaled by dtheta / c(dtheta), so that f.r(dd) is
  // the work f.dd it was built for (k: the tangent of f, updated to match).
  void pairWithRate(const ElemVec& dd, ElemVec& f, ElemMat* k) const {
    if (!rotationsByCayley()) return;
    for (int i : {2, 2 + kNodeDofs}) {
      const double s = cayley::ratio(dd(i));
      if (k) {
        k->row(i) *= s;
        (*k)(i, i) += f(i) * cayley::ratioSlope(dd(i));
      }
      f(i) *= s;
    }
  }
};

}  // namespace c2d
