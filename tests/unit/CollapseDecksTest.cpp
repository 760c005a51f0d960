// Collapse-phase decks checked against closed forms (verification V5, V6) and
// the energy balance of the conserving mid-point scheme, through the whole deck
// path (GRAVity, CONTact, DYNA,ENERgy, TPLOt ener).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "macro/DeckRunner.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using Columns = std::map<std::string, std::vector<double>>;

// Runs a deck into a directory of its own and reads the TPLOt file <stem>_tplot.csv.
Columns runAndRead(const std::string& deck, const std::string& stem) {
  const testing::DeckTempDir dir;
  const testing::DeckResult ran = testing::runSourceDeck(dir, deck);
  EXPECT_EQ(ran.outcome.exitCode, 0) << ran.outcome.message;
  const testing::Csv csv = testing::readCsv(ran.out / (stem + "_tplot.csv"));
  Columns cols;
  for (const std::string& n : csv.names) cols[n] = csv.column(n);
  return cols;
}

double relativeDrift(const std::vector<double>& total, double scale) {
  const auto [lo, hi] = std::minmax_element(total.begin(), total.end());
  return (*hi - *lo) / scale;
}

TEST(CollapseDecks, PendulumPeriod) {
  Columns c = runAndRead("collapse/pendulum.inp", "pendulum");
  ASSERT_FALSE(c["time"].empty());
  const double L = 1, th = 0.05, g = 9.81, A = 1, I = 1e-4, pi = std::acos(-1.0);
  const double T0 = 2 * pi * std::sqrt(2 * L / (3 * g)), h = T0 / 100, Om = 2 * pi / T0;
  const double k = std::sin(th / 2);
  const double expected = T0 * std::sqrt(1 + 3 * I / (A * L * L)) *
                          (1 + k * k / 4 + 9 * std::pow(k, 4) / 64) * Om * h /
                          (2 * std::atan(Om * h / 2));
  // Zero crossings of the tip's horizontal position (x = L sin theta).
  const auto& t = c["time"];
  const auto& u = c["disp_5_1"];
  std::vector<double> crossings;
  for (size_t i = 1; i < t.size(); ++i) {
    const double a = u[i - 1] + L * std::sin(th), b = u[i] + L * std::sin(th);
    if ((a > 0) != (b > 0)) crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * a / (a - b));
  }
  ASSERT_GE(crossings.size(), 5u);
  EXPECT_NEAR((crossings[2] - crossings[0]) / expected, 1.0, 2e-5);
  EXPECT_NEAR((crossings[4] - crossings[2]) / expected, 1.0, 2e-5);
  const double kmax = *std::max_element(c["kinetic"].begin(), c["kinetic"].end());
  EXPECT_LT(relativeDrift(c["total"], kmax), 1e-10);
}

// decks/collapse/friction_pendulum.inp: every half swing from theta_a to
// theta_b loses the joint friction's work Mr (theta_a + theta_b) (the
// extremes sampled at the steps), and the energy balance stays closed.
TEST(CollapseDecks, FrictionPendulumLosesTheFrictionsWork) {
  Columns c = runAndRead("collapse/friction_pendulum.inp", "friction_pendulum");
  ASSERT_FALSE(c["time"].empty());
  const double L = 1, th = 0.3, m = 1, g = 9.81, l = L / 2, Mr = 0.05;
  std::vector<double> a;
  for (size_t i = 0; i < c["time"].size(); ++i)
    a.push_back(std::atan2(L * std::sin(th) + c["disp_7_1"][i], L * std::cos(th) - c["disp_7_2"][i]));
  std::vector<double> extremes{a[0]};
  for (size_t i = 1; i + 1 < a.size(); ++i)
    if ((a[i] - a[i - 1]) * (a[i + 1] - a[i]) < 0) extremes.push_back(a[i]);
  ASSERT_GE(extremes.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    const double ta = std::abs(extremes[i]), tb = std::abs(extremes[i + 1]);
    EXPECT_LT(extremes[i] * extremes[i + 1], 0.0);  // the other side
    EXPECT_NEAR(m * g * l * (std::cos(tb) - std::cos(ta)), Mr * (ta + tb), 0.02 * Mr * (ta + tb))
        << "half swing " << i;
  }
  const double kmax = *std::max_element(c["kinetic"].begin(), c["kinetic"].end());
  EXPECT_LT(relativeDrift(c["balance"], kmax), 1e-9);
  EXPECT_GT(c["dissipated"].back(), 0.1 * kmax);
}

