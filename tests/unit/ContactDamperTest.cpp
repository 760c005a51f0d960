// The contact dashpot's coefficient (core/contact/ContactDamper.h): a share of
// the critical damping of the mass the contact moves.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/contact/ContactDamper.h"

namespace c2d {
namespace {

TEST(ContactDamper, CriticalDampingOfTheMassTheContactMoves) {
  EXPECT_NEAR(damperCoefficient(0.5, 1e5, 4.0), 2 * 0.5 * std::sqrt(4e5), 1e-9);
  EXPECT_EQ(damperCoefficient(0.5, 1e5, std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_EQ(damperCoefficient(0.0, 1e5, 4.0), 0.0);
}

}  // namespace
}  // namespace c2d
