// The jitter of an ensemble's nodes (macro/studies/Jitter): coincident nodes
// move together, every offset within the radius, uniform over the disc.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/Model.h"
#include "elements/ElementFactory.h"
#include "macro/draws/Jitter.h"
#include "tests/unit/EnsembleTestSupport.h"

namespace c2d {
namespace {

using testing::ksCritical;
using testing::ksStatistic;

TEST(EnsembleDraws, JitterMovesCoincidentNodesTogether) {
  Model m;
  MaterialSet mat;
  mat.number = 1;
  mat.elementType = "FRAMe";
  mat.resEA = mat.resGA = 1e6;
  mat.resEI = 1e4;
  m.materials()[1] = mat;
  for (const Vec2& x : {Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(2, 0), Vec2(1, 1e-12)})
    m.addNode(x);
  std::vector<Vec2> before;
  for (int n = 0; n < m.numNodes(); ++n) before.push_back(m.coord(n));
  jitterNodes(m, JitterSpec{1e-3, 0}, 5, 2);
  for (int n = 0; n < m.numNodes(); ++n) {
    EXPECT_LE((m.coord(n) - before[n]).norm(), 1e-3 + 1e-15);
    EXPECT_GT((m.coord(n) - before[n]).norm(), 0);
  }
  // Nodes 2, 3 and 5 (0-based 1, 2, 4) lie together: one offset.
  EXPECT_EQ(m.coord(1), m.coord(2));
  EXPECT_EQ((m.coord(4) - before[4]), (m.coord(1) - before[1]));
  EXPECT_NE((m.coord(0) - before[0]), (m.coord(1) - before[1]));
  // Uniform over the disc: over many samples the offsets' radii r have
  // P(r <= rho) = (rho/dx)^2.
  std::vector<double> r;
  for (int k = 1; k <= 1000; ++k) {
    Model one;
    one.addNode(Vec2(0, 0));
    jitterNodes(one, JitterSpec{1, 0}, 1, k);
    r.push_back(one.coord(0).norm());
  }
  EXPECT_LT(ksStatistic(r, [](double v) { return std::min(1.0, v * v); }), ksCritical(1000));
}

}  // namespace
}  // namespace c2d
