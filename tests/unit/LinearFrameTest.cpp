// LinearFrame: rigid-body modes, tangent vs finite differences, symmetry,
// mid-point energy identity, mass and body load, and closed-form cantilevers.
#include "elements/LinearFrame.h"
#include "tests/unit/ElementTestSupport.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

namespace c2d {
namespace {

MaterialSet frameMaterial(bool shear, MassType mass = MassType::Consistent) {
  MaterialSet m;
  m.number = 1;
  m.elementType = "FRAMe";
  m.E = 2.1e8;
  m.nu = 0.3;
  m.A = 0.12;
  m.I = 1.6e-3;
  m.density = 7.8;
  m.shear = shear;
  m.mass = mass;
  return m;
}

StepRule makeRule(Scheme scheme, double alpha = 0) {
  StepRule r;
  r.scheme = scheme;
  r.alpha = alpha;
  if (scheme != Scheme::Static) {
    r.cv = 2.0 / 0.01;
    r.vv = -1.0;
    r.va = 0.3;
    r.ca = 4.0 / (0.01 * 0.01);
    r.av = -4.0 / 0.01;
    r.aa = -1.0;
  }
  return r;
}

// Infinitesimal rigid modes of an element with nodes x1, x2.
std::vector<ElemVec> rigidModes(const Vec2& x1, const Vec2& x2) {
  ElemVec tx, ty, rz;
  tx << 1, 0, 0, 1, 0, 0;
  ty << 0, 1, 0, 0, 1, 0;
  const Vec2 c(0.3, -0.7);  // any pivot
  rz << -(x1.y() - c.y()), x1.x() - c.x(), 1, -(x2.y() - c.y()), x2.x() - c.x(), 1;
  return {tx, ty, rz};
}

// Parameter: SHEAr ON (Timoshenko) or OFF (Euler-Bernoulli).
struct LinearFrameParam : ::testing::TestWithParam<bool> {};

TEST_P(LinearFrameParam, LinearFrameRigidBodyModesGiveZeroResidual) {
  const Vec2 x1(1.0, 2.0), x2(3.5, 0.4);
  LinearFrame e(frameMaterial(GetParam()), {0, 1}, x1, x2);
  const double scale = e.stiffness().cwiseAbs().maxCoeff();
  for (const ElemVec& d : rigidModes(x1, x2)) {
    ElementKinematics kin{d, ElemVec::Zero(), ElemVec::Zero(), ElemVec::Zero()};
    ElemVec r;
    ElemMat k;
    ASSERT_TRUE(e.evaluate(kin, makeRule(Scheme::Static), true, r, k).ok);
    EXPECT_LT(r.norm(), 1e-12 * scale * d.norm());
    EXPECT_LT(e.strainEnergy(), 1e-12 * scale * d.squaredNorm());
  }
}

TEST_P(LinearFrameParam, LinearFrameTangentMatchesFiniteDifferences) {
  std::mt19937 gen(7);
  const Vec2 x1(0.2, -0.1), x2(-1.1, 2.3);
  LinearFrame e(frameMaterial(GetParam()), {0, 1}, x1, x2);
  const StepRule rules[] = {makeRule(Scheme::Static), makeRule(Scheme::Newmark),
                            makeRule(Scheme::MidPoint, 0.0), makeRule(Scheme::MidPoint, 0.2)};
  // Small increments, and rotation increments near 1 rad, where the mid-point
  // scheme's pairing of the rotation forces with the Cayley rate (dtheta / c)
  // and the inertia's slope c' differ from 1 by 10 %.
  for (double size : {0.01, 0.5}) {
    for (const StepRule& rule : rules) {
      ElementKinematics kin{test::randomVec(gen, size), test::randomVec(gen, size),
                            test::randomVec(gen, 0.5), test::randomVec(gen, 5.0)};
      ElemVec r;
      ElemMat k;
      ASSERT_TRUE(e.evaluate(kin, rule, true, r, k).ok);
      const ElemMat fd = test::centralDifferenceTangent(e, kin, rule);
      EXPECT_LT((fd - k).cwiseAbs().maxCoeff(), 1e-7 * k.cwiseAbs().maxCoeff())
          << "size " << size << " scheme " << static_cast<int>(rule.scheme);
    }
  }
}

TEST_P(LinearFrameParam, LinearFrameStiffnessAndMassAreSymmetric) {
  for (MassType mt : {MassType::Consistent, MassType::Lumped}) {
    LinearFrame e(frameMaterial(GetParam(), mt), {0, 1}, Vec2(0, 0), Vec2(1.2, 0.9));
    const ElemMat& k = e.stiffness();
    const ElemMat m = e.mass();
    EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
    EXPECT_LT((m - m.transpose()).cwiseAbs().maxCoeff(), 1e-14 * m.cwiseAbs().maxCoeff());
    // Positive definite mass (rhoI > 0 here).
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<ElemMat>(m).eigenvalues().minCoeff(), 0.0);
  }
}

// (d - dn).f_int = W(d) - W(dn) + alpha dd.K.dd (for the one-point element
// alpha l dE.C.dE is exactly dd.K.dd; for the exact Euler-Bernoulli stiffness too).
TEST_P(LinearFrameParam, LinearFrameMidPointEnergyIdentity) {
  std::mt19937 gen(11);
  LinearFrame e(frameMaterial(GetParam()), {0, 1}, Vec2(0.5, 0.5), Vec2(2.0, 1.5));
  for (double alpha : {0.0, 0.2}) {
    for (int trial = 0; trial < 5; ++trial) {
      const ElemVec d = test::randomVec(gen, 0.02), dn = test::randomVec(gen, 0.02);
      ElemVec r;
      ElemMat k;
      ASSERT_TRUE(e.evaluate({dn, dn, ElemVec::Zero(), ElemVec::Zero()},
                             makeRule(Scheme::Static), false, r, k).ok);
      const double wn = e.strainEnergy();
      // Internal force only: no inertia coefficients.
      StepRule rule = makeRule(Scheme::MidPoint, alpha);
      rule.ca = rule.av = rule.aa = 0;
      ASSERT_TRUE(e.evaluate({d, dn, ElemVec::Zero(), ElemVec::Zero()}, rule, false, r, k).ok);
      const double w = e.strainEnergy();
      const ElemVec dd = d - dn;
      const double rhs = w - wn + alpha * dd.dot(e.stiffness() * dd);
      // The force pairs with the rotations' Cayley increments (core/StepRule.h).
      EXPECT_NEAR(rule.rate(dd).dot(r), rhs, 1e-12 * (std::abs(w) + std::abs(wn)));
    }
  }
}

TEST_P(LinearFrameParam, LinearFrameMassReproducesRigidMotionKineticEnergy) {
  const double l = 2.5;
  const Vec2 t(std::cos(0.4), std::sin(0.4)), x1(1, 1), x2 = x1 + l * t;
  const MaterialSet mat = frameMaterial(GetParam());
  LinearFrame e(mat, {0, 1}, x1, x2);
  const double rhoA = mat.rhoA(), rhoI = mat.rhoI();
  ElemVec v;
  v << 0.3, -1.2, 0, 0.3, -1.2, 0;
  EXPECT_NEAR(e.kineticEnergy(v), 0.5 * rhoA * l * v.head<2>().squaredNorm(), 1e-12);
  // Spin omega about the midpoint: both interpolations represent it exactly.
  const double w = 1.7;
  const Vec2 n(-t.y(), t.x());
  v << -0.5 * l * w * n, w, 0.5 * l * w * n, w;
  EXPECT_NEAR(e.kineticEnergy(v), 0.5 * w * w * (rhoA * l * l * l / 12 + rhoI * l), 1e-12);
  // Lumped: point masses at the ends.
  LinearFrame lumped(frameMaterial(GetParam(), MassType::Lumped), {0, 1}, x1, x2);
  EXPECT_NEAR(lumped.kineticEnergy(v), 0.5 * w * w * (rhoA * l * l * l / 4 + rhoI * l), 1e-12);
}

// The consistent load of a uniform g equals M_consistent (rhoI = 0) times the
// rigid translation by g, since the interpolation holds translations exactly.
TEST_P(LinearFrameParam, LinearFrameBodyLoadIsConsistent) {
  MaterialSet mat = frameMaterial(GetParam());
  mat.I = 0;
  mat.resEI = 5000.0;  // bending stiffness without rotary inertia
  const Vec2 x1(0, 0), x2(1.5, 2.0), g(0.4, -9.81);
  LinearFrame e(mat, {0, 1}, x1, x2);
  ElemVec gt;
  gt << g, 0, g, 0;
  const ElemVec f = e.bodyLoad(g);
  EXPECT_LT((f - e.mass() * gt).norm(), 1e-12 * f.norm());
  EXPECT_NEAR(f(0) + f(3), mat.rhoA() * 2.5 * g.x(), 1e-12);
  EXPECT_NEAR(f(1) + f(4), mat.rhoA() * 2.5 * g.y(), 1e-12);
  if (!GetParam()) {
    const double q = mat.rhoA() * (-0.8 * g.x() + 0.6 * g.y());
    EXPECT_NEAR(f(2), q * 2.5 * 2.5 / 12, 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(LinearFrameShear, LinearFrameParam, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "Timoshenko" : "EulerBernoulli"; });

// Cantilever of n elements along the direction `angle`, clamped at the origin,
// global tip load (Fx, Fy, M): the elements and the solved nodal dofs.
struct Cantilever {
  std::vector<LinearFrame> elems;
  Eigen::VectorXd d;
};

Cantilever solveCantilever(const MaterialSet& mat, int n, double l, double angle,
                           const Vec3& tipLoad) {
  const Vec2 t(std::cos(angle), std::sin(angle));
  Cantilever c;
  for (int e = 0; e < n; ++e)
    c.elems.emplace_back(mat, std::array<int, 2>{e, e + 1}, (l * e / n) * t,
                         (l * (e + 1) / n) * t);
  const int ndof = 3 * (n + 1);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(ndof, ndof);
  for (int e = 0; e < n; ++e) k.block<6, 6>(3 * e, 3 * e) += c.elems[e].stiffness();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(ndof);
  f.tail<3>() = tipLoad;
  const int nf = ndof - 3;  // node 0 clamped
  c.d = Eigen::VectorXd::Zero(ndof);
  c.d.tail(nf) = k.bottomRightCorner(nf, nf).partialPivLu().solve(f.tail(nf));
  return c;
}

TEST(LinearFrameEulerBernoulli, OneElementCantileverTipDeflection) {
  const MaterialSet mat = frameMaterial(false);
  const double l = 3.0, p = 12.0, ei = mat.EI(), ea = mat.EA();
  for (double angle : {0.0, 0.9}) {
    const Vec2 t(std::cos(angle), std::sin(angle)), n(-t.y(), t.x());
    const Vec3 load(p * n.x() + 2 * p * t.x(), p * n.y() + 2 * p * t.y(), 0);
    Cantilever c = solveCantilever(mat, 1, l, angle, load);
    const Vec2 tip = c.d.segment<2>(3);
    EXPECT_NEAR(tip.dot(n), p * l * l * l / (3 * ei), 1e-12 * p * l * l * l / ei);
    EXPECT_NEAR(tip.dot(t), 2 * p * l / ea, 1e-12 * p * l / ea);
    EXPECT_NEAR(c.d(5), p * l * l / (2 * ei), 1e-12 * p * l * l / ei);
    // Section forces at the midpoint: N = 2P, V = P, M = P l/2.
    ElemVec r;
    ElemMat k;
    const ElemVec de = c.d.head<6>();
    ASSERT_TRUE(c.elems[0].evaluate({de, de, de, de}, makeRule(Scheme::Static), false, r, k).ok);
    const SectionForces s = c.elems[0].sectionForces();
    EXPECT_NEAR(s.N, 2 * p, 1e-9 * p);
    EXPECT_NEAR(s.V, p, 1e-9 * p);
    EXPECT_NEAR(s.M, p * l / 2, 1e-9 * p * l);
  }
}

// One-point Timoshenko element, n elements of length h = L/n, tip force P:
// every element carries V = P and the midpoint moment M_e = P(L - x_mid), so
// the nodal rotations are exact, theta(x) = P(Lx - x^2/2)/EI; the shear
// strain is P/GA and v_tip = PL/GA + trapezoidal rule of theta over the mesh,
// which for a quadratic is exact + h^2/12 (theta'(L) - theta'(0)):
//   v_tip = PL^3/(3EI) (1 - 1/(4 n^2)) + PL/GA.
TEST(LinearFrameTimoshenko, CantileverTipDeflectionMeshFactor) {
  MaterialSet mat = frameMaterial(true);
  mat.resGA = 2.0e5;  // shear term of the same order as bending
  const double l = 3.0, p = 12.0, ei = mat.EI(), ga = mat.GA();
  for (double angle : {0.0, -2.2}) {
    const Vec2 t(std::cos(angle), std::sin(angle)), n(-t.y(), t.x());
    for (int ne : {1, 2, 4}) {
      Cantilever c = solveCantilever(mat, ne, l, angle, Vec3(p * n.x(), p * n.y(), 0));
      const double vTip = p * l * l * l / (3 * ei) * (1 - 1.0 / (4 * ne * ne)) + p * l / ga;
      const int tip = 3 * ne;
      EXPECT_NEAR(c.d.segment<2>(tip).dot(n), vTip, 1e-10 * vTip) << "n = " << ne;
      EXPECT_NEAR(c.d.segment<2>(tip).dot(t), 0.0, 1e-10 * vTip);
      EXPECT_NEAR(c.d(tip + 2), p * l * l / (2 * ei), 1e-10 * p * l * l / ei);
      // Midpoint section forces of the element next to the support.
      ElemVec r;
      ElemMat k;
      const ElemVec de = c.d.head<6>();
      ASSERT_TRUE(
          c.elems[0].evaluate({de, de, de, de}, makeRule(Scheme::Static), false, r, k).ok);
      EXPECT_NEAR(c.elems[0].sectionForces().V, p, 1e-9 * p);
      EXPECT_NEAR(c.elems[0].sectionForces().M, p * (l - 0.5 * l / ne), 1e-9 * p * l);
    }
  }
}

TEST(LinearFrameTimoshenko, ReportsFailureOnNonFiniteState) {
  LinearFrame e(frameMaterial(true), {0, 1}, Vec2(0, 0), Vec2(1, 0));
  ElemVec d = ElemVec::Zero();
  d(4) = std::nan("");
  ElemVec r;
  ElemMat k;
  EXPECT_FALSE(e.evaluate({d, ElemVec::Zero(), ElemVec::Zero(), ElemVec::Zero()},
                          makeRule(Scheme::Static), true, r, k)
                   .ok);
}

TEST(LinearFrameTimoshenko, RevertRestoresCommittedReport) {
  LinearFrame e(frameMaterial(true), {0, 1}, Vec2(0, 0), Vec2(1, 0));
  ElemVec d = ElemVec::Zero(), r;
  ElemMat k;
  d(4) = 1e-3;
  ASSERT_TRUE(e.evaluate({d, d, d, d}, makeRule(Scheme::Static), false, r, k).ok);
  e.commit();
  const double w = e.strainEnergy();
  ASSERT_TRUE(e.evaluate({2 * d, d, d, d}, makeRule(Scheme::Static), false, r, k).ok);
  EXPECT_NEAR(e.strainEnergy(), 4 * w, 1e-12 * w);
  e.revert();
  EXPECT_EQ(e.strainEnergy(), w);
}

}  // namespace
}  // namespace c2d
