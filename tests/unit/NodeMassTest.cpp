// The mass a node's translation moves (core/NodeMass.h): half a member's mass
// at each end, masters carrying their slaves, held nodes not moving.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "core/NodeMass.h"
#include "tests/unit/ContactTestSupport.h"

namespace c2d::test {
namespace {

TEST(NodeMass, HalfAMembersMassAtEachEndMastersCarryTheirSlavesHeldNodesDoNotMove) {
  Model m;
  m.materials()[1] = rod(1, 1e6, 1e6, 1e3, 3.0, 1e-3);  // 3 t/m
  const int a = newRod(m, Vec2(0, 0), Vec2(2, 0), 1);   // 6 t
  const int b = newRod(m, Vec2(2, 0), Vec2(3, 0), 1);   // 3 t, its first node at a + 1's place
  m.joints().push_back({a + 1, b, JointForm::Shared});
  m.bound(b + 1) = {1, 1, 0};
  const std::vector<double> mass = translationalMasses(m);
  EXPECT_NEAR(mass[a], 3.0, 1e-12);
  EXPECT_NEAR(mass[a + 1], 3.0 + 1.5, 1e-12);
  EXPECT_EQ(mass[b], 0.0);
  EXPECT_EQ(mass[b + 1], std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace c2d::test
