#pragma once
// Shared by the element tests: random element vectors, a section given by its
// resultant stiffnesses, the tangent by central differences of an element's
// residual, a Reissner element's end displacements for given strains, and one
// time step of an analysis solved by Newton iterations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/Element.h"
#include "core/MaterialSet.h"
#include "core/StepRule.h"
#include "solvers/Analysis.h"
#include "tests/unit/FrameMaterialSupport.h"

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

// Nodal displacements of an element from x1 (the origin) at angle phi, turned
// rigidly by rho about node 1, with strains eps, gamma and curvature kappa.
inline ElemVec turned(double l, double phi, double rho, double eps, double gamma, double kappa) {
  ElemVec d;
  const double th2 = rho + kappa * l;
  const Vec2 x2 = l * Vec2(std::cos(phi), std::sin(phi));
  const Vec2 y2 = l * (rot(phi + 0.5 * (rho + th2)) * Vec2(1 + eps, gamma));
  d << 0, 0, rho, y2.x() - x2.x(), y2.y() - x2.y(), th2;
  return d;
}

// Kinematics d at t_n+1 and dn at t_n, with constant rates at t_n.
inline ElementKinematics kinAt(const ElemVec& d, const ElemVec& dn) {
  ElementKinematics kin;
  kin.d = d;
  kin.dn = dn;
  kin.vn.setConstant(0.2);
  kin.an.setConstant(-1.0);
  return kin;
}

// Kinematics d from rest: no displacement, velocity or acceleration at t_n.
inline ElementKinematics staticKinematics(const ElemVec& d) {
  ElementKinematics k;
  k.d = d;
  k.dn.setZero();
  k.vn.setZero();
  k.an.setZero();
  return k;
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

// A finite element from x1 to x2 under rigid motions (rotations up to 10 rad
// about c, a translation t): no force and no strain energy at rest (static),
// and no mid-point force between two different rigid positions either.
inline void expectRigidMotionsGiveZeroResidual(Element& e, const Vec2& x1, const Vec2& x2) {
  const Vec2 c(-0.7, 0.4), t(1.5, -2.5);
  for (double w : {0.0, 0.7, 3.5, 10.0, -7.3}) {
    const ElemVec d = rigidMotion(x1, x2, w, c, t);
    ElemVec r;
    ElemMat k;
    ASSERT_TRUE(
        e.evaluate({d, d, ElemVec::Zero(), ElemVec::Zero()}, stepRule(Scheme::Static), true, r, k)
            .ok);
    EXPECT_LT(r.norm(), 1e-10) << "w = " << w;
    EXPECT_LT(e.strainEnergy(), 1e-20);
    const ElemVec dn = rigidMotion(x1, x2, w - 2.5, c, -t);  // below pi (Cayley)
    StepRule rule = stepRule(Scheme::MidPoint, 0.1);
    rule.ca = rule.av = rule.aa = 0;
    ASSERT_TRUE(e.evaluate({d, dn, ElemVec::Zero(), ElemVec::Zero()}, rule, true, r, k).ok);
    EXPECT_LT(r.norm(), 1e-10) << "w = " << w;
  }
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
  return resultantFrame(Kinematics::Small, 1e6, 1e6, 1e4, 1, 1, 0);
}

// A FINIte rod's set with the hinge laws: 10 kg/m, bilinear hardening to
// Mu = 2.4 and softening Ks = -8 with the rupture rotation thetaR.
inline MaterialSet hingedRodMaterial(double thetaR) {
  MaterialSet m = resultantFrame(Kinematics::Finite, 1e6, 5e5, 1e3, 1, 10, 1e-2);
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

// e's tangent at kin against central differences of its residual: the relative
// error (Frobenius norms); e's trial state is left at kin.
inline double tangentError(Element& e, const ElementKinematics& kin, const StepRule& rule) {
  ElemVec r, again;
  ElemMat k, unused;
  EXPECT_TRUE(e.evaluate(kin, rule, true, r, k).ok);
  const ElemMat fd = centralDifferenceTangent(e, kin, rule, 1e-8);
  EXPECT_TRUE(e.evaluate(kin, rule, true, again, unused).ok);
  return (k - fd).norm() / k.norm();
}

// One step (TIME) solved by Newton iterations, at most maxIterations for each
// part of it (a step through an impact is taken in parts: solvers/ImpactSteps.h);
// prints the iteration history when it does not converge (unless quiet).
inline bool solveStep(Analysis& an, int maxIterations = 40, bool quiet = false) {
  if (!an.advance()) return false;
  IterationInfo info;
  for (int i = 0; i < maxIterations; ++i) {
    if (!an.iterate(false, false, info)) return false;
    if (info.converged) return true;
    if (info.subStep) i = -1;
  }
  if (quiet) return false;
  for (const IterationInfo& h : an.stepHistory())
    std::printf("  iteration %d: residual %.3e energy %.3e\n", h.iteration, h.residual, h.energy);
  return false;
}

}  // namespace c2d::test
