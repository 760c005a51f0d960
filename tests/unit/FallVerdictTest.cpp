// The verdict of a run against SITE's intended fall (macro/output/FallVerdict), by
// hand for constructed end states.
#include <gtest/gtest.h>

#include <cmath>

#include "macro/output/Debris.h"
#include "macro/output/FallVerdict.h"
#include "elements/ElementFactory.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d {
namespace {

// The eight-storey frame's figures: H = 25.6 m, W = 16.5 m. A rigid body
// tipped about its back edge moves its centroid by (H - W)/2 = 4.55 m; half of
// that, T = 2.275 m, counts (H/20 = 1.28 m is less).
TEST(FallVerdict, ThresholdsByHand) {
  const double h = 25.6, w = 16.5;
  EXPECT_NEAR(fellingThreshold(h, w), 2.275, 1e-12);
  // A building as wide as high: 5 % of its height.
  EXPECT_NEAR(fellingThreshold(10, 12), 0.5, 1e-12);
  using D = FallDirection;
  using V = FallVerdict;
  EXPECT_EQ(fallVerdict(D::Right, 4.55, h, w), V::Felled);
  EXPECT_EQ(fallVerdict(D::Right, 2.2751, h, w), V::Felled);  // just past T
  EXPECT_EQ(fallVerdict(D::Right, 2.27, h, w), V::InPlace);
  EXPECT_EQ(fallVerdict(D::Right, 1.25, h, w), V::InPlace);  // the RC frame's move
  EXPECT_EQ(fallVerdict(D::Right, -0.6, h, w), V::InPlace);
  EXPECT_EQ(fallVerdict(D::Right, -2.3, h, w), V::OtherWay);
  EXPECT_EQ(fallVerdict(D::Left, -4.0, h, w), V::Felled);
  EXPECT_EQ(fallVerdict(D::Left, 4.0, h, w), V::OtherWay);
  EXPECT_EQ(fallVerdict(D::Left, 1.0, h, w), V::InPlace);
  EXPECT_EQ(fallVerdict(D::Down, 2.0, h, w), V::InPlace);
  EXPECT_EQ(fallVerdict(D::Down, -2.3, h, w), V::Felled);
  EXPECT_EQ(fallVerdict(D::None, 9.0, h, w), V::None);
  EXPECT_FALSE(unintended(D::Right, V::Felled));
  EXPECT_TRUE(unintended(D::Right, V::InPlace));
  EXPECT_TRUE(unintended(D::Left, V::OtherWay));
  EXPECT_FALSE(unintended(D::Down, V::InPlace));
  EXPECT_TRUE(unintended(D::Down, V::Felled));
  EXPECT_FALSE(unintended(D::None, V::InPlace));
  EXPECT_STREQ(fallVerdictName(V::OtherWay), "other way");
}

// A column of two unit-mass-per-length members from (0, 0) to (0, 10), on the
// ground y = 0, turned by `deg` about its foot (+: toward +x).
Model column(double deg, State& s) {
  Model m;
  m.materials()[1] = test::unitMassBarMaterial();
  for (int i = 0; i < 3; ++i) m.addNode(Vec2(0, 5.0 * i));
  for (int e = 0; e < 2; ++e)
    m.setElement(e, makeElement(m.materials().at(1), {e, e + 1}, m.coord(e), m.coord(e + 1)));
  m.ground() = Ground{0, 1e6};
  s.resize(3);
  const double a = deg * M_PI / 180;
  for (int n = 0; n < 3; ++n) {
    const double y = 5.0 * n;
    s.u[3 * n] = y * std::sin(a);
    s.u[3 * n + 1] = y * std::cos(a) - y;
  }
  return m;
}

// H = 10, W = 0: T = 2.5. The centroid (at 5 m up) moves by 5 sin(deg).
TEST(FallVerdict, ConstructedEndStates) {
  State s;
  Model m = column(90, s);  // lying on the ground toward +x: moved 5 m
  m.site() = Site{-20, 20, FallDirection::Right};
  DebrisFigures d = debrisFigures(m, s);
  EXPECT_NEAR(d.buildingHeight, 10, 1e-12);
  EXPECT_NEAR(d.centroidShift, 5, 1e-9);
  EXPECT_NEAR(d.centroidMoveH(), 0.5, 1e-9);
  EXPECT_EQ(d.verdict, FallVerdict::Felled);
  EXPECT_EQ(d.tilt, 0);  // nothing stands
  EXPECT_FALSE(d.unintendedFall());

  m = column(20, s);  // leaning 20 degrees: moved 1.71 m < T, still standing
  m.site() = Site{-20, 20, FallDirection::Right};
  d = debrisFigures(m, s);
  EXPECT_NEAR(d.centroidShift, 5 * std::sin(20 * M_PI / 180), 1e-9);
  EXPECT_EQ(d.verdict, FallVerdict::InPlace);
  EXPECT_NEAR(d.tilt, 20, 1e-9);
  EXPECT_TRUE(d.unintendedFall());

  m = column(-40, s);  // toward -x: 3.21 m the other way, tilted 40 degrees
  m.site() = Site{-20, 20, FallDirection::Right};
  d = debrisFigures(m, s);
  EXPECT_EQ(d.verdict, FallVerdict::OtherWay);
  EXPECT_NEAR(d.tilt, -40, 1e-9);
  m.site()->dir = FallDirection::Left;
  EXPECT_EQ(debrisFigures(m, s).verdict, FallVerdict::Felled);
  m.site()->dir = FallDirection::Down;
  EXPECT_EQ(debrisFigures(m, s).verdict, FallVerdict::Felled);
  m.site()->dir = FallDirection::None;
  EXPECT_EQ(debrisFigures(m, s).verdict, FallVerdict::None);

  // The CSV row carries the verdict and its figures.
  m.site()->dir = FallDirection::Left;
  const std::string row = debrisCsvRow(debrisFigures(m, s));
  EXPECT_NE(row.find(",felled,"), std::string::npos) << row;
  EXPECT_NE(debrisLogLines(debrisFigures(m, s)).find("felled (intended LEFT)"), std::string::npos);
}

}  // namespace
}  // namespace c2d
