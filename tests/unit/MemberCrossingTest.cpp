// The crossing check (core/contact/MemberCrossing): members that cross are
// reported with the point and the nearest nodes, members that only touch are
// not, and tips pressed together are not through each other.
#include <gtest/gtest.h>

#include "core/contact/MemberCrossing.h"
#include "tests/unit/ContactTestSupport.h"

namespace c2d {
namespace {

using test::newRod;
using test::rod;

TEST(MemberCrossing, ReportsCrossingMembersOnly) {
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 50.0, 1.0, 1e-4);
  newRod(m, Vec2(0, 0), Vec2(2, 0), 2);           // elements 0, 1
  newRod(m, Vec2(1.6, -0.5), Vec2(1.6, 0.7), 1);  // element 2 crosses element 1
  newRod(m, Vec2(0.2, 0.1), Vec2(0.8, 0.1), 1);   // element 3: parallel, above element 0
  newRod(m, Vec2(2, 0), Vec2(2.5, 0.0), 1);       // element 4 touches element 1's end
  State s;
  s.resize(m.numNodes());
  auto crossings = findCrossings(m, s);
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_EQ(crossings[0].first, 1);
  EXPECT_EQ(crossings[0].second, 2);
  // Where: at (1.6, 0), 0.4 m from element 1's node at (2, 0) and 0.5 m from
  // element 2's node at (1.6, -0.5).
  EXPECT_NEAR(crossings[0].point.x(), 1.6, 1e-14);
  EXPECT_NEAR(crossings[0].point.y(), 0.0, 1e-14);
  EXPECT_EQ(crossings[0].nearNode[0], 2);
  EXPECT_NEAR(crossings[0].fromNode[0], 0.4, 1e-14);
  EXPECT_EQ(crossings[0].nearNode[1], 3);
  EXPECT_NEAR(crossings[0].fromNode[1], 0.5, 1e-14);
  // Move element 3 down through element 0: now it crosses too.
  s.u(3 * 5 + 1) = -0.2;
  crossings = findCrossings(m, s);
  ASSERT_EQ(crossings.size(), 2u);
  EXPECT_EQ(crossings[0].first, 0);
  EXPECT_EQ(crossings[0].second, 3);
}

TEST(MemberCrossing, TipsPressedTogetherDoNotCross) {
  // Section radius sqrt(3 I / A) = 0.0173, so tips within 5 % of 0.0346 m
  // (1.7 mm) of the crossing are pressed together, not through each other.
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 50.0, 1.0, 1e-4);
  newRod(m, Vec2(3, 0), Vec2(4, 0), 1);                   // element 0
  const int q = newRod(m, Vec2(3.001, 0.5), Vec2(3.0005, -0.0005), 1);  // its tip 0.5 mm under
  State s;
  s.resize(m.numNodes());
  EXPECT_TRUE(findCrossings(m, s).empty());
  s.u(3 * (q + 1) + 1) = -0.0095;  // the tip 10 mm under: through
  ASSERT_EQ(findCrossings(m, s).size(), 1u);
}

}  // namespace
}  // namespace c2d
