// The infilled frame of decks/infill/infilled_frame.inp pushed sideways
// against the frame-plus-strut closed form: the bare frame's and the
// infilled frame's stiffness, the wall's shear at its peak, and the bare
// frame's curve once the panel is gone. The panel, the strut law, the strut
// element and INFIll: InfillPanelTest, StrutLawTest, InfillStrutTest,
// InfillCommandTest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

TEST(InfillDeck, PushoverFollowsTheFramePlusStrutClosedForm) {
  testing::DeckTempDir dir;
  const testing::DeckResult ran = testing::runSourceDeck(dir, "infill/infilled_frame.inp");
  const DeckOutcome& out = ran.outcome;
  ASSERT_EQ(out.exitCode, 0) << out.message;
  const testing::Csv wall = testing::readCsv(ran.out / "infilled_frame_op=0_tplot.csv");
  const testing::Csv bare = testing::readCsv(ran.out / "infilled_frame_op=1_tplot.csv");
  const std::vector<double> H = wall.column("reac_4_1"), u = wall.column("disp_4_1");
  const std::vector<double> Hb = bare.column("reac_4_1"), ub = bare.column("disp_4_1");
  ASSERT_GT(H.size(), 90u);
  ASSERT_EQ(H.size(), Hb.size());
  // The closed form of the deck's header.
  const double E = 30e6, Ic = std::pow(0.4, 4) / 12, Ib = 0.3 * 0.125 / 12, h = 3, L = 5;
  const double k = (Ib / L) / (Ic / h);
  const double Kf = 24 * E * Ic / (h * h * h) * (6 * k + 1) / (6 * k + 4);
  const double Linf = 4.6, hinf = 2.75, t = 0.2, Em = 2.2e6, fm = 4000;
  const double theta = std::atan2(hinf, Linf), rinf = std::hypot(Linf, hinf);
  const double lambda1 = std::pow(Em * t * std::sin(2 * theta) / (4 * E * Ic * hinf), 0.25);
  const double a = 0.175 * std::pow(lambda1 * h, -0.4) * rinf;
  const double r = std::hypot(L, h), c = L / r;
  const double Ks = Em * a * t / r * c * c;
  const double V = std::min(a * t * fm * c, Linf * t * 0.03 * fm);
  const double up = V / c / (Em * a * t) * r / c;
  EXPECT_NEAR(Hb[0] / ub[0], Kf, 0.03 * Kf);              // the bare frame
  EXPECT_NEAR(H[0] / u[0], Kf + Ks, 0.1 * (Kf + Ks));     // frame plus strut
  // The wall's shear: the difference of the two runs at the same drift.
  std::size_t ip = 0;
  for (std::size_t i = 0; i < H.size(); ++i) {
    ASSERT_DOUBLE_EQ(u[i], ub[i]);
    if (H[i] - Hb[i] > H[ip] - Hb[ip]) ip = i;
  }
  EXPECT_NEAR(H[ip] - Hb[ip], V, 0.05 * V);
  EXPECT_NEAR(u[ip], up, 0.15 * up);
  EXPECT_NEAR(H[ip], V + Kf * up, 0.1 * (V + Kf * up));  // the peak of the strut's branch
  // Past 10 u_p the panel is gone: the bare frame's curve.
  ASSERT_GT(u.back(), 10.5 * up);
  EXPECT_NEAR(H.back(), Hb.back(), 1e-9 * Hb.back());
  const std::string& log = ran.log;
  EXPECT_NE(log.find("infill panel 1 crushed at t ="), std::string::npos);
}

}  // namespace
}  // namespace c2d
