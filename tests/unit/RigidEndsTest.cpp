// Rigid end zones (elements/RigidEnds.h) in the frame elements: the stiffness
// against the closed form of a beam with rigid ends, rigid-body modes, tangents
// against finite differences in SMALl and FINIte kinematics, the mid-point
// work identity and moment balance, mass, and restart round trips.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <sstream>

#include "elements/ElementFactory.h"
#include "elements/InelasticFrame.h"
#include "elements/LinearFrame.h"
#include "elements/ReissnerFrame.h"
#include "elements/RigidEnds.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d {
namespace {

StepRule makeRule(Scheme scheme, double alpha = 0) { return test::stepRule(scheme, alpha); }

ElemMat tangentAt(Element& e, const ElemVec& d, const StepRule& rule = makeRule(Scheme::Static)) {
  ElemVec r;
  ElemMat k;
  EXPECT_TRUE(e.evaluate({d, d, ElemVec::Zero(), ElemVec::Zero()}, rule, true, r, k).ok);
  return k;
}

// The tip (node 2) displacement of a cantilever fixed at node 1 under the tip
// load p (global components and moment), from the element's stiffness.
Vec3 tipDisplacement(const ElemMat& k, const Vec3& p) {
  return k.bottomRightCorner<3, 3>().partialPivLu().solve(p);
}

constexpr double kO1 = 0.6, kO2 = 0.25;  // rigid zones (m)

// A horizontal Euler-Bernoulli cantilever of length L with rigid zones a at the
// root and b at the tip under a transverse tip load P: with l = L - a - b,
//   v_tip = P/(3EI) ((l + b)^3 - b^3),  theta_tip = P/(2EI) ((l + b)^2 - b^2),
// the axial tip displacement under an axial load H: H l/EA.
TEST(RigidEndsStiffness, EulerBernoulliCantileverMatchesClosedForm) {
  const MaterialSet mat = test::resultantMaterial(Kinematics::Small, false);
  const double L = 3.0, l = L - kO1 - kO2, ei = mat.EI(), ea = mat.EA();
  for (double angle : {0.0, 0.7, -2.1}) {
    const Eigen::Matrix2d q = test::rot(angle);
    const Vec2 x1(0.4, -1.0), x2 = x1 + q * Vec2(L, 0);
    LinearFrame e(mat, {0, 1}, x1, x2, {kO1, kO2});
    const double P = 3.0, H = 50.0, b = kO2;
    const Vec2 load = q * Vec2(H, P);
    const Vec3 d = tipDisplacement(e.stiffness(), Vec3(load.x(), load.y(), 0));
    const Vec2 local = q.transpose() * d.head<2>();
    EXPECT_NEAR(local.y(), P / (3 * ei) * (std::pow(l + b, 3) - std::pow(b, 3)), 1e-10);
    EXPECT_NEAR(d(2), P / (2 * ei) * (std::pow(l + b, 2) - b * b), 1e-10);
    EXPECT_NEAR(local.x(), H * l / ea, 1e-12);
  }
}

// The 6x6 stiffness of a Timoshenko beam with rigid ends: K = T^T K_flex T,
// K_flex the element's own on the flexible length, T written out here
// (v_face1 = v1 + a theta1, v_face2 = v2 - b theta2 for a horizontal beam).
TEST(RigidEndsStiffness, TimoshenkoIsTransformedFlexibleStiffness) {
  const MaterialSet mat = test::resultantMaterial(Kinematics::Small, true);
  const double L = 2.5, l = L - kO1 - kO2;
  LinearFrame e(mat, {0, 1}, Vec2(1, 2), Vec2(1 + L, 2), {kO1, kO2});
  LinearFrame flex(mat, {0, 1}, Vec2(0, 0), Vec2(l, 0));
  ElemMat t = ElemMat::Identity();
  t(1, 2) = kO1;
  t(4, 5) = -kO2;
  const ElemMat expected = t.transpose() * flex.stiffness() * t;
  EXPECT_LT((e.stiffness() - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.norm());
  // The cantilever's tip deflection: the one-point element's l^3/4 bending
  // flexibility and l/GA shear, with the tip arm b: P (l^3/(4EI) + l/GA) + b^2 l P/EI + b l^2 P/EI.
  const double P = 2.0, b = kO2;
  const Vec3 d = tipDisplacement(e.stiffness(), Vec3(0, P, 0));
  const double v = P * (std::pow(l, 3) / (4 * mat.EI()) + l / mat.GA()) +
                   P * b * b * l / mat.EI() + P * b * l * l / mat.EI();
  EXPECT_NEAR(d(1), v, 1e-10 * v);
}

// Mass and self-weight are the full length's, as without rigid zones.
TEST(RigidEndsStiffness, MassAndBodyLoadAreTheFullLengths) {
  for (MassType mt : {MassType::Consistent, MassType::Lumped})
    for (Kinematics kin : {Kinematics::Small, Kinematics::Finite}) {
      MaterialSet mat = test::resultantMaterial(kin, true, mt);
      if (kin == Kinematics::Small) mat.hardening = HardeningData{1.0, 2.0, 40, 4};
      const Vec2 x1(0, 0), x2(1.2, 1.6);
      auto with = makeElement(mat, {0, 1}, x1, x2, {kO1, kO2});
      auto without = makeElement(mat, {0, 1}, x1, x2);
      EXPECT_LT((with->mass() - without->mass()).norm(), 1e-14);
      EXPECT_LT((with->bodyLoad(Vec2(0, -9.81)) - without->bodyLoad(Vec2(0, -9.81))).norm(), 1e-14);
    }
}

// Small kinematics: translations and the infinitesimal rotation about any
// point give no force; the inelastic element's stiffness equals the elastic one's.
TEST(RigidEndsRigidBody, SmallRigidModesGiveNoForce) {
  const Vec2 x1(0.2, 0.1), x2(1.4, 2.0);
  MaterialSet mat = test::resultantMaterial(Kinematics::Small);
  LinearFrame lin(mat, {0, 1}, x1, x2, {kO1, kO2});
  mat.hardening = HardeningData{1.0, 2.0, 40, 4};
  InelasticFrame inel(mat, {0, 1}, x1, x2, {kO1, kO2});
  ElemVec spin;
  spin << -x1.y(), x1.x(), 1, -x2.y(), x2.x(), 1;
  for (const ElemVec& mode :
       {ElemVec((ElemVec() << 1, 0, 0, 1, 0, 0).finished()),
        ElemVec((ElemVec() << 0, 1, 0, 0, 1, 0).finished()), spin}) {
    EXPECT_LT((lin.stiffness() * mode).norm(), 1e-10 * lin.stiffness().norm());
    EXPECT_LT((tangentAt(inel, ElemVec::Zero()) * mode).norm(), 1e-10 * lin.stiffness().norm());
  }
  EXPECT_LT((tangentAt(inel, ElemVec::Zero()) - lin.stiffness()).cwiseAbs().maxCoeff(),
            1e-12 * lin.stiffness().norm());
}

// Finite kinematics: any rigid motion, however large its rotation, gives no
// force (static and mid-point), and the tangent at rest is the linear one.
TEST(RigidEndsRigidBody, FiniteRigidMotionsGiveZeroResidual) {
  const Vec2 x1(1.0, -0.5), x2(2.2, 1.1);
  const MaterialSet mat = test::resultantMaterial(Kinematics::Finite);
  ReissnerFrame e(mat, {0, 1}, x1, x2, {kO1, kO2});
  test::expectRigidMotionsGiveZeroResidual(e, x1, x2);
  MaterialSet small = mat;
  small.kinematics = Kinematics::Small;
  LinearFrame lin(small, {0, 1}, x1, x2, {kO1, kO2});
  const ElemMat k0 = tangentAt(e, ElemVec::Zero());
  EXPECT_LT((k0 - lin.stiffness()).cwiseAbs().maxCoeff(), 1e-12 * k0.norm());
}

// Tangents against central differences of the residual: the exact map's
// geometric term (static, Newmark) and the algorithmic one's (mid-point).
TEST(RigidEndsTangent, FiniteMatchesFiniteDifferencesForEveryScheme) {
  std::mt19937 gen(36);
  const Vec2 x1(0.0, 0.0), x2(1.6, -1.2);
  MaterialSet hardening = test::resultantMaterial(Kinematics::Finite);
  hardening.hardening = HardeningData{0.5, 1.0, 40, 4};
  for (const MaterialSet& mat : {test::resultantMaterial(Kinematics::Finite), hardening}) {
    ReissnerFrame e(mat, {0, 1}, x1, x2, {kO1, kO2});
    for (const StepRule& rule : {makeRule(Scheme::Static), makeRule(Scheme::Newmark),
                                 makeRule(Scheme::MidPoint, 0.0), makeRule(Scheme::MidPoint, 0.2)}) {
      // The inelastic mid-point moment's own tangent is not the exact
      // derivative (HingedBending::midPointMoment), with or without zones.
      if (mat.hardening && rule.scheme == Scheme::MidPoint) continue;
      for (auto [w1, w0] : {std::pair{4.0, 2.9}, std::pair{-3.6, -2.4}, std::pair{0.3, 0.3}}) {
        const ElementKinematics kin{
            test::rigidMotion(x1, x2, w1, Vec2(0.2, 0.1), Vec2(0.3, -0.4)) + test::randomVec(gen, 0.05),
            test::rigidMotion(x1, x2, w0, Vec2(0.2, 0.1), Vec2(0.3, -0.4)) + test::randomVec(gen, 0.05),
            test::randomVec(gen, 1.0), test::randomVec(gen, 10.0)};
        ElemVec r;
        ElemMat k;
        ASSERT_TRUE(e.evaluate(kin, rule, true, r, k).ok);
        const ElemMat fd = test::centralDifferenceTangent(e, kin, rule);
        EXPECT_LT((fd - k).cwiseAbs().maxCoeff(), 1e-6 * k.cwiseAbs().maxCoeff())
            << "scheme " << static_cast<int>(rule.scheme) << " alpha " << rule.alpha << " w " << w1
            << " hardening " << mat.hardening.has_value();
      }
    }
  }
}

TEST(RigidEndsTangent, SmallMatchesFiniteDifferences) {
  std::mt19937 gen(7);
  const Vec2 x1(0.0, 0.0), x2(0.9, 2.0);
  MaterialSet mat = test::resultantMaterial(Kinematics::Small);
  mat.hardening = HardeningData{0.5, 1.0, 40, 4};
  InelasticFrame e(mat, {0, 1}, x1, x2, {kO1, kO2});
  for (const StepRule& rule : {makeRule(Scheme::Static), makeRule(Scheme::MidPoint, 0.1)}) {
    const ElementKinematics kin{test::randomVec(gen, 0.05), test::randomVec(gen, 0.05),
                                test::randomVec(gen, 1.0), test::randomVec(gen, 10.0)};
    ElemVec r;
    ElemMat k;
    ASSERT_TRUE(e.evaluate(kin, rule, true, r, k).ok);
    const ElemMat fd = test::centralDifferenceTangent(e, kin, rule);
    EXPECT_LT((fd - k).cwiseAbs().maxCoeff(), 1e-6 * k.cwiseAbs().maxCoeff());
    // The axial force's gradient maps to the nodes with the same map.
    const double n0 = e.axialForce();
    ElementKinematics kp = kin;
    kp.d(2) += 1e-7;
    ASSERT_TRUE(e.evaluate(kp, rule, false, r, k).ok);
    EXPECT_NEAR((e.axialForce() - n0) / 1e-7, e.axialForceGradient()(2), 1e-4 * std::abs(n0) + 1e-6);
  }
}

// Under the mid-point scheme the nodal force's work on the increments (the
// rotations' Cayley measure) is the flexible part's energy change, and its
// moment about the mid-point configuration vanishes: the algorithmic map keeps
// the element's conservation properties.
TEST(RigidEndsMidPoint, WorkIdentityAndMomentBalance) {
  std::mt19937 gen(99);
  const Vec2 x1(0.0, 0.0), x2(0.8, 1.5);
  const MaterialSet mat = test::resultantMaterial(Kinematics::Finite);
  ReissnerFrame e(mat, {0, 1}, x1, x2, {kO1, kO2});
  StepRule rule = makeRule(Scheme::MidPoint, 0.0);
  rule.ca = rule.av = rule.aa = 0;  // internal force only
  for (auto [w1, w0] : {std::pair{0.3, 0.1}, std::pair{4.0, 2.6}, std::pair{12.0, 10.0}}) {
    const ElemVec d = test::rigidMotion(x1, x2, w1, Vec2(0.2, 0.1), Vec2(0.3, -0.4)) +
                      test::randomVec(gen, 0.05);
    const ElemVec dn = test::rigidMotion(x1, x2, w0, Vec2(0.2, 0.1), Vec2(0.3, -0.4)) +
                       test::randomVec(gen, 0.05);
    ElemVec f;
    ElemMat k;
    ASSERT_TRUE(e.evaluate({d, dn, ElemVec::Zero(), ElemVec::Zero()}, rule, false, f, k).ok);
    const double w = e.energy(d), wn = e.energy(dn);
    EXPECT_NEAR(rule.rate(d - dn).dot(f), w - wn, 1e-11 * (std::abs(w) + std::abs(wn)));
    const ElemVec m = 0.5 * (d + dn);
    const Vec2 p1 = x1 + m.segment<2>(0), p2 = x2 + m.segment<2>(3);
    auto cross = [](const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
    EXPECT_LT((f.segment<2>(0) + f.segment<2>(3)).norm(), 1e-11 * f.norm());
    EXPECT_LT(std::abs(cross(p1, f.segment<2>(0)) + f(2) + cross(p2, f.segment<2>(3)) + f(5)),
              1e-11 * f.norm());
  }
}

// The faces of a finite element move rigidly with the nodes: a bent state's
// strains are those of a plain element between the faces' displaced positions.
TEST(RigidEndsRigidBody, FiniteStrainsAreTheFlexiblePartsBetweenTheFaces) {
  std::mt19937 gen(3);
  const Vec2 x1(0.5, 0.0), x2(0.5, 3.0);  // a column
  const MaterialSet mat = test::resultantMaterial(Kinematics::Finite);
  ReissnerFrame e(mat, {0, 1}, x1, x2, {kO1, kO2});
  const Vec2 f1 = x1 + Vec2(0, kO1), f2 = x2 - Vec2(0, kO2);
  ReissnerFrame plain(mat, {0, 1}, f1, f2);
  const ElemVec d = test::randomVec(gen, 0.8);
  ElemVec df = d;
  df.segment<2>(0) += test::rot(d(2)) * Vec2(0, kO1) - Vec2(0, kO1);
  df.segment<2>(3) += test::rot(d(5)) * Vec2(0, -kO2) - Vec2(0, -kO2);
  EXPECT_LT((e.strains(d) - plain.strains(df)).norm(), 1e-14);
}

// Restart files keep the rigid zones: the element read back gives the same
// residual and tangent.
TEST(RigidEndsRestart, RoundTripKeepsTheZones) {
  std::mt19937 gen(11);
  const Vec2 x1(0.0, 0.0), x2(2.0, 0.5);
  MaterialSet inel = test::resultantMaterial(Kinematics::Small);
  inel.hardening = HardeningData{0.5, 1.0, 40, 4};
  for (const MaterialSet& mat : {test::resultantMaterial(Kinematics::Small), inel,
                                 test::resultantMaterial(Kinematics::Finite)}) {
    auto a = makeElement(mat, {0, 1}, x1, x2, {kO1, kO2});
    auto b = makeElement(mat, {0, 1}, x1, x2);
    std::stringstream s;
    dynamic_cast<Checkpoint&>(*a).writeState(s);
    dynamic_cast<Checkpoint&>(*b).readState(s);
    EXPECT_EQ(rigidOffsets(*b)[0], kO1);
    EXPECT_EQ(rigidOffsets(*b)[1], kO2);
    const ElemVec d = test::randomVec(gen, 0.02);
    const ElementKinematics kin{d, d, ElemVec::Zero(), ElemVec::Zero()};
    ElemVec ra, rb;
    ElemMat ka, kb;
    ASSERT_TRUE(a->evaluate(kin, makeRule(Scheme::Static), true, ra, ka).ok);
    ASSERT_TRUE(b->evaluate(kin, makeRule(Scheme::Static), true, rb, kb).ok);
    EXPECT_EQ(ra, rb);
    EXPECT_EQ(ka, kb);
  }
}

TEST(RigidEndsMap, RefusesZonesWithoutFlexibleLength) {
  EXPECT_THROW(RigidEnds(Vec2(0, 0), Vec2(1, 0), 0.6, 0.4), std::invalid_argument);
  EXPECT_THROW(RigidEnds(Vec2(0, 0), Vec2(1, 0), -0.1, 0.0), std::invalid_argument);
  EXPECT_NO_THROW(RigidEnds(Vec2(0, 0), Vec2(1, 0), 0.6, 0.3));
}

}  // namespace
}  // namespace c2d