// decks/collapse/free_spin.inp: after the pulse (t >= 0.2 s) the free beam's
// linear and angular momentum and its energy stay constant to the solver
// tolerance (rotations by the Cayley rule), while it turns 4.6 times.
TEST(CollapseDecks, FreeSpinKeepsItsMomentum) {
  Columns c = runAndRead("collapse/free_spin.inp", "free_spin");
  ASSERT_FALSE(c["time"].empty());
  const auto& t = c["time"];
  std::size_t first = 0;
  while (first < t.size() && t[first] < 0.2 - 1e-9) ++first;
  ASSERT_LT(first + 10, t.size());
  const double j0 = c["angular_momentum"][first], px0 = c["momentum_x"][first];
  EXPECT_GT(std::abs(j0), 1.0);
  EXPECT_GT(std::abs(px0), 0.1);
  double worstJ = 0, worstP = 0, worstE = 0;
  for (std::size_t i = first; i < t.size(); ++i) {
    worstJ = std::max(worstJ, std::abs(c["angular_momentum"][i] - j0));
    worstP = std::max(worstP, std::hypot(c["momentum_x"][i] - px0,
                                          c["momentum_y"][i] - c["momentum_y"][first]));
    worstE = std::max(worstE, std::abs(c["total"][i] - c["total"][first]));
  }
  EXPECT_LT(worstJ, 1e-9 * std::abs(j0));
  EXPECT_LT(worstP, 1e-9 * std::abs(px0));
  EXPECT_LT(worstE, 1e-9 * c["kinetic"][first]);
  // The end section turned more than four times.
  EXPECT_GT(std::abs(c["disp_7_3"].back()), 4 * 2 * std::acos(-1.0));
}

// A mass m dropped from h0 onto a contact of stiffness K (the column's
// vertical displacement, h0 + disp its height above the contact distance):
// the closed-form penetration and contact duration, an elastic rebound to h0
// (energy conserved through the impact) and the energy balance.
void expectElasticBounce(Columns& c, const std::string& disp, double K, double m, double g,
                         double h0, double dt) {
  const double om = std::sqrt(K / m), v0 = std::sqrt(2 * g * h0);
  const double pen = m * g / K + std::sqrt(std::pow(m * g / K, 2) + m * v0 * v0 / K);
  const double tc = (std::acos(-1.0) + 2 * std::atan(g / (om * v0))) / om;
  const auto& t = c["time"];
  std::vector<double> y;
  for (double d : c[disp]) y.push_back(h0 + d);
  EXPECT_NEAR(*std::min_element(y.begin(), y.end()), -pen, 0.01 * pen);
  double first = -1, last = -1;
  for (size_t i = 0; i < y.size(); ++i)
    if (y[i] < 0) {
      if (first < 0) first = t[i];
      last = t[i];
    }
  ASSERT_GT(first, 0);
  EXPECT_NEAR(last - first, tc, 2 * dt);
  double rebound = -1;
  for (size_t i = 0; i < y.size(); ++i)
    if (t[i] > last) rebound = std::max(rebound, y[i]);
  EXPECT_NEAR(rebound, h0, 1e-3 * h0);
  EXPECT_LT(relativeDrift(c["total"], m * g * h0), 1e-10);
}

TEST(CollapseDecks, BarDrop) {
  Columns c = runAndRead("collapse/bar_drop.inp", "bar_drop");
  ASSERT_FALSE(c["time"].empty());
  const double L = 2, n = 4, h0 = 0.05, k = 1e4, g = 9.81, m = L, dt = 5e-4;
  expectElasticBounce(c, "disp_3_2", (n + 1) * k, m, g, h0, dt);
}

