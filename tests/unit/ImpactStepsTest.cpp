// What an impact's step needs (solvers/ImpactSteps.h): a contact that touched
// and turned in one step is taken again; a loading one or one at rest is not.
#include <gtest/gtest.h>

#include <cmath>

#include "solvers/ImpactSteps.h"
#include "solvers/TimeIntegrator.h"

namespace c2d {
namespace {

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
}  // namespace c2d
