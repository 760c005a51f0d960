// The convergence test and the cycle detection of the Newton driver.
#include <gtest/gtest.h>

#include <cmath>

#include "solvers/ConvergenceTest.h"

namespace c2d {
namespace {

ConvergenceTest::Figures figures(int iteration, double energy, double residual) {
  ConvergenceTest::Figures f;
  f.iteration = iteration;
  f.energy = energy;
  f.energy0 = 1.0;
  f.previousEnergy = 1e6 * energy;  // falling fast: not stagnated
  f.residual = residual;
  f.residual0 = 100.0;
  f.largestResidual = residual;
  f.roundoff = 1e-12;
  f.largestCorrection = 1.0;
  f.positions = 1.0;
  return f;
}

TEST(ConvergenceTest, EnergyTestAsFeap) {
  ConvergenceTest t;
  EXPECT_FALSE(t.converged(figures(2, 1e-12, 1.0)));
  EXPECT_TRUE(t.converged(figures(2, 1e-17, 1.0)));
  t.energyTol = 1e-10;
  EXPECT_TRUE(t.converged(figures(2, 1e-12, 1.0)));
}

TEST(ConvergenceTest, ResidualToleranceOnlyWhenSet) {
  ConvergenceTest t;
  EXPECT_FALSE(t.converged(figures(3, 1e-12, 1e-5)));  // ||R|| = 1e-7 of the first
  t.residualTol = 1e-6;
  EXPECT_TRUE(t.converged(figures(3, 1e-12, 1e-5)));
  EXPECT_FALSE(t.converged(figures(3, 1e-12, 1e-3)));
}

TEST(ConvergenceTest, AbsoluteEnergyValue) {
  ConvergenceTest t;
  t.energyZero = 1e-8;
  EXPECT_TRUE(t.converged(figures(2, 1e-9, 1.0)));
  EXPECT_FALSE(t.converged(figures(2, 1e-7, 1.0)));
}

TEST(ConvergenceTest, CyclesOfPeriodOneAndTwo) {
  const double two[] = {5.0, 4.1e2, 1.03e3, 4.1e2, 1.03e3, 4.1e2};
  EXPECT_TRUE(repeatsWithPeriod(two, 6, 2, 2));
  EXPECT_TRUE(repeatsWithPeriod(two, 6, 2, 3));
  EXPECT_FALSE(repeatsWithPeriod(two, 6, 2, 4));
  EXPECT_FALSE(repeatsWithPeriod(two, 6, 1, 1));
  const double one[] = {1.99e3, 5.19, 3.27e2, 1.03e3, 1.03e3};
  EXPECT_TRUE(repeatsWithPeriod(one, 5, 1, 1));
  EXPECT_FALSE(repeatsWithPeriod(one, 5, 1, 2));
  const double converging[] = {1.0, 1e-3, 1e-7, 1e-15};
  EXPECT_FALSE(repeatsWithPeriod(converging, 4, 1, 1));
  EXPECT_FALSE(repeatsWithPeriod(converging, 4, 2, 2));
  EXPECT_FALSE(repeatsWithPeriod(converging, 1, 1, 1));  // too short
}

TEST(ConvergenceTest, NewtonStopsProgressingOnCyclesUpToPeriodSix) {
  // Residuals of the main example with member contact: a two-cycle that
  // Newton's iterates approach geometrically (seen at 1 % after two periods,
  // at 1e-6 only after eight), and a three-cycle.
  const double two[] = {2.9606e2, 7.0078e1, 5.674, 2.7683, 3.4595, 2.3031, 3.4241, 2.2933, 3.4173};
  EXPECT_TRUE(stopsProgressing(two, 9, 6, 1e-2));
  EXPECT_FALSE(stopsProgressing(two, 9, 6, 1e-6));
  const double three[] = {9.0e2, 41.3, 17.2, 55.0, 41.2, 17.3, 55.1};
  EXPECT_TRUE(stopsProgressing(three, 7, 6, 1e-2));
  EXPECT_FALSE(stopsProgressing(three, 7, 2, 1e-2));
  EXPECT_FALSE(stopsProgressing(three, 6, 6, 1e-2));  // not yet a whole period again
  // Converging, quadratically or slowly (a tenth per iteration): never.
  const double quadratic[] = {3.7e3, 8.1e2, 2.1e2, 1.5e1, 1.3e-1, 4.5e-5};
  EXPECT_FALSE(stopsProgressing(quadratic, 6, 6, 1e-2));
  double slow[12];
  for (int k = 0; k < 12; ++k) slow[k] = std::pow(0.9, k);
  EXPECT_FALSE(stopsProgressing(slow, 12, 6, 1e-2));
}

TEST(ConvergenceTest, AStaticStepsResidualsRunningAwayAreSeen) {
  // An RC cantilever under 50 kN of tension pushed 10 mm at its tip in one
  // step (FINIte): the committed state's residual, then the first
  // correction's, then away.
  const double away[] = {1.6e-9, 285.07, 726.05, 6.7011e4, 4.2082e7};
  EXPECT_FALSE(runsAway(away, 3));  // too short
  EXPECT_TRUE(runsAway(away, 4));   // twice up, 235 times the least
  const double up[] = {1.6e-9, 285.07, 726.05, 2.0e4};
  EXPECT_FALSE(runsAway(up, 4));  // twice up, 70 times the least
  // A step that passes a kink and comes back (residual up once): not away.
  const double back[] = {1e-9, 221.4, 142.7, 2e4, 20.6, 1.1e-4};
  for (std::size_t n = 4; n <= 6; ++n) EXPECT_FALSE(runsAway(back, n)) << n;
  const double quadratic[] = {3.7e3, 8.1e2, 2.1e2, 1.5e1, 1.3e-1, 4.5e-5};
  for (std::size_t n = 4; n <= 6; ++n) EXPECT_FALSE(runsAway(quadratic, n)) << n;
}

}  // namespace
}  // namespace c2d
