// The rotation capacity of an RC section's hinge from its stirrups
// (materials/Confinement, RcSection::ultimateConfined): the confinement
// effectiveness and the confined ultimate strain against a hand calculation
// of EN 1998-3 (A.10), (A.11) with EN 1998-1 5.4.3.2.2(8)'s alpha, the mean
// chord rotation at ultimate against a hand evaluation of EN 1998-3 (A.1),
// dense links giving more rotation than sparse ones, and the deck
// decks/rc/stirrup_rotation.inp's chord rotations at the 20 % drop beside
// (A.1)'s.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "macro/DeckRunner.h"
#include "materials/Confinement.h"
#include "materials/RcSection.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

// The section of verification.md V20 (kN, m): 0.5 x 0.5 m, 4 bars of 20 mm at
// 0.05 m from each face, C30, B500; links of two legs of 10 mm at spacing s.
RcSectionData v20(double s) {
  RcSectionData d;
  d.b = d.h = 0.5;
  d.fc = 30e3;
  d.fy = 500e3;
  d.Es = 200e6;
  d.fu = 540e3;
  d.eu = 0.05;
  const double a = 4 * M_PI * 0.01 * 0.01;
  d.bars = {{0.05, a}, {0.45, a}};
  if (s > 0) d.stirrups = Stirrups{2 * M_PI * 0.005 * 0.005, s, 500e3};
  return d;
}

TEST(RcConfinement, EffectivenessAndConfinedStrainByHand) {
  // Core b0 = h0 = 0.4 m (to the bars' centres). s = 0.1 m:
  //   alpha_s = (1 - 0.1/0.8)^2 = 0.765625, alpha_n = 1 - 4 (0.16)/(6 (0.16)) = 1/3,
  //   alpha = 0.2552083; rho_sx = 1.5708e-4/(0.5 x 0.1) = 3.14159e-3;
  //   alpha rho_sx fyw/fc = 0.2552083 x 3.14159e-3 x 500/30 = 0.0133627;
  //   fcc = 30 (1 + 3.7 x 0.0133627^0.86) = 30 x 1.090455 = 32.714 MPa;
  //   eps_cu,c = 0.004 + 0.5 x 0.2552083 x 3.14159e-3 x 500/32.714 = 0.010127.
  const auto c = confinementOf(v20(0.1));
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->b0, 0.4, 1e-12);
  EXPECT_NEAR(c->h0, 0.4, 1e-12);
  EXPECT_NEAR(c->alphaS, 0.765625, 1e-9);
  EXPECT_NEAR(c->alphaN, 1.0 / 3, 1e-9);
  EXPECT_NEAR(c->alpha, 0.2552083, 1e-6);
  EXPECT_NEAR(c->rhoSx, 3.14159e-3, 1e-8);
  EXPECT_NEAR(c->fcc, 32.714e3, 2);
  EXPECT_NEAR(c->epsCu, 0.010127, 2e-6);
  // s = 0.3 m: alpha_s = (1 - 0.3/0.8)^2 = 0.390625, alpha = 0.1302083,
  // rho_sx = 1.0472e-3, index 2.27256e-3, fcc = 30 (1 + 3.7 x 0.0053294)
  // = 30.5916 MPa, eps_cu,c = 0.004 + 0.5 x 1.36354e-4 x 500/30.5916 = 0.0051143.
  const auto sparse = confinementOf(v20(0.3));
  ASSERT_TRUE(sparse);
  EXPECT_NEAR(sparse->alpha, 0.1302083, 1e-6);
  EXPECT_NEAR(sparse->fcc, 30.5916e3, 2);
  EXPECT_NEAR(sparse->epsCu, 0.0051143, 2e-6);
  EXPECT_FALSE(confinementOf(v20(0)));  // no links: EC2's eps_cu2
}

