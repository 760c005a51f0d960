// A hinge at the face of a rigid end zone (decks/walls/face_hinge.inp): a
// cantilever with a rigid zone at its clamped root, pushed at its tip, opens
// its hinge when the face moment reaches Mu and then turns about the face:
// its force-displacement curve against the closed form of the deck's header.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

testing::DeckResult runWallsDeck(const testing::DeckTempDir& dir, const std::string& name) {
  return testing::runDeckFile(dir, std::string(C2D_SOURCE_DIR) + "/decks/walls/" + name);
}

TEST(FaceHinge, CantileverOpensAtTheFaceAndTurnsAboutIt) {
  const testing::DeckTempDir dir;
  const testing::DeckResult r = runWallsDeck(dir, "face_hinge.inp");
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  const testing::Csv csv = testing::readCsv(r.out / "face_hinge_tplot.csv");
  const std::vector<double> v = csv.column("disp_4_2"), f = csv.column("reac_1_2"),
                            m = csv.column("reac_1_3");
  ASSERT_EQ(v.size(), 62u);
  const double L = 3, l = 2.4, EI = 1e4, GA = 1e7, Mu = 120, Ks = -200;
  // The elements' tip compliance: curvature at their middles (x_i from the tip).
  const double c = (0.4 * 2.2 * 2.2 + 1.5 * 1.5 + 0.5 * 0.5) / EI + l / GA;
  const double vOpen = c * Mu / l;
  EXPECT_NEAR(*std::max_element(f.begin(), f.end()), Mu / l, 1e-8 * Mu / l);
  int opened = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double push = -v[i];
    EXPECT_NEAR(m[i], L * f[i], 1e-9 * std::abs(m[i]));  // the root's moment
    if (push <= vOpen * (1 + 1e-9)) {
      EXPECT_NEAR(f[i], push / c, 1e-8 * Mu / l) << "step " << i;
      continue;
    }
    const double psi = (push - c * Mu / l) / (l + c * Ks / l);
    EXPECT_NEAR(f[i], (Mu + Ks * psi) / l, 1e-8 * Mu / l) << "v " << push;
    ++opened;
  }
  EXPECT_EQ(opened, 58);
  EXPECT_NEAR(f.back(), 29.6232, 1e-4);  // the header's figure
}

// The RC member (SECTion, V20's section): the hinge opens at the face when
// F (L - o) reaches the hand-calculated Mu(0) = 269.128 kN m, its shear span
// the face's distance to the tip.
TEST(FaceHinge, RcCantileverOpensAtTheFace) {
  const testing::DeckTempDir dir;
  const testing::DeckResult r = runWallsDeck(dir, "face_hinge_rc.inp");
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  const testing::Csv csv = testing::readCsv(r.out / "face_hinge_rc_tplot.csv");
  const std::vector<double> f = csv.column("reac_1_2"), m = csv.column("reac_1_3");
  ASSERT_EQ(f.size(), 62u);
  const double Mu = 269.128, L = 3, o = 0.4;
  EXPECT_NEAR(-*std::min_element(f.begin(), f.end()), Mu / (L - o), 2e-6 * Mu / (L - o));
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(m[i], L * f[i], 1e-8 * Mu);
  EXPECT_NE(r.log.find("end 1 (node 1, joint's slave node 8)"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("shear span L_V = 2.600000e+00"), std::string::npos);
  EXPECT_LT(-f.back(), 0.7 * Mu / (L - o));  // softening at the face
}

// RC beams framing into a wall's faces through rigid zones: their hinges open
// at the faces (x = 6 and 10 m on the beams' axis y = 3), at the beam's Mu(N).
TEST(FaceHinge, BeamsFramingIntoAWallHingeAtItsFaces) {
  const testing::DeckTempDir dir;
  const testing::DeckResult r = runWallsDeck(dir, "wall_rc_beams.inp");
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  for (const std::string& row : {std::string(R"(\n +16 +\d+ +6\.00000E\+00 +3\.00000E\+00 .*end 2\n)"),
                                 std::string(R"(\n +17 +\d+ +1\.00000E\+01 +3\.00000E\+00 .*end 1\n)")})
    EXPECT_TRUE(std::regex_search(r.log, std::regex(row))) << row << "\n" << r.log;
  EXPECT_NE(r.log.find("element 16 end 2 (node 10,"), std::string::npos);
  EXPECT_NE(r.log.find("element 17 end 1 (node 10,"), std::string::npos);
}

}  // namespace
}  // namespace c2d
