// The pieces the contact's damping and impact steps are built of: the peak an
// impact came back from (core/contact/CrushingLaw.h crushingPeak), the mass a node's
// translation moves (core/NodeMass.h), a member pair's reduced mass
// (core/contact/PairMotion.h), the dashpot's coefficient (core/contact/ContactDamper.h) and
// what an impact's step needs (solvers/ImpactSteps.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ContactTestSupport.h"
#include "core/contact/ContactDamper.h"
#include "core/contact/CrushingLaw.h"
#include "core/NodeMass.h"
#include "core/contact/PairMotion.h"
#include "solvers/ImpactSteps.h"

namespace c2d::test {
namespace {

TEST(CrushingPeak, TheUnloadingBranchsEnergyGivesThePeakBack) {
  // From the peak q the branch gives back e^2 k q^2 / 2: at p on the branch
  // m r^2 / 2 + (k / e^2)(p - (1 - e^2) q)^2 / 2 is that.
  const double k = 1e5, e = 0.5, m = 2, q = 0.1, a = 1 - e * e;
  for (double p : {0.099, 0.09, 0.08, 0.0751}) {
    const double r = -std::sqrt((e * e * k * q * q - k / (e * e) * std::pow(p - a * q, 2)) / m);
    EXPECT_NEAR(crushingPeak(k, e, m, p, r), q, 1e-12 * q) << p;
  }
  // In the set (p <= (1 - e^2) q) the mass has left the surface with e q sqrt(k/m).
  for (double p : {0.07, 0.03})
    EXPECT_NEAR(crushingPeak(k, e, m, p, -e * q * std::sqrt(k / m)), q, 1e-12 * q) << p;
  // No mass, not unloading, or elastic: the step's end.
  EXPECT_EQ(crushingPeak(k, e, 0.0, 0.05, -1.0), 0.05);
  EXPECT_EQ(crushingPeak(k, e, m, 0.05, 1.0), 0.05);
  EXPECT_EQ(crushingPeak(k, 1.0, m, 0.05, -1.0), 0.05);
  // The loading point takes it only where the contact turned in the step.
  EXPECT_EQ(crushingLoadingPoint(k, e, 0.0, m, 0.09, -1.0, -2.0), 0.09);
  const double r = -std::sqrt((e * e * k * q * q - k / (e * e) * std::pow(0.09 - a * q, 2)) / m);
  EXPECT_NEAR(crushingLoadingPoint(k, e, 0.0, m, 0.09, 3.0, r), q, 1e-12 * q);
}

TEST(NodeMass, HalfAMembersMassAtEachEndMastersCarryTheirSlavesHeldNodesDoNotMove) {
  Model m;
  m.materials()[1] = rod(1, 1e6, 1e6, 1e3, 3.0, 1e-3);  // 3 t/m
  const int a = newRod(m, Vec2(0, 0), Vec2(2, 0), 1);   // 6 t
  const int b = newRod(m, Vec2(2, 0), Vec2(3, 0), 1);   // 3 t, its first node at a + 1's place
  m.joints().push_back({a + 1, b, JointForm::Shared});
  m.bound(b + 1) = {1, 1, 0};
  const std::vector<double> mass = translationalMasses(m);
  EXPECT_NEAR(mass[a], 3.0, 1e-12);
  EXPECT_NEAR(mass[a + 1], 3.0 + 1.5, 1e-12);
  EXPECT_EQ(mass[b], 0.0);
  EXPECT_EQ(mass[b + 1], std::numeric_limits<double>::infinity());
}

TEST(PairMotion, ReducedMassOfANodeAndASegmentsPoint) {
  ContactPair pair;
  pair.node = 0;
  pair.a = 1;
  pair.b = 2;
  const std::vector<double> masses{2.0, 4.0, 8.0};
  // The node over a quarter of the segment: 1/m = 1/2 + 0.75^2/4 + 0.25^2/8.
  const PairPositions q{Vec2(1, 0.3), Vec2(0, 0), Vec2(4, 0)};
  EXPECT_NEAR(pairMass(masses, pair, q), 1 / (0.5 + 0.5625 / 4 + 0.0625 / 8), 1e-12);
  // Beyond an end: clamped to it.
  const PairPositions beyond{Vec2(-1, 0.3), Vec2(0, 0), Vec2(4, 0)};
  EXPECT_NEAR(pairMass(masses, pair, beyond), 1 / (0.5 + 0.25), 1e-12);
  EXPECT_EQ(pairMass({0.0, 4.0, 8.0}, pair, q), 0.0);
}

TEST(ContactDamper, CriticalDampingOfTheMassTheContactMoves) {
  EXPECT_NEAR(damperCoefficient(0.5, 1e5, 4.0), 2 * 0.5 * std::sqrt(4e5), 1e-9);
  EXPECT_EQ(damperCoefficient(0.5, 1e5, std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_EQ(damperCoefficient(0.0, 1e5, 4.0), 0.0);
}

TEST(ImpactSteps, AContactThatTouchedAndTurnedInOneStepIsTakenAgain) {
  StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  ContactMotion c;
  c.k = 1e5;
  c.e = 0.3;
  c.m = 10.2;
  // Out at t_n, in and already leaving at t_n+1: no state holds its peak.
  c.p0 = -0.05;
  c.p1 = 0.02;
  c.r0 = 16;
  c.r1 = -3;
  EXPECT_EQ(ImpactSteps::need(c, rule), ImpactSteps::kEvent);
  // In at both ends and still loading: the mid-point law is exact.
  c.p0 = 0.02;
  c.p1 = 0.08;
  c.r0 = 15;
  c.r1 = 8;
  c.q = 0.02;
  EXPECT_EQ(ImpactSteps::need(c, rule), 0.0);
  // A body resting on its contact (its energy within ten times its weight's
  // (m g)^2 / 2k) is no impact.
  c.p0 = c.p1 = c.q = 10.2 * 9.81 / 1e5;
  c.r0 = 1e-3;
  c.r1 = -1e-3;
  c.rest = 0.5 * std::pow(10.2 * 9.81, 2) / 1e5;
  EXPECT_EQ(ImpactSteps::need(c, rule), 0.0);
}

}  // namespace
}  // namespace c2d::test
