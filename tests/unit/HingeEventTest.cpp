// Hinge events of the static driver (Analysis) on the V2 cantilever of
// verification.md: tip rotation imposed, the step that takes the moment past Mu
// is cut where it reaches Mu, exactly one hinge opens under the uniform moment
// (or in the weakened element), and the rest of the step converges on the
// softening branch.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>

#include "tests/unit/V2Material.h"
#include "core/Hinge.h"
#include "core/Model.h"
#include "elements/InelasticFrame.h"
#include "solvers/Analysis.h"

namespace c2d {
namespace {

using namespace test::v2;
constexpr double kL = 2.5;

MaterialSet v2Set(int number, double Mu) { return material(number, 1.25e6, Kinematics::Small, Mu); }

// n elements along x, clamped at node 0, tip rotation theta = thetaMax * t;
// element `weak` (or none: -1) has the ultimate moment muWeak.
Model cantilever(int n, double thetaMax, int weak = -1, double muWeak = kMu) {
  Model m;
  m.materials()[1] = v2Set(1, kMu);
  m.materials()[2] = v2Set(2, muWeak);
  m.resizeNodes(n + 1);
  for (int i = 0; i <= n; ++i) m.setCoord(i, Vec2(kL * i / n, 0));
  for (int e = 0; e < n; ++e)
    m.setElement(e, std::make_unique<InelasticFrame>(m.materials()[e == weak ? 2 : 1], std::array{e, e + 1},
                                                     m.coord(e), m.coord(e + 1)));
  m.bound(0) = {1, 1, 1};
  m.bound(n) = {0, 0, 1};
  m.disp(n) = {0, 0, thetaMax};
  return m;
}

// One TIME + Newton loop; the converged step is left uncommitted (as TANG leaves it).
int solveStep(Analysis& an) {
  if (!an.advance()) return -1;
  IterationInfo info;
  for (int i = 1; i <= 10; ++i) {
    if (!an.iterate(false, true, info)) return -1;
    if (info.converged) return i;
  }
  return -1;
}

struct Hinges {
  int count = 0, element = -1;
  HingeInfo info;
};

Hinges activeHinges(const Model& m) {
  Hinges h;
  for (int e = 0; e < m.numElements(); ++e) {
    const HingeInfo i = dynamic_cast<const HingeCarrier&>(m.element(e)).hinge();
    if (!i.active) continue;
    ++h.count;
    h.element = e;
    h.info = i;
  }
  return h;
}

// Tip moment: the reaction at the prescribed tip rotation.
double tipMoment(Analysis& an, int n) {
  Eigen::VectorXd r;
  EXPECT_TRUE(an.reactions(r));
  return r[3 * n + 2];
}

// theta(M) past the peak: L (kp + M/EI) + (M - Mu)/Ks, kp the plastic curvature at Mu.
double postPeakMoment(double theta, double mu) {
  const double kp = kappaOf(mu) - mu / kEI;
  return (theta - kL * kp + mu / kKs) / (kL / kEI + 1 / kKs);
}

TEST(HingeEvent, UniformMomentOpensExactlyOneHingeAtTheLocatedLevel) {
  for (int n : {5, 10, 20}) {
    const double thetaF = kL * (kappaOf(kMu) - kMu / kEI) + kMu / -kKs;  // M = 0
    Model m = cantilever(n, thetaF);
    Analysis an(m);
    an.setLoadFunction(1, ProportionalLoad::ramp());
    double activationTheta = -1;
    an.onHingeActivated = [&](int, const HingeInfo&) { activationTheta = an.state().u[3 * n + 2]; };
    an.setDt(0.1);
    for (int s = 1; s <= 10; ++s) {
      // Two iterations per step (the predictor and one correction); the last
      // step holds the event and complete failure.
      const int its = solveStep(an);
      ASSERT_GT(its, 0) << "n = " << n << ", step " << s;
      if (s < 10) {
        EXPECT_EQ(its, 2) << "n = " << n << ", step " << s;
      }
      const double theta = thetaF * s / 10, M = tipMoment(an, n);
      const Hinges h = activeHinges(m);
      if (theta < kL * kappaOf(kMu)) {
        EXPECT_EQ(h.count, 0);
        EXPECT_NEAR(kL * kappaOf(M), theta, 1e-12);
      } else {
        ASSERT_EQ(h.count, 1) << "n = " << n;
        EXPECT_EQ(h.element, 0);  // ties to round-off go to the lowest element number
        EXPECT_NEAR(M, std::max(0.0, postPeakMoment(theta, kMu)), 1e-6) << "step " << s;
        EXPECT_NEAR(h.info.moment, M, 1e-6);
      }
    }
    EXPECT_NEAR(activationTheta, 0.0835350, 5e-8);
    EXPECT_NEAR(activationTheta, kL * kappaOf(kMu), 1e-9);
    // At theta_f the jump is Mu/|Ks| (the moment is zero to the location band).
    EXPECT_NEAR(activeHinges(m).info.jump, kMu / -kKs, 1e-9);
    EXPECT_NEAR(tipMoment(an, n), 0, 1e-6);
  }
}

TEST(HingeEvent, WeakenedElementCarriesTheHinge) {
  const int n = 10, weak = 6;
  const double muW = 270, thetaMax = 0.05;
  Model m = cantilever(n, thetaMax, weak, muW);
  Analysis an(m);
  an.setLoadFunction(1, ProportionalLoad::ramp());
  an.setDt(0.05);
  for (int s = 1; s <= 20; ++s) {
    const double theta = thetaMax * s / 20;
    // Two iterations per step, twice that in the step of the event: two up to
    // the converged end of the step that detects it, two for the rest after
    // the hinge opened at the located level.
    const int its = solveStep(an);
    const bool event = theta > kL * kappaOf(muW) && theta - thetaMax / 20 < kL * kappaOf(muW);
    EXPECT_EQ(its, event ? 4 : 2) << "step " << s;
    if (theta > kL * kappaOf(muW)) {
      const Hinges h = activeHinges(m);
      ASSERT_EQ(h.count, 1);
      EXPECT_EQ(h.element, weak);
      EXPECT_NEAR(tipMoment(an, n), std::max(0.0, postPeakMoment(theta, muW)), 1e-6);
    }
  }
}

// A dynamic step (mid-point scheme) in which the weakened element reaches Mu:
// the event is located in the band and costs few iterations. Each trial of the
// location starts from the chord between the bracket's converged ends
// (HingeEvents::solveBetween), a correction or two from the solution; from the
// committed state every trial took a whole solve.
TEST(HingeEvent, DynamicEventTrialsStartFromTheBracket) {
  const int n = 10, weak = 6;
  const double muW = 270, thetaMax = 0.05;
  Model m = cantilever(n, thetaMax, weak, muW);
  for (int e = 0; e < n; ++e) {
    MaterialSet mat = m.materials()[e == weak ? 2 : 1];
    mat.density = 2.5;
    mat.A = 0.12;
    mat.I = 1.6e-3;
    m.setElement(
        e, std::make_unique<InelasticFrame>(mat, std::array{e, e + 1}, m.coord(e), m.coord(e + 1)));
  }
  Analysis an(m);
  an.setLoadFunction(1, ProportionalLoad::ramp());
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setDt(0.05);
  double demand = -1;
  an.onHingeActivated = [&](int, const HingeInfo& h) { demand = std::abs(h.moment) / muW; };
  int eventIterations = -1;
  for (int s = 1; s <= 20 && demand < 0; ++s) {
    const int before = an.totalIterations();
    ASSERT_TRUE(an.advance());
    IterationInfo info;
    // Up to 35 iterations where Newton's method cycles on the hardening kinks.
    for (int i = 0; i < 60 && !info.converged; ++i) ASSERT_TRUE(an.iterate(false, true, info));
    ASSERT_TRUE(info.converged) << "step " << s;
    if (demand >= 0) eventIterations = an.totalIterations() - before;
  }
  ASSERT_GE(demand, 1.0);
  EXPECT_LE(demand, 1.0 + 1e-12);
  const Hinges h = activeHinges(m);
  ASSERT_EQ(h.count, 1);
  EXPECT_EQ(h.element, weak);
  // 48 iterations in the step of the event (73 with every trial from the
  // committed state).
  EXPECT_LE(eventIterations, 55);
}

}  // namespace
}  // namespace c2d
