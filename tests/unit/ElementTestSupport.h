#pragma once
// Shared by the element tests: random element vectors, a section given by its
// resultant stiffnesses, and the tangent by central differences of an element's
// residual.
#include <gtest/gtest.h>

#include <random>

#include <cmath>

#include "core/Element.h"
#include "core/MaterialSet.h"
#include "core/StepRule.h"

namespace c2d::test {

inline ElemVec randomVec(std::mt19937& gen, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  ElemVec v;
  for (int i = 0; i < kElemDofs; ++i) v(i) = u(gen);
  return v;
}

inline Eigen::Matrix2d rot(double a) {
  return (Eigen::Matrix2d() << std::cos(a), -std::sin(a), std::sin(a), std::cos(a)).finished();
}

// Nodal displacements of the rigid motion x -> c + R(w)(x - c) + t.
inline ElemVec rigidMotion(const Vec2& x1, const Vec2& x2, double w, const Vec2& c, const Vec2& t) {
  ElemVec d;
  d << c + rot(w) * (x1 - c) + t - x1, w, c + rot(w) * (x2 - c) + t - x2, w;
  return d;
}

// A step rule of the scheme: Newmark's trapezoidal coefficients for dt = 0.05.
inline StepRule stepRule(Scheme scheme, double alpha = 0) {
  StepRule r;
  r.scheme = scheme;
  r.alpha = alpha;
  if (scheme != Scheme::Static) {
    const double dt = 0.05;
    r.cv = 2.0 / dt;
    r.vv = -1.0;
    r.ca = 4.0 / (dt * dt);
    r.av = -4.0 / dt;
    r.aa = -1.0;
  }
  return r;
}

// EA = 2e4, GA = 8e3, EI = 1e2 (A = 2, I = 0.05 for the mass, density 0.5).
inline MaterialSet resultantMaterial(Kinematics kin, bool shear = true,
                                     MassType mass = MassType::Consistent) {
  MaterialSet m;
  m.number = 1;
  m.elementType = "FRAMe";
  m.kinematics = kin;
  m.shear = shear;
  m.E = 1.0e4;
  m.nu = 0.25;
  m.A = 2.0;
  m.I = 0.05;
  m.resEA = 2.0e4;
  m.resGA = 8.0e3;
  m.resEI = 1.0e2;
  m.density = 0.5;
  m.mass = mass;
  return m;
}

// Stiff bars of unit mass per length (density 1, A = 1): EA = GA = 1e6,
// EI = 1e4; the debris figures' test models.
inline MaterialSet unitMassBarMaterial() {
  MaterialSet m;
  m.number = 1;
  m.elementType = "FRAMe";
  m.resEA = m.resGA = 1e6;
  m.resEI = 1e4;
  m.density = 1;
  m.A = 1;
  return m;
}

// A FINIte rod's set with the hinge laws: 10 kg/m, bilinear hardening to
// Mu = 2.4 and softening Ks = -8 with the rupture rotation thetaR.
inline MaterialSet hingedRodMaterial(double thetaR) {
  MaterialSet m;
  m.number = 1;
  m.elementType = "FRAMe";
  m.kinematics = Kinematics::Finite;
  m.resEA = 1e6;
  m.resGA = 5e5;
  m.resEI = 1e3;
  m.density = 1;
  m.A = 10;
  m.I = 1e-2;
  m.hardening = HardeningData{{1.0, 2.0, 400, 40}};
  m.softening = SofteningData{2.4, -8, thetaR};
  return m;
}

// dr/dd by central differences with step h, each residual evaluated without tangent.
inline ElemMat centralDifferenceTangent(Element& e, const ElementKinematics& kin,
                                        const StepRule& rule, double h = 1e-6) {
  ElemMat fd;
  for (int j = 0; j < kElemDofs; ++j) {
    ElementKinematics kp = kin, km = kin;
    kp.d(j) += h;
    km.d(j) -= h;
    ElemVec rp, rm;
    ElemMat unused;
    EXPECT_TRUE(e.evaluate(kp, rule, false, rp, unused).ok);
    EXPECT_TRUE(e.evaluate(km, rule, false, rm, unused).ok);
    fd.col(j) = (rp - rm) / (2 * h);
  }
  return fd;
}

}  // namespace c2d::test
