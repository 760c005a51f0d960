// Infill panels' equivalent struts (materials/InfillPanel): width, stiffness
// and strength against FEMA 356 7.5.2's relations computed by hand for a solid
// panel and one with an opening, crushing governing a narrow strut, and a
// panel without clear size refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "materials/InfillPanel.h"

namespace c2d {
namespace {

// Panel A: bay 5 m x storey 3 m, columns 0.4 m deep (EIcol = 30e6 0.4^4/12 =
// 64000 kN m^2), beams 0.5 m deep; wall t = 0.2 m, fm = 4000 kN/m^2,
// Em = 550 fm = 2.2e6, rho = 1.8, solid.
//   L_inf = 4.6, h_inf = 2.5, r_inf = sqrt(4.6^2 + 2.5^2) = 5.235456,
//   sin(2 theta) = 2 L h / r^2 = 23/27.41 = 0.839110,
//   lambda1 = (2.2e6 0.2 0.839110 / (4 64000 2.5))^(1/4) = 0.576888^(1/4) = 0.871511,
//   a = 0.175 (0.871511 3)^-0.4 5.235456 = 0.623785 m,
//   K = Em a t = 274465 kN; theta_s = atan(3/5), cos = 0.857493;
//   crushing V_c = a t fm cos = 427.91 kN, sliding V_s = 4.6 0.2 0.03 4000 = 110.40 kN,
//   Pu = 110.40 / 0.857493 = 128.747 kN; mass 1.8 0.2 4.6 2.5 = 4.14 t.
TEST(InfillPanel, SolidPanelAgainstFema356ByHand) {
  const InfillWall wall{0.2, 4000, 2.2e6, 1.8, 0};
  InfillFrame frame;
  frame.bay = 5;
  frame.storey = 3;
  frame.columnDepth = 0.4;
  frame.beamDepth = 0.5;
  frame.EIcol = 30e6 * std::pow(0.4, 4) / 12;
  const InfillStruts s = infillStruts(wall, frame);
  EXPECT_NEAR(s.rinf, 5.235456, 1e-6);
  EXPECT_NEAR(s.lambda1, 0.871511, 1e-6);
  EXPECT_NEAR(s.width, 0.623785, 1e-6);
  EXPECT_NEAR(s.stiffness, 274465.4, 0.1);
  EXPECT_NEAR(s.crushing, 427.913, 1e-3);
  EXPECT_NEAR(s.sliding, 110.400, 1e-9);
  EXPECT_FALSE(s.crushingGoverns());
  EXPECT_NEAR(s.strength, 128.7474, 1e-4);
  EXPECT_NEAR(s.mass, 4.14, 1e-12);
}

// Panel B: bay 4 m x storey 3.2 m, columns 0.3 m deep (EIcol = 20250), no
// beam depth; wall t = 0.12, fm = 2500, Em = 1.5e6, rho = 1.6, open = 0.3.
//   L_inf = 3.7, h_inf = 3.2, r_inf = 4.891830, sin(2 theta) = 23.68/23.93 = 0.989553,
//   lambda1 = (1.5e6 0.12 0.989553 / (4 20250 3.2))^(1/4) = 0.910477,
//   a = 0.175 (0.910477 3.2)^-0.4 4.891830 = 0.558138 m,
//   R1 = 0.6 0.09 - 1.6 0.3 + 1 = 0.574 (Al-Chaar 2002),
//   K = Em R1 a t = 57666.8 kN; cos(theta_s) = 4/sqrt(26.24) = 0.780869;
//   V_c = R1 a t fm cos = 75.050 kN, V_s = R1 3.7 0.12 0.03 2500 = 19.1142 kN,
//   Pu = 19.1142 / 0.780869 = 24.4781 kN; mass 1.6 0.12 3.7 3.2 0.7 = 1.591296 t.
TEST(InfillPanel, PanelWithAnOpeningAgainstFema356AndAlChaarByHand) {
  const InfillWall wall{0.12, 2500, 1.5e6, 1.6, 0.3};
  InfillFrame frame;
  frame.bay = 4;
  frame.storey = 3.2;
  frame.columnDepth = 0.3;
  frame.EIcol = 30e6 * std::pow(0.3, 4) / 12;
  const InfillStruts s = infillStruts(wall, frame);
  EXPECT_NEAR(s.lambda1, 0.910477, 1e-6);
  EXPECT_NEAR(s.width, 0.558138, 1e-6);
  EXPECT_NEAR(s.reduction, 0.574, 1e-12);
  EXPECT_NEAR(s.stiffness, 57666.84, 0.01);
  EXPECT_NEAR(s.crushing, 75.0504, 1e-4);
  EXPECT_NEAR(s.sliding, 19.1142, 1e-9);
  EXPECT_NEAR(s.strength, 24.47812, 1e-5);
  EXPECT_NEAR(s.mass, 1.591296, 1e-9);
  // The opening's reduction falls from 1 (solid) to 0 (no wall).
  EXPECT_DOUBLE_EQ(openingReduction(0), 1.0);
  EXPECT_NEAR(openingReduction(1), 0.0, 1e-15);
}

TEST(InfillPanel, CrushingGovernsANarrowStrut) {
  // The lesser of the two: with a strut narrower than 0.03 L_inf / cos the
  // crushing governs (here the columns make lambda1 h large).
  const InfillWall wall{0.2, 4000, 2.2e6, 1.8, 0};
  InfillFrame frame{30, 3, 0, 0, 1e-6};
  const InfillStruts s = infillStruts(wall, frame);
  ASSERT_TRUE(s.crushingGoverns());
  EXPECT_NEAR(s.strength, s.width * 0.2 * 4000, 1e-9 * s.strength);
}

TEST(InfillPanel, RefusesAPanelWithoutClearSize) {
  const InfillWall wall{0.2, 4000, 2.2e6, 1.8, 0};
  InfillFrame frame{5, 3, 6, 0, 64000};
  EXPECT_THROW(infillStruts(wall, frame), std::invalid_argument);
}

}  // namespace
}  // namespace c2d