TEST(CollapseDecks, BarBounce) {
  Columns c = runAndRead("collapse/bar_bounce.inp", "bar_bounce");
  ASSERT_FALSE(c["time"].empty());
  const double L = 2, n = 4, h0 = 0.05, k = 1e4, g = 9.81, m = L, e = 0.5;
  const double K = (n + 1) * k, v0 = std::sqrt(2 * g * h0);
  const double pen = m * g / K + std::sqrt(std::pow(m * g / K, 2) + m * v0 * v0 / K);
  const auto& t = c["time"];
  std::vector<double> y;
  for (double d : c["disp_3_2"]) y.push_back(h0 + d);
  EXPECT_NEAR(*std::min_element(y.begin(), y.end()), -pen, 0.01 * pen);
  // Up again after the contact: the bar leaves at the set -pen (1 - e^2) with
  // e v0 and rises to e^2 h0 - pen (1 - e^2).
  size_t bottom = std::min_element(y.begin(), y.end()) - y.begin();
  double rebound = -1;
  for (size_t i = bottom; i < y.size() && t[i] < t[bottom] + 0.08; ++i) rebound = std::max(rebound, y[i]);
  EXPECT_NEAR(rebound, e * e * h0 - pen * (1 - e * e), 2e-3 * h0);
  // What the impact took, (1 - e^2) of the loading work k (n+1) pen^2 / 2 =
  // m g (h0 + pen), dissipated, and the balance closed.
  double dissipated = 0;
  for (size_t i = 0; i < y.size() && t[i] < t[bottom] + 0.08; ++i) dissipated = c["dissipated"][i];
  EXPECT_NEAR(dissipated, m * g * (h0 + pen) * (1 - e * e), 2e-3 * m * g * h0);
  EXPECT_LT(relativeDrift(c["balance"], m * g * h0), 1e-10);
}

TEST(CollapseDecks, BarComesToRest) {
  // TIME,REST,10,1e-6,0.1 (see the deck): the loop ends at the first step at
  // which the kinetic energy has stayed at most 1e-6 of its peak for 0.1 s,
  // long before t = 10.
  Columns c = runAndRead("collapse/bar_at_rest.inp", "bar_at_rest");
  ASSERT_FALSE(c["time"].empty());
  const auto& t = c["time"];
  const auto& kinetic = c["kinetic"];
  const double ratio = 1e-6, hold = 0.1, dt = 1e-3;
  const double peak = *std::max_element(kinetic.begin(), kinetic.end());
  std::size_t moving = 0;  // the last row above ratio of the peak
  for (std::size_t i = 0; i < t.size(); ++i)
    if (kinetic[i] > ratio * peak) moving = i;
  ASSERT_LT(moving + 1, t.size());
  EXPECT_LT(t.back(), 1.0);
  EXPECT_GE(t.back() - t[moving], hold - 1e-9);
  EXPECT_LT(t.back() - t[moving], hold + 1.5 * dt);
  EXPECT_LT(relativeDrift(c["balance"], peak), 1e-10);
}

TEST(CollapseDecks, BarOnBeam) {
  // Member contact: two node-to-segment pairs of stiffness k (see the deck).
  Columns c = runAndRead("collapse/bar_on_beam.inp", "bar_on_beam");
  ASSERT_FALSE(c["time"].empty());
  const double k = 2e4, h0 = 0.05, g = 9.81, m = 1, dt = 1e-3;
  expectElasticBounce(c, "disp_4_2", 2 * k, m, g, h0, dt);
}

