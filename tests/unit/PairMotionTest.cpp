// A member pair's reduced mass (core/contact/PairMotion.h): a node and the point
// of a segment it is over.
#include <gtest/gtest.h>

#include <vector>

#include "core/contact/PairMotion.h"

namespace c2d {
namespace {

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

}  // namespace
}  // namespace c2d
