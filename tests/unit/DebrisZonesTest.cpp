// The share of a segment in a protected zone (core/DebrisZones), by hand.
#include <gtest/gtest.h>

#include "macro/output/DebrisZones.h"

namespace c2d {
namespace {

TEST(SiteZones, SegmentShareInAZone) {
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(0, 0), Vec2(4, 0), 1, 3, -kUnbounded), 0.5);
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(0, 0), Vec2(4, 0), 1, 3, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(0, 0), Vec2(0, 4), -1, 1, 1), 0.75);  // above y = 1
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(0, 0), Vec2(4, 4), 2, kUnbounded, 3), 0.25);
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(2, 2), Vec2(2, 2), 1, 3, 0), 1.0);  // a point inside
  EXPECT_DOUBLE_EQ(shareInZone(Vec2(5, 2), Vec2(5, 2), 1, 3, 0), 0.0);
}

}  // namespace
}  // namespace c2d
