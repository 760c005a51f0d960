// The crushing law's peak an impact came back from (core/contact/CrushingLaw.h
// crushingPeak, crushingLoadingPoint) against the unloading branch's energy.
#include <gtest/gtest.h>

#include <cmath>

#include "core/contact/CrushingLaw.h"

namespace c2d {
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

}  // namespace
}  // namespace c2d
