// The infill strut element (elements/InfillStrut): its tangent by finite
// differences, geometrically exact under a rigid rotation, the energy of an
// elastic strut conserved under the mid-point rule, its mass and weight at its
// nodes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "core/Brace.h"
#include "elements/InfillStrut.h"
#include "materials/StrutLaw.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d {
namespace {

InfillStrutData strutData(bool finite) {
  InfillStrutData d;
  d.nodes = {0, 1};
  d.x1 = Vec2(0.3, -0.2);
  d.x2 = Vec2(4.3, 2.8);  // length 5
  d.law = StrutLaw(2e5, 100);  // s_p = 5e-4
  d.nodeMass = 0.7;
  d.finite = finite;
  return d;
}

// Displacements that shorten the strut by the strain s along it, plus a rigid
// rotation phi (finite) and a translation.
ElemVec shortened(double s, double phi) {
  const Vec2 x1(0.3, -0.2), x2(4.3, 2.8);
  const Vec2 c = 0.5 * (x1 + x2);
  const Eigen::Rotation2Dd r(phi);
  ElemVec d = ElemVec::Zero();
  const Vec2 y1 = c + (1 - s) * (r * (x1 - c)) + Vec2(0.1, -0.05);
  const Vec2 y2 = c + (1 - s) * (r * (x2 - c)) + Vec2(0.1, -0.05);
  d.segment<2>(0) = y1 - x1;
  d.segment<2>(3) = y2 - x2;
  d(2) = 0.3;  // rotations: the strut ignores them
  d(5) = -0.2;
  return d;
}

TEST(InfillStrut, TangentMatchesFiniteDifferences) {
  std::mt19937 gen(7);
  for (bool finite : {false, true})
    for (double s : {2e-4, 1.5e-3, 4.5e-3})  // elastic, softening, residual
      for (Scheme scheme : {Scheme::Static, Scheme::MidPoint}) {
        InfillStrut strut(strutData(finite));
        StepRule rule;
        rule.scheme = scheme;
        rule.alpha = scheme == Scheme::MidPoint ? 0.1 : 0;
        if (scheme == Scheme::MidPoint) {
          rule.h = 0.01;
          rule.ca = 2 / rule.h / rule.h;
          rule.av = -2 / rule.h;
        }
        ElementKinematics kin;
        kin.d = shortened(s, finite ? 0.3 : 0.0) + test::randomVec(gen, 1e-6);
        kin.dn = shortened(0.8 * s, finite ? 0.25 : 0.0);
        kin.vn = test::randomVec(gen, 0.1);
        kin.an = test::randomVec(gen, 0.1);
        ElemVec r;
        ElemMat k;
        ASSERT_TRUE(strut.evaluate(kin, rule, true, r, k).ok);
        const ElemMat fd = test::centralDifferenceTangent(strut, kin, rule, 1e-8);
        EXPECT_LT((k - fd).cwiseAbs().maxCoeff(), 1e-5 * std::max(1.0, k.cwiseAbs().maxCoeff()))
            << "finite " << finite << " s " << s << " scheme " << static_cast<int>(scheme)
            << "\nK\n" << k << "\nFD\n" << fd;
        for (int i : {2, 5}) EXPECT_EQ(r(i), 0.0);  // no moment
      }
}

TEST(InfillStrut, GeometricallyExactUnderARigidRotation) {
  InfillStrut strut(strutData(true));
  ElementKinematics kin;
  kin.d = shortened(0, 1.2);
  kin.dn = kin.d;
  kin.vn.setZero();
  kin.an.setZero();
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(strut.evaluate(kin, StepRule{}, false, r, k).ok);
  EXPECT_LT(r.norm(), 1e-9);
  // Shortened by 2e-4 and turned: the force along the turned chord, N = K eps.
  kin.d = shortened(2e-4, 1.2);
  ASSERT_TRUE(strut.evaluate(kin, StepRule{}, false, r, k).ok);
  const double eps = (std::pow(1 - 2e-4, 2) - 1) / 2;
  EXPECT_NEAR(strut.sectionForces().N, 2e5 * eps, 1e-9);
  const Vec2 chord = Eigen::Rotation2Dd(1.2) * Vec2(4, 3) * (1 - 2e-4);
  const Vec2 f2 = r.segment<2>(3);
  EXPECT_NEAR(f2.normalized().dot(chord.normalized()), -1.0, 1e-12);  // pulls node 2 in
}

TEST(InfillStrut, MidPointConservesTheEnergyOfAnElasticStrut) {
  InfillStrut strut(strutData(true));
  StepRule rule;
  rule.scheme = Scheme::MidPoint;
  ElementKinematics kin;
  kin.dn = shortened(1e-4, 0.2);
  kin.d = shortened(3e-4, 0.5);
  kin.vn.setZero();
  kin.an.setZero();
  ElemVec r;
  ElemMat k;
  ElementKinematics start = kin;
  start.d = kin.dn;
  ASSERT_TRUE(strut.evaluate(start, StepRule{}, false, r, k).ok);
  const double w0 = strut.strainEnergy();
  ASSERT_TRUE(strut.evaluate(kin, StepRule{}, false, r, k).ok);
  const double w1 = strut.strainEnergy();
  ASSERT_GT(w1, 2 * w0);
  ASSERT_TRUE(strut.evaluate(kin, rule, false, r, k).ok);  // no inertia (ca = 0)
  EXPECT_NEAR(r.dot(kin.d - kin.dn), w1 - w0, 1e-12 * w1);
}

TEST(InfillStrut, MassAndWeightAtItsNodes) {
  InfillStrut strut(strutData(false));
  const ElemMat m = strut.mass();
  EXPECT_DOUBLE_EQ(m(0, 0), 0.7);
  EXPECT_DOUBLE_EQ(m(4, 4), 0.7);
  EXPECT_DOUBLE_EQ(m(2, 2), 0.0);
  const ElemVec g = strut.bodyLoad(Vec2(0, -9.81));
  EXPECT_DOUBLE_EQ(g(1), -0.7 * 9.81);
  EXPECT_DOUBLE_EQ(g(4), -0.7 * 9.81);
  EXPECT_FALSE(strut.holdsRotation(0));
  EXPECT_TRUE(isBrace(strut));
}

}  // namespace
}  // namespace c2d
