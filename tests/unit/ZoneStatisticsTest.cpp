// The protected zones' statistics over a table of runs
// (macro/studies/ZoneStatistics): counts, shares and Wilson intervals by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "macro/studies/EnsembleTable.h"
#include "macro/studies/ZoneStatistics.h"
#include "tests/unit/EnsembleTestSupport.h"

namespace c2d {
namespace {

using testing::okRun;

// Five runs, zones left (a protected side; the right receives) and wall.
TEST(SiteZones, ZoneCountsAndWilsonByHand) {
  std::vector<EnsembleRun> runs = {
      okRun({{"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 2}, {"hit_wall", 1},
           {"flyrock_count_wall", 0}, {"left95", 1}, {"right95", 10}}),
      okRun({{"mass_left", 0.5}, {"hit_left", 1}, {"mass_wall", 0}, {"hit_wall", 0},
           {"flyrock_count_wall", 2}, {"left95", 3}, {"right95", 12}}),
      okRun({{"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 0}, {"hit_wall", 0},
           {"left95", 0.5}, {"right95", 11}}),
      okRun({{"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 0}, {"hit_wall", 0},
           {"left95", 0}, {"right95", 9}}),
      okRun({{"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 1}, {"hit_wall", 1},
           {"left95", 0}, {"right95", 13}, {"risk_level", 0.05}, {"risk_confidence", 0.9}}),
  };
  std::vector<const EnsembleRun*> ptr;
  for (const EnsembleRun& r : runs) ptr.push_back(&r);
  const std::vector<std::string> zones = {"left", "wall"};
  const ProtectedStats g = protectedStatistics(zones, ptr);
  EXPECT_EQ(g.runs, 5);
  EXPECT_EQ(g.anyHits, 3);
  EXPECT_DOUBLE_EQ(g.pAny, 0.6);
  EXPECT_NEAR(g.meanMass, 3.5 / 5, 1e-15);
  EXPECT_DOUBLE_EQ(g.medianReach95, 0.5);  // left95 only: the right side receives
  EXPECT_DOUBLE_EQ(g.level, 0.05);
  EXPECT_DOUBLE_EQ(g.confidence, 0.9);
  ASSERT_EQ(g.zones.size(), 2u);
  const ZoneStats& wall = g.zones[1];
  EXPECT_EQ(wall.hits, 2);
  EXPECT_DOUBLE_EQ(wall.p, 0.4);
  // Wilson 2/5: (0.4 + 0.38416 -+ 1.96 sqrt(0.048 + 0.038416)) / 1.76832.
  EXPECT_NEAR(wall.lo, 0.117618, 1e-6);
  EXPECT_NEAR(wall.hi, 0.769280, 1e-6);
  EXPECT_DOUBLE_EQ(wall.massMedian, 0);
  EXPECT_DOUBLE_EQ(wall.massMax, 2);
  EXPECT_EQ(wall.flyrockRuns, 1);
  EXPECT_DOUBLE_EQ(wall.pFlyrock, 0.2);
  EXPECT_FALSE(wall.shown);
  const ZoneStats& left = g.zones[0];
  EXPECT_EQ(left.hits, 1);
  EXPECT_NEAR(left.lo, 0.036223, 1e-6);  // Wilson 1/5
  EXPECT_NEAR(left.hi, 0.624472, 1e-6);
  EXPECT_TRUE(hitsProtected(runs[1], zones));
  EXPECT_FALSE(hitsProtected(runs[2], zones));
  EXPECT_DOUBLE_EQ(protectedReach95(runs[1], zones), 3);
  EXPECT_DOUBLE_EQ(protectedReach95(runs[1], {"left", "right"}), 12);
}

}  // namespace
}  // namespace c2d
