// The run's watch on members past their capacity (macro/run/CapacityWatch.h):
// the largest |M|/Mu is kept, and a member past Mu by more than the tolerance
// is warned of once, by element and time.
#include <gtest/gtest.h>

#include <sstream>

#include "core/Hinge.h"
#include "macro/run/CapacityWatch.h"

namespace c2d {
namespace {

TEST(CapacityWatch, KeepsTheLargestRatioAndWarnsOncePerElementPastTheTolerance) {
  CapacityWatch w;
  std::ostringstream log;
  w.observe(4, 0.8, 0.1, log);
  w.observe(4, 1 + 0.5 * kCapacityTolerance, 0.2, log);  // within the band: no warning
  EXPECT_EQ(log.str(), "");
  EXPECT_DOUBLE_EQ(w.maxRatio(), 1 + 0.5 * kCapacityTolerance);

  w.observe(4, 1.004, 0.3, log);
  EXPECT_NE(log.str().find("warning: element 5 carries |M|/Mu = 1.0040 at t = 3.000000e-01"),
            std::string::npos)
      << log.str();
  const std::string once = log.str();
  w.observe(4, 1.01, 0.4, log);  // the same element again: no second line
  EXPECT_EQ(log.str(), once);
  EXPECT_DOUBLE_EQ(w.maxRatio(), 1.01);

  w.observe(11, 1.002, 0.5, log);  // another element
  EXPECT_NE(log.str().find("warning: element 12 "), std::string::npos);
  EXPECT_EQ(w.warned(), 2);

  w.observe(-1, 2.0, 0.6, log);  // no element: kept, not warned
  EXPECT_DOUBLE_EQ(w.maxRatio(), 2.0);
  EXPECT_EQ(w.warned(), 2);
}

TEST(CapacityWatch, ARestartKeepsTheRunsLargestRatio) {
  CapacityWatch w;
  w.setMaxRatio(0.97);
  std::ostringstream log;
  w.observe(0, 0.5, 1.0, log);
  EXPECT_DOUBLE_EQ(w.maxRatio(), 0.97);
}

}  // namespace
}  // namespace c2d
