// Ground contact with restitution e < 1 (core/contact/GroundContact): the crushing law's
// mid-point force does the law's work over the step (what is stored plus what
// crushing dissipates), its tangent is the derivative of the force, the law
// reduces to the elastic one as e -> 1, and the loading point follows the
// largest penetration and is forgotten off the ground.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/contact/GroundContact.h"
#include "solvers/TimeIntegrator.h"

namespace c2d {
namespace {

struct Case {
  double q, p0, p1;  // loading point, penetrations at t_n and t_n+1
};

// Steps that stay on one branch, cross the set, the loading point, both, enter
// and leave the ground, in both directions, and hardly move.
std::vector<Case> cases(double q) {
  std::vector<Case> out;
  const double set = q * (1 - 0.25), pts[] = {-0.4 * q, 0.2 * q, 0.8 * q, 0.95 * q, q, 1.3 * q};
  for (double a : pts)
    for (double b : pts)
      if (a <= q) out.push_back({q, a, b});
  out.push_back({q, set - 1e-9, set + 1e-9});
  out.push_back({q, q - 1e-9, q + 1e-9});
  out.push_back({q, 0.9 * q, 0.9 * q + 1e-12});
  return out;
}

TEST(GroundCrushing, MidPointForceDoesTheWorkStoredPlusDissipated) {
  const Ground g{0.0, 1e4, 0.0, 0.0, 0.5};
  const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  for (const Case& c : cases(2e-3)) {
    const double y0 = -c.p0, y1 = -c.p1;
    const ContactForce f = groundContact(g, c.q, y0, y1, rule);
    // The force acts upward: its work on the penetration's increment.
    const double work = f.force * (c.p1 - c.p0);
    const double stored = contactEnergy(g, c.q, y1) - contactEnergy(g, c.q, y0);
    const double dissipated = groundDissipation(g, c.q, 0, 0, y0, 0, y1, rule);
    EXPECT_GE(dissipated, 0.0);
    EXPECT_NEAR(work, stored + dissipated, 1e-12 * g.k * c.q * c.q)
        << c.q << " " << c.p0 << " -> " << c.p1;
    EXPECT_GE(f.force, 0.0);  // never pulls
    EXPECT_EQ(f.normal, f.force);
  }
}

TEST(GroundCrushing, TangentIsTheDerivativeOfTheForce) {
  const Ground g{0.0, 1e4, 0.0, 0.0, 0.5};
  const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  for (const Case& c : cases(2e-3)) {
    if (std::abs(c.p1 - c.p0) < 1e-6) continue;  // the difference quotient would straddle a kink
    const double y0 = -c.p0, y1 = -c.p1, h = 1e-9;
    const double fd = -(groundContact(g, c.q, y0, y1 + h, rule).force -
                        groundContact(g, c.q, y0, y1 - h, rule).force) /
                      (2 * h);
    EXPECT_NEAR(groundContact(g, c.q, y0, y1, rule).tangent, fd, 1e-5 * g.k)
        << c.q << " " << c.p0 << " -> " << c.p1;
  }
}

TEST(GroundCrushing, TendsToTheElasticLaw) {
  const Ground elastic{0.0, 1e4, 0.0, 0.0, 1.0}, nearly{0.0, 1e4, 0.0, 0.0, 1 - 1e-12};
  const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  for (const Case& c : cases(2e-3)) {
    const ContactForce a = groundContact(elastic, c.q, -c.p0, -c.p1, rule),
                       b = groundContact(nearly, c.q, -c.p0, -c.p1, rule);
    EXPECT_NEAR(a.force, b.force, 1e-8 * elastic.k * c.q);
    EXPECT_NEAR(a.tangent, b.tangent, 1e-6 * elastic.k);
  }
}

TEST(GroundCrushing, StaticLawUnloadsStiffAndStopsAtTheSet) {
  const Ground g{0.0, 1e4, 0.0, 0.0, 0.5};
  const StepRule rule = TimeIntegrator::statics().rule(1);
  const double q = 2e-3, set = q * (1 - 0.25);
  EXPECT_NEAR(groundContact(g, q, -q, -1.5 * q, rule).force, 1.5 * g.k * q, 1e-9);  // loading
  EXPECT_NEAR(groundContact(g, q, -q, -0.9 * q, rule).force, g.k * q - 4 * g.k * 0.1 * q, 1e-9);
  EXPECT_NEAR(groundContact(g, q, -q, -0.9 * q, rule).tangent, 4 * g.k, 1e-9);
  EXPECT_EQ(groundContact(g, q, -q, -0.99 * set, rule).force, 0.0);
}

TEST(GroundCrushing, LoadingPointFollowsTheLargestPenetrationAndIsForgottenAboveTheGround) {
  const Ground g{0.0, 1e4, 0.0, 0.0, 0.5};
  EXPECT_EQ(loadingPoint(g, 0.0, 0.0, -1e-3, 0.0, 0.0), 1e-3);
  EXPECT_EQ(loadingPoint(g, 2e-3, 0.0, -1e-3, 0.0, 0.0), 2e-3);
  EXPECT_EQ(loadingPoint(g, 2e-3, 0.0, 1e-6, 0.0, 0.0), 0.0);
  // Still moving down, or massless: the step's end.
  EXPECT_EQ(loadingPoint(g, 0.0, 2.0, -1e-3, -1.0, -0.5), 1e-3);
  EXPECT_EQ(loadingPoint(g, 0.0, 0.0, -1e-3, -1.0, 0.5), 1e-3);
  // Stored energy: the unloading branch's f^2 e^2 / (2 k).
  const double q = 2e-3, p = 0.9 * q, f = g.k * q - 4 * g.k * (q - p);
  EXPECT_NEAR(contactEnergy(g, q, -p), f * f * 0.25 / (2 * g.k), 1e-15);
}

}  // namespace
}  // namespace c2d
