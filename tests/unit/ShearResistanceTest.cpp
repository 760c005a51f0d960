// The shear capacity Vu(N) of RC sections (materials/ShearResistance, EC2
// 6.2.2 and 6.2.3) against hand calculations: two sections at a tension, at
// N = 0 and at a compression. The hand numbers below are worked in MPa and mm
// as EC2 writes them, then turned into kN.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "materials/RcSection.h"

namespace c2d {
namespace {

constexpr double kA16 = M_PI * 0.008 * 0.008, kA20 = M_PI * 0.01 * 0.01,
                 kA25 = M_PI * 0.0125 * 0.0125;

RcSectionData section(double b, double h, double fc, std::vector<RebarLayer> bars,
                      Stirrups links) {
  RcSectionData d;
  d.b = b;
  d.h = h;
  d.fc = fc;
  d.fy = 500e3;
  d.Es = 200e6;
  d.fu = 540e3;
  d.eu = 0.05;
  d.bars = std::move(bars);
  d.stirrups = links;
  return d;
}

void expectParts(const RcSection& s, double N, int sign, double vc, double cot, double vs) {
  SCOPED_TRACE("N = " + std::to_string(N) + ", sign " + std::to_string(sign));
  const ShearResistance::Parts p = s.shear().parts(N, sign);
  EXPECT_NEAR(p.concrete, vc, 1e-4);
  EXPECT_NEAR(p.cot, cot, 1e-5);
  EXPECT_NEAR(p.stirrups, vs, 1e-4);
  EXPECT_NEAR(p.vu, std::max(vc, vs), 1e-4);
}

// Beam 0.3 x 0.5 m, C30, 2 x 16 mm at 40 mm, 3 x 20 mm at 450 mm from the top,
// links 2 legs of 10 mm at 100 mm, fyw = 500 MPa: omega = Asw fyw / s = 785.40 kN/m.
// Sign +1: d = 450 mm, Asl = 942.48 mm^2: k = 1 + sqrt(200/450) = 1.66667,
// rho_l = 942.48/(300 x 450) = 0.0069813, 0.18 k (100 rho_l 30)^(1/3) = 0.82694 MPa
// (vmin = 0.035 k^1.5 30^0.5 = 0.41248 below it).
// Sign -1: d = 460 mm, Asl = 402.12 mm^2: k = 1.65938, rho_l = 0.0029140, 0.61530 MPa.
// nu = 0.6 (1 - 30/250) = 0.528; struts a = alpha_cw bw nu fc = 4752 alpha_cw kN/m.
//  N = +300 (tension): sigma_cp = -2 MPa: VRd,c+ = (0.82694 - 0.3) 300 x 450 = 71.137 kN,
//    VRd,c- = (0.61530 - 0.3) 300 x 460 = 43.511 kN; alpha_cw = 1: cot^2 = 4752/785.40 - 1,
//    cot = 2.24732, VRd,s = 785.40 x 0.405 x 2.24732 = 714.841 kN (+), z = 0.414: 730.726 (-).
//  N = 0: VRd,c+ = 111.637, VRd,c- = 84.911 kN; VRd,s as in tension.
//  N = -3300: sigma_cp = 22 MPa, capped at 0.2 fc = 6 in VRd,c: 233.137 and 209.111 kN;
//    alpha_cw = 2.5 (1 - 22/30) = 0.66667: cot = sqrt(3168/785.40 - 1) = 1.74173,
//    VRd,s = 785.40 x 0.405 x 1.74173 = 554.020 kN (+), 566.332 kN (-).
TEST(ShearResistance, BeamWithLinksAgainstHandCalculations) {
  const RcSection s(section(0.3, 0.5, 30e3, {{0.04, 2 * kA16}, {0.45, 3 * kA20}},
                            Stirrups{2 * M_PI * 0.005 * 0.005, 0.1, 500e3}));
  expectParts(s, 300, 1, 71.136932, 2.247317, 714.840695);
  expectParts(s, 300, -1, 43.511185, 2.247317, 730.726043);
  expectParts(s, 0, 1, 111.636932, 2.247317, 714.840695);
  expectParts(s, 0, -1, 84.911185, 2.247317, 730.726043);
  expectParts(s, -3300, 1, 233.136932, 1.741730, 554.020328);
  expectParts(s, -3300, -1, 209.111185, 1.741730, 566.331891);
  // The member's: the smaller sign's.
  EXPECT_NEAR(s.shearCapacity(0.0), 714.840695, 1e-4);
  EXPECT_NEAR(s.shearCapacity(-3300.0), 554.020328, 1e-4);
}

// Column 0.4 x 0.4 m, C25, 3 x 25 mm at 50 mm from each face, sparse links 2
// legs of 6 mm at 300 mm, fyw = 400 MPa: omega = 75.398 kN/m.
// d = 350 mm, Asl = 1472.6 mm^2, k = 1 + sqrt(200/350) = 1.75593, rho_l =
// 0.010519, 0.18 k (100 rho_l 25)^(1/3) = 0.93990 MPa; nu = 0.54.
//  N = +400: sigma_cp = -2.5 MPa: VRd,c = (0.93990 - 0.375) 400 x 350 = 79.086 kN;
//    cot = 2.5 (a/omega = 8640/75.4 large): VRd,s = 75.398 x 0.315 x 2.5 = 59.376 kN:
//    Vu = VRd,c = 79.086 kN.
//  N = 0: VRd,c = 131.586 kN = Vu.
//  N = -3000: sigma_cp = 18.75 MPa, capped at 0.2 x 25 = 5 MPa in VRd,c:
//    (0.93990 + 0.75) 400 x 350 = 236.586 kN; alpha_cw = 2.5 (1 - 0.75) = 0.625, cot still 2.5: 59.376 kN.
TEST(ShearResistance, ShearCriticalColumnAgainstHandCalculations) {
  const RcSection s(section(0.4, 0.4, 25e3, {{0.05, 3 * kA25}, {0.35, 3 * kA25}},
                            Stirrups{2 * M_PI * 0.003 * 0.003, 0.3, 400e3}));
  for (int sign : {1, -1}) {
    expectParts(s, 400, sign, 79.085647, 2.5, 59.376101);
    expectParts(s, 0, sign, 131.585647, 2.5, 59.376101);
    expectParts(s, -3000, sign, 236.585647, 2.5, 59.376101);
  }
  // Vu(N) is continuous: no jump at N = 0 or where sigma_cp reaches 0.2 fc.
  for (double n : {0.0, -0.2 * 25e3 * 0.16})
    EXPECT_NEAR(s.shearCapacity(n - 1e-6), s.shearCapacity(n + 1e-6), 1e-6);
  // A tension that leaves no concrete share: (0.9399 / 0.15) MPa x 0.16 m^2 = 1002.6 kN;
  // the links still carry their 59.376 kN.
  EXPECT_NEAR(s.shearCapacity(1100.0), 59.376101, 1e-4);
  // Without links: Vu = VRd,c, floored at 0, with a finite demand.
  RcSectionData bare = s.data();
  bare.stirrups.reset();
  const RcSection b(bare);
  EXPECT_NEAR(b.shearCapacity(0.0), 131.585647, 1e-4);
  EXPECT_EQ(b.shearCapacity(1100.0), 0.0);
  EXPECT_TRUE(std::isfinite(b.shear().demand(10.0, 1100.0)));
  EXPECT_GT(b.shear().demand(10.0, 1100.0), 1e6);
  EXPECT_NEAR(b.shear().demand(-65.792823, 0.0), 0.5, 1e-6);
}

// A fc surely not in kN/m^2 is refused (the rule's expressions are in MPa).
TEST(ShearResistance, RefusesAStrengthInAnotherUnit) {
  RcSectionData d = section(0.4, 0.4, 25e3, {{0.05, 3 * kA25}, {0.35, 3 * kA25}},
                            Stirrups{1e-4, 0.2, 400e3});
  d.fc = 25;  // MPa
  EXPECT_THROW(RcSection{d}, std::invalid_argument);
  d.fc = 25e6;  // N/m^2
  EXPECT_THROW(RcSection{d}, std::invalid_argument);
}

// The shortest piece: Lb = the larger of Mu(0)/Vu(0) of the two signs.
TEST(ShearResistance, ShortestPieceFromTheCapacity) {
  const RcSection s(section(0.4, 0.4, 25e3, {{0.05, 3 * kA25}, {0.35, 3 * kA25}},
                            Stirrups{2 * M_PI * 0.003 * 0.003, 0.3, 400e3}));
  EXPECT_NEAR(s.shortestPiece(), s.at(1, 0).Mu / 131.585647, 1e-6);
}

}  // namespace
}  // namespace c2d
