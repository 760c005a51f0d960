// The member contact's broad phase (core/contact/ContactGrid): the grid's query
// against brute force, before and after the boxes grow.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/contact/ContactGrid.h"

namespace c2d {
namespace {

TEST(ContactGrid, QueryFindsExactlyTheOverlappingBoxes) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> pos(-50, 50), size(0, 2), big(0, 60);
  std::vector<Box> boxes;
  for (int i = 0; i < 400; ++i) {
    const double x = pos(gen), y = pos(gen);
    const double w = i % 50 == 0 ? big(gen) : size(gen), hgt = size(gen);
    boxes.push_back({x, y, x + w, y + hgt});
  }
  ContactGrid grid;
  for (int round = 0; round < 2; ++round) {
    grid.build(boxes, 1e-3);
    for (int q = 0; q < 300; ++q) {
      const double x = pos(gen), y = pos(gen);
      const Box b{x, y, x + size(gen) * 3, y + size(gen)};
      std::vector<int> found, expected;
      grid.query(b, [&](int i) { found.push_back(i); });
      for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
        if (boxes[i].overlaps(b)) expected.push_back(i);
      std::sort(found.begin(), found.end());
      EXPECT_EQ(found, expected);
    }
    for (Box& b : boxes) b = b.inflated(0.5);
  }
}

}  // namespace
}  // namespace c2d