TEST(RcConfinement, ChordRotationAtUltimateByHandFromEquationA1) {
  // N = -1000 kN: nu = 1000/(0.25 x 30e3) = 0.13333, 0.3^nu = 0.851693;
  // w = w' = 1.25664e-3 x 500/(0.5 x 0.45 x 30) = 0.093084: [1 x 30]^0.225 =
  // 2.149524; 25^0.0133627 = 1.043951:
  //   theta_um/(L_V/h)^0.35 = 0.016 x 0.851693 x 2.149524 x 1.043951 = 0.030579,
  // and at L_V = 3 m (6^0.35 = 1.872171) theta_um = 0.057249 rad.
  const double hand = 0.016 * std::pow(0.3, 1000 / (0.25 * 30e3)) * std::pow(30.0, 0.225) *
                      std::pow(25.0, 0.2552083 * 3.14159265e-3 * 500 / 30);
  EXPECT_NEAR(hand, 0.030579, 2e-6);
  for (int sign : {1, -1}) {
    const auto f = chordRotationFactor(v20(0.1), -1000, sign);
    ASSERT_TRUE(f);
    EXPECT_NEAR(*f, hand, 1e-6 * hand);
  }
  // Tension counts as nu = 0; an unbalanced section: omega'/omega; units.
  RcSectionData d = v20(0.1);
  EXPECT_NEAR(*chordRotationFactor(d, 500, 1), hand / std::pow(0.3, 1000 / 7.5e3), 1e-6 * hand);
  d.bars[0].area /= 2;  // top bars halved: positive moments compress them
  EXPECT_NEAR(*chordRotationFactor(d, -1000, 1) / *chordRotationFactor(v20(0.1), -1000, 1),
              std::pow(0.5, 0.225), 1e-9);
  d = v20(0.1);
  d.fc = 30;  // MPa: the same rule
  d.fy = 500;
  d.stirrups->fy = 500;
  EXPECT_NEAR(*chordRotationFactor(d, -1000e-3, 1), hand, 1e-6 * hand);
  d.fc = 3e-2;  // no unit system with C30 at that number
  EXPECT_FALSE(chordRotationFactor(d, 0, 1));
}

TEST(RcConfinement, DenseLinksGiveMoreRotationThanSparseOnes) {
  const RcSection dense(v20(0.1)), sparse(v20(0.3)), none(v20(0));
  for (double n : {-3000.0, -1000.0, 0.0, 500.0}) {
    SCOPED_TRACE(n);
    // In tension the bars reach eu first whatever the links: equal there within
    // the stress blocks' difference (fcc, eps_c2,c).
    if (n <= 0)
      EXPECT_GT(dense.plasticRotation(n, 1, 3.0), 1.1 * sparse.plasticRotation(n, 1, 3.0));
    else
      EXPECT_NEAR(dense.plasticRotation(n, 1, 3.0), sparse.plasticRotation(n, 1, 3.0),
                  0.01 * sparse.plasticRotation(n, 1, 3.0));
    EXPECT_GT(sparse.plasticRotation(n, 1, 3.0), none.plasticRotation(n, 1, 3.0));
    EXPECT_GT(*chordRotationFactor(dense.data(), n, 1), *chordRotationFactor(sparse.data(), n, 1));
    // The flexural capacity is the unconfined section's (EC2 eps_cu2).
    EXPECT_DOUBLE_EQ(dense.ultimate(n, 1).M, none.ultimate(n, 1).M);
  }
  EXPECT_NEAR(dense.confinedStrain(), 0.010127, 2e-6);
  EXPECT_EQ(none.confinedStrain(), RcSection::kEpsCu2);
  // The confined state: the compressed face at most at eps_cu,c (here the
  // tension bars reach eu = 0.05 first), beyond the unconfined eps_cu2.
  const RcSection::State u = dense.ultimateConfined(-1000, 1);
  ASSERT_TRUE(u.exists);
  EXPECT_LE(-u.e0, 0.010127 + 1e-9);
  EXPECT_GT(-u.e0, 0.0035);
  EXPECT_GT(u.kappa, dense.ultimate(-1000, 1).kappa);
  EXPECT_GT(dense.ruptureRotation(), none.ruptureRotation());
}

// The deck's base moment and tip displacement: the chord rotation (tip / H)
// where the moment, past its peak, has fallen to 0.8 of it (interpolated).
double chordRotationAtDrop(const testing::Csv& csv, double H) {
  const auto m = csv.column("reac_1_3"), u = csv.column("disp_7_1");
  double peak = 0;
  std::size_t at = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (std::abs(m[i]) > peak) peak = std::abs(m[i]), at = i;
  for (std::size_t i = at + 1; i < m.size(); ++i)
    if (std::abs(m[i]) <= 0.8 * peak) {
      const double a = std::abs(m[i - 1]), b = std::abs(m[i]);
      const double t = (a - 0.8 * peak) / (a - b);
      return (u[i - 1] + t * (u[i] - u[i - 1])) / H;
    }
  return -1;
}