TEST(CollapseDecks, SlidingBeam) {
  // Ground friction mu = 0.2 under gravity (0.3 g, -g): x = 0.05 g t^2, plus
  // less than mu g t_s t from the friction springs' stretch (see the deck).
  Columns c = runAndRead("collapse/sliding_beam.inp", "sliding_beam");
  ASSERT_EQ(c["time"].size(), 20u);
  const double g = 9.81, mu = 0.2, k = 1e5;
  const double reach = mu * (g / 2) / k, ts = std::sqrt(2 * reach / (0.3 * g));
  for (size_t i = 0; i < c["time"].size(); ++i) {
    const double t = c["time"][i], x = c["disp_1_1"][i];
    EXPECT_GT(x, 0.05 * g * t * t) << "t = " << t;
    EXPECT_LT(x - 0.05 * g * t * t, mu * g * ts * t) << "t = " << t;
    EXPECT_EQ(c["disp_2_1"][i], x);
    EXPECT_NEAR(c["disp_1_2"][i], 0.0, 1e-15);  // resting vertically at its static penetration
  }
  // Energy falls by what friction takes, mu m g x (less the springs' reach).
  const double x = c["disp_1_1"].back();
  EXPECT_NEAR(c["total"].front() - c["total"].back(),
              mu * g * (x - c["disp_1_1"].front()), 1e-3 * mu * g * x);
}

TEST(CollapseDecks, BarLandingSidewaysSticksWhereItLands) {
  // Dropped from H under gravity (0.2 g, -g): it lands 0.2 H on at 19.8 m/s,
  // 3.96 m/s sideways, and friction (mu = 0.5) holds it within 0.05 m of
  // there (0.51 m on before the stick element's dashpot), at rest.
  Columns c = runAndRead("collapse/bar_lands_sideways.inp", "bar_lands_sideways");
  const double H = 19.8 * 19.8 / (2 * 9.81);
  ASSERT_GT(c["time"].back(), 3.5);
  EXPECT_NEAR(c["disp_1_1"].back(), 0.2 * H, 0.05);
  EXPECT_LT(c["kinetic"].back(), 1e-6 * 0.9 * 9.81 * H);
}

TEST(CollapseDecks, SixStoryCollapseWithMemberContactLeavesNoCrossingMembers) {
  // The 84-element six-story workflow (decks/paper/six_story_collapse_short.inp)
  // run on to t = 200 s, when the frame lies on the ground, with member contact
  // beside the ground contact. Without it, five pairs of members end up
  // crossing each other (the run's log says so); with it, none.
  namespace fs = std::filesystem;
  const fs::path src = fs::path(C2D_SOURCE_DIR) / "decks" / "paper";
  const testing::DeckTempDir scratch;
  const fs::path& dir = scratch.path();
  using testing::readText;
  auto replaced = [](std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
  };
  for (const auto& entry : fs::directory_iterator(src))
    if (entry.path().extension() == ".inc")
      fs::copy_file(entry.path(), dir / entry.path().filename(),
                    fs::copy_options::overwrite_existing);
  std::ofstream(dir / "six_story_workflow.inc")
      << replaced(readText(src / "six_story_workflow.inc"), "  GROUnd,,0,1e5\n",
                  "  GROUnd,,0,1e5\n  MEMBers,,1e5\n");
  std::ofstream(dir / "members.inp")
      << replaced(readText(src / "six_story_collapse_short.inp"), "tend = 30 ", "tend = 200 ");
  const testing::DeckResult ran = testing::runDeckFile(scratch, (dir / "members.inp").string());
  ASSERT_EQ(ran.outcome.exitCode, 0) << ran.outcome.message;
  const std::string& log = ran.log;
  EXPECT_NE(log.find("M e m b e r   C o n t a c t"), std::string::npos);
  EXPECT_NE(log.find("debris:"), std::string::npos);
  EXPECT_EQ(log.find("warning: members"), std::string::npos) << log.substr(log.find("debris:"));
}

TEST(CollapseDecks, SchemeComparison) {
  // Two runs of the jointed double pendulum: Newmark, then the conserving scheme.
  Columns newmark = runAndRead("collapse/double_pendulum.inp", "double_pendulum_1");
  Columns conserving = runAndRead("collapse/double_pendulum.inp", "double_pendulum_2");
  ASSERT_EQ(newmark["time"].size(), 300u);
  ASSERT_EQ(conserving["time"].size(), 300u);
  const double released = 9.81 * 3.0;  // potential energy scale: rods of unit mass, L = 1
  const double dNewmark = relativeDrift(newmark["total"], released);
  const double dConserving = relativeDrift(conserving["total"], released);
  EXPECT_LT(dConserving, 1e-10);
  EXPECT_GT(dNewmark, 1e4 * dConserving);
  // The free end falls by nearly the whole length of the chain.
  EXPECT_LT(*std::min_element(conserving["disp_10_2"].begin(), conserving["disp_10_2"].end()), -1.9);
}


