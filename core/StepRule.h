#pragma once
// How the time integrator relates velocities and the inertia "acceleration" to
// the trial displacement d_{n+1}. Every integrator here makes them affine:
//   v_{n+1} = cv*(d - d_n) + vv*v_n + va*a_n
//   a_eff   = ca*(d - d_n) + av*v_n + aa*a_n
// a_eff is the acceleration that multiplies M in the residual (a_{n+1} for
// Newmark, (v_{n+1} - v_n)/dt for the mid-point scheme). Elements use it for
// their own internal dofs (a joint's relative rotation) with the same formulas.
namespace c2d {

enum class Scheme {
  Static,    // no inertia; internal force at d_{n+1}
  Newmark,   // inertia M a_{n+1}; internal force at d_{n+1}
  MidPoint,  // energy conserving/decaying: algorithmic internal force between d_n and d_{n+1}
};

struct StepRule {
  Scheme scheme = Scheme::Static;
  // Mid-point strain weight: stress resultants from (1/2+alpha) E_{n+1} + (1/2-alpha) E_n.
  double alpha = 0;
  double cv = 0, vv = 0, va = 0;
  double ca = 0, av = 0, aa = 0;

  bool dynamic() const { return scheme != Scheme::Static; }
  // Weight of the n+1 state in the residual (1 for static/Newmark, 1/2 for mid-point loads).
  double loadWeight() const { return scheme == Scheme::MidPoint ? 0.5 : 1.0; }

  template <class D>
  auto velocity(const D& dd, const D& vn, const D& an) const {
    return cv * dd + vv * vn + va * an;
  }
  template <class D>
  auto acceleration(const D& dd, const D& vn, const D& an) const {
    return ca * dd + av * vn + aa * an;
  }
  double velocity(double dd, double vn, double an) const { return cv * dd + vv * vn + va * an; }
  double acceleration(double dd, double vn, double an) const { return ca * dd + av * vn + aa * an; }
};

}  // namespace c2d