TEST(RcConfinement, CantileversDifferingInTheirLinksBesideEquationA1) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("c2d_rc_rotation_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  DeckOptions opt;
  opt.outDir = dir;
  opt.quiet = true;
  const SolutionCommands commands;
  std::ostringstream console;
  const DeckOutcome o = runDeck(std::string(C2D_SOURCE_DIR) + "/decks/rc/stirrup_rotation.inp",
                                opt, commands, console);
  ASSERT_EQ(o.exitCode, kExitOk) << console.str();
  const double H = 3, dense = chordRotationAtDrop(testing::readCsv(dir / "stirrup_rotation_s=0.1_tplot.csv"), H),
               sparse = chordRotationAtDrop(testing::readCsv(dir / "stirrup_rotation_s=0.3_tplot.csv"), H);
  std::filesystem::remove_all(dir);
  // EN 1998-3 (A.1), mean, L_V/h = 6 (hand: see the test above).
  const double lv = std::pow(6.0, 0.35);
  const double a1Dense = 0.016 * std::pow(0.3, 1000 / 7.5e3) * std::pow(30.0, 0.225) *
                         std::pow(25.0, 0.2552083 * 3.14159265e-3 * 500 / 30) * lv;
  const double a1Sparse = 0.016 * std::pow(0.3, 1000 / 7.5e3) * std::pow(30.0, 0.225) *
                          std::pow(25.0, 0.1302083 * 1.0471976e-3 * 500 / 30) * lv;
  RecordProperty("dense", std::to_string(dense) + " A.1 " + std::to_string(a1Dense));
  RecordProperty("sparse", std::to_string(sparse) + " A.1 " + std::to_string(a1Sparse));
  std::printf("chord rotation at the 20 %% drop: dense %.5f (A.1 %.5f), sparse %.5f (A.1 %.5f)\n",
              dense, a1Dense, sparse, a1Sparse);
  EXPECT_GT(dense, sparse);
  // EN 1998-3's own curvature route (A.9) for these members, assembled by hand
  // from the sections' curvatures (RcSectionTest and the test above check
  // those) with the code's yield rotation (A.10b) theta_y = phi_y L_V/3 +
  // 0.0013 (1 + 1.5 h/L_V) + 0.13 phi_y dbL fy/sqrt(fc) and (A.10)'s Lpl =
  // 3/30 + 0.2 x 0.5 + 0.11 x 0.02 x 500/sqrt(30) = 0.400832 m:
  // theta_um = theta_y + (phi_u - phi_y) Lpl (1 - 0.5 Lpl/3). The member
  // model's chord rotation has the flexural part of theta_y only (no shear
  // deformation, no bar slip: the 0.0013 (1.25) + 0.13 phi_y dbL fy/sqrt(fc)
  // terms, about 0.0037 rad here), and at the drop its elastic part has
  // unloaded to 0.8 Mu (0.2 phi_y L_V/3 less): so it is the route's value
  // less those, within 3 %.
  const double lpl = 0.400832, rot = lpl * (1 - 0.5 * lpl / 3);
  for (const auto& [s, model] : {std::pair{0.1, dense}, std::pair{0.3, sparse}}) {
    const RcSection section(v20(s));
    const double phiY = section.firstYield(-1000, 1).kappa;
    const double phiU = section.ultimateConfined(-1000, 1).kappa;
    const double slip = 0.0013 * 1.25 + 0.13 * phiY * 0.02 * 500 / std::sqrt(30.0);
    const double routeA9 = phiY + slip + (phiU - phiY) * rot;  // phi_y L_V/3 = phi_y
    const double expected = routeA9 - slip - 0.2 * phiY;
    std::printf("  s = %.1f: (A.9) route %.5f, less shear, slip and unloading %.5f, model %.5f\n",
                s, routeA9, expected, model);
    EXPECT_NEAR(model, expected, 0.03 * expected);
  }
  // The band against (A.1)'s cyclic mean (docs/design/rc-rotation-capacity.md):
  // 0.4-1.8. Above: a monotonic push exceeds the cyclic mean, by about 1.5-1.6
  // in the tests behind Annex A (Biskinis and Fardis), so 1.8 leaves the
  // scatter of a fit; below: the code's own two routes part for light links
  // ((A.1)'s 25^(alpha rho_sx fyw/fc) moves it 4 % between these members,
  // (A.12)'s eps_cu,c halves: the (A.9) route is 1.0 (dense) and 0.56
  // (sparse) of (A.1) here), and the member model lacks the shear and slip
  // share of theta_y. 0.93 and 0.49 when written.
  EXPECT_GT(dense / a1Dense, 0.8);
  EXPECT_LT(dense / a1Dense, 1.8);
  EXPECT_GT(sparse / a1Sparse, 0.4);
  EXPECT_LT(sparse / a1Sparse, 1.8);
}

}  // namespace
}  // namespace c2d
