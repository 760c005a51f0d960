// The rotation capacity of an RC section's hinge from its stirrups
// (RcSection::ultimateConfined): dense links giving more rotation than sparse
// ones, and the deck decks/rc/stirrup_rotation.inp's chord rotations at the
// 20 % drop beside EN 1998-3 (A.1)'s. The confinement itself and (A.1) by
// hand: ConfinementTest.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "macro/DeckRunner.h"
#include "materials/Confinement.h"
#include "materials/RcSection.h"
#include "tests/unit/RcTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using test::v20;

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
  const testing::DeckTempDir scratch;
  const testing::DeckResult ran = testing::runSourceDeck(scratch, "rc/stirrup_rotation.inp");
  ASSERT_EQ(ran.outcome.exitCode, kExitOk) << ran.console;
  const std::filesystem::path& dir = ran.out;
  const double H = 3,
               dense = chordRotationAtDrop(
                   testing::readCsv(dir / "stirrup_rotation_s=0.1_tplot.csv"), H),
               sparse = chordRotationAtDrop(
                   testing::readCsv(dir / "stirrup_rotation_s=0.3_tplot.csv"), H);
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