// A double pendulum of two jointed rods released horizontal, under the
// conserving mid-point scheme at h = 0.06 s: in its fastest swings Newton's
// method from the constant-velocity prediction diverges. AUTO,CUT,dtmin,1 cuts
// those steps (a half step from the prediction) instead of starting them again
// from the committed state, AUTO,CUT,dtmin,0 starts them again; at the
// smallest step (dtmin = h) the restart stays. Energy is kept to round-off
// either way.
std::string pendulumWithCutting(const std::string& autoRecord) {
  return "FEAP * * double pendulum, mid-point scheme, step cutting\n"
         "  0 0 0 2 3 2\n\n"
         "BLOCk\n  CARTesian 4 0 1 1 1\n  1 0 0\n  2 1 0\n\n"
         "BLOCk\n  CARTesian 4 0 6 5 1\n  1 1 0\n  2 2 0\n\n"
         "JOINt\n  5 6\n\n"
         "MATErial,1\n  FRAMe\n    RESUltant STIFfness 1e6 1e6 1e4\n"
         "    CROSs section 1 1e-4\n    DENSity,,1\n    FINIte\n\n"
         "BOUNdary\n  1 0 1 1 0\n\n"
         "GRAVity,,0,-9.81\n\n"
         "END\nBATCh\n  DYNAmic,ENERgy\n  " + autoRecord +
         "\n  DT,,0.06\n  TPLOt\n  LOOP,,100000\n    TIME,,4\n    LOOP,,20\n      TANG,,1\n"
         "    NEXT\n  NEXT\nEND\nener\n\nSTOP\n";
}

TEST(CollapseDecks, DivergingPredictionCutsTheStepWhenAsked) {
  const testing::DeckTempDir dir;
  struct Run {
    int diverged = 0, restarts = 0, cuts = 0;
    double drift = 0;
  };
  auto run = [&](const std::string& name, const std::string& autoRecord) {
    const auto r = testing::runDeckText(dir, name + ".inp", pendulumWithCutting(autoRecord));
    EXPECT_EQ(r.outcome.exitCode, 0) << r.console;
    Run out;
    for (std::size_t p = 0; (p = r.log.find("(the predicted start diverges)", p)) != std::string::npos; ++p)
      ++out.diverged;
    for (std::size_t p = 0; (p = r.log.find("the step starts again from the committed state\n", p)) !=
                            std::string::npos;
         ++p)
      ++out.restarts;
    for (std::size_t p = 0; (p = r.log.find("  cut    step to dt", p)) != std::string::npos; ++p)
      ++out.cuts;
    const auto csv = testing::readCsv(r.out / (name + "_tplot.csv"));
    const auto total = csv.column("total");
    const auto kinetic = csv.column("kinetic");
    EXPECT_FALSE(total.empty());
    if (!total.empty())
      out.drift = relativeDrift(total, *std::max_element(kinetic.begin(), kinetic.end()));
    return out;
  };
  const Run cut = run("cut", "AUTO,CUT,0.06/64,1");
  const Run restart = run("restart", "AUTO,CUT,0.06/64,0");
  const Run smallest = run("smallest", "AUTO,CUT,0.06,1");
  EXPECT_GT(cut.diverged, 0);
  EXPECT_EQ(cut.cuts, cut.diverged);
  EXPECT_EQ(cut.restarts, 0);
  EXPECT_EQ(restart.diverged, 0);
  EXPECT_GT(restart.restarts, 0);
  EXPECT_EQ(restart.cuts, 0);
  EXPECT_EQ(smallest.diverged, 0);
  EXPECT_GT(smallest.restarts, 0);
  for (const Run* r : {&cut, &restart, &smallest}) EXPECT_LT(r->drift, 1e-10);
}

}  // namespace
}  // namespace c2d
