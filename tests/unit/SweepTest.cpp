// SWEEp (concise parameter study): parsing (zipped variables, errors at their
// place), file tags and legend labels, a sweep deck whose runs write tagged
// outputs with the closed-form results and whose PLOT,CURVe is overlaid with a
// legend entry per run; parameters derived after the sweep; FEAP's top-level
// LOOP study keeps its numbered runs and gets an overlay labelled by the
// parameter that changes; repeated tags inside a loop get run numbers.
#include <gtest/gtest.h>

#include <fstream>

#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/draws/Sweep.h"
#include "tests/unit/OutputTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;
using testing::readText;
using testing::XmlNode;
using testing::XmlReader;

// The last value of a column of a TPLOt file.
double lastValue(const std::filesystem::path& csv, std::size_t column) {
  std::ifstream in(csv);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::size_t pos = 0;
  for (std::size_t c = 0; c < column; ++c) pos = last.find(',', pos) + 1;
  return std::stod(last.substr(pos));
}

std::vector<std::string> legend(const XmlNode& svg) {
  std::vector<std::string> out;
  for (const XmlNode* g : svg.all("g", "legend"))
    for (const XmlNode* t : g->all("text")) out.push_back(t->text);
  return out;
}

const std::string kCurve = "disp_3_2 reac_1_2 deflection_[m] load_[kN]\n";

TEST(Sweep, TagsAndLabels) {
  EXPECT_EQ(formatSweepValue(-393), "-393");
  EXPECT_EQ(formatSweepValue(0.001), "0.001");
  EXPECT_EQ(formatSweepValue(2.5e-7), "2.5e-07");
  EXPECT_EQ(formatSweepValue(-0.0), "0");
  const SweepValues v = {{"ks", -393}, {"Mu", 120.5}};
  EXPECT_EQ(sweepTag(v), "ks=-393_Mu=120.5");
  EXPECT_EQ(sweepLabel(v), "ks = -393, Mu = 120.5");
}

TEST(Sweep, ParsesZippedVariables) {
  const Deck d = parseDeckText(
      "SWEEp\n  ks = -393 -500 2*-350\n  mu = 100 110 120\n\nPARAmeter\n  k2 = 2*ks\n\n"
      "FEAP * * t\n  0 0 0 2 3 2\nEND\nBATCh\nEND\nSTOP\n",
      "s.inp");
  ASSERT_EQ(d.items.size(), 1u);
  const auto& sw = std::get<TopSweep>(d.items[0]);
  Parameters p;
  EXPECT_EQ(sweepRuns(sw, p).size(), 3u);
  ASSERT_EQ(sw.variables.size(), 2u);
  EXPECT_EQ(sw.variables[0].name, "ks");
  EXPECT_DOUBLE_EQ(sweepValues(sw.variables[0], p)[2], -700);
  ASSERT_EQ(sw.body.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<ParamBlock>(sw.body[0]));
  EXPECT_TRUE(std::holds_alternative<Problem>(sw.body[1]));
}

TEST(Sweep, ErrorsAtTheirPlace) {
  using testing::expectDeckError;
  expectDeckError([] { parseDeckText("SWEEp\n  ks = 1 2 3\n  mu = 1 2\n\nFEAP * * t\n 0 0 0 2 3 2\nEND\n", "s.inp"); },
                  "s.inp", 3, 3, "the variables of a sweep are zipped");
  expectDeckError([] { parseDeckText("SWEEp\n  ks =\n\nFEAP * * t\n 0 0 0 2 3 2\nEND\n", "s.inp"); }, "s.inp", 2,
                  7, "has no values");
  expectDeckError([] { parseDeckText("SWEEp\n  ks = 1 2\n\nSTOP\n", "s.inp"); }, "s.inp", 4, 1,
                  "must be followed by the problem it applies to");
  expectDeckError([] { parseDeckText("SWEEp\n  ks = 1 2\nFEAP * * t\n", "s.inp"); }, "s.inp", 3, 1,
                  "SWEEp block (line 1) is not ended by a blank record");
  expectDeckError([] { parseDeckText("SWEEp\n  ks = 1 2\n  KS = 3 4\n\nFEAP * * t\n 0 0 0 2 3 2\nEND\n", "s.inp"); },
                  "s.inp", 3, 3, "swept twice");
}

// Long sweeps: ranges lo:step:hi and records that continue a variable's values.
TEST(Sweep, RangesAndContinuationRecords) {
  const Deck d = parseDeckText(
      "SWEEp\n  x = 0:0.01:0.99\n  y = 1 2 -0.5:0.5:47\n      2*2 k\n\n"
      "FEAP * * t\n  0 0 0 2 3 2\nEND\nBATCh\nEND\nSTOP\n",
      "s.inp");
  const auto& sw = std::get<TopSweep>(d.items[0]);
  Parameters p;
  p.set("k", 7);
  const std::vector<double> x = sweepValues(sw.variables[0], p);
  ASSERT_EQ(x.size(), 100u);
  EXPECT_EQ(x[0], 0);
  EXPECT_EQ(x[99], 0.99);  // the end itself, not 0.99000000000000010
  EXPECT_DOUBLE_EQ(x[37], 0.37);
  const std::vector<double> y = sweepValues(sw.variables[1], p);
  ASSERT_EQ(y.size(), 100u);  // 1, 2, 96 values -0.5 ... 47, 4, 7
  EXPECT_EQ(y[2], -0.5);
  EXPECT_EQ(y[97], 47);
  EXPECT_EQ(y[98], 4);
  EXPECT_EQ(y[99], 7);
  EXPECT_EQ(sweepRuns(sw, p).size(), 100u);
  // Downward, and a step that does not land on the end.
  const Deck down = parseDeckText("SWEEp\n  t = 1:-0.25:0 3:2:8\n\nFEAP * * t\n  0 0 0 2 3 2\nEND\nSTOP\n", "s.inp");
  EXPECT_EQ(sweepValues(std::get<TopSweep>(down.items[0]).variables[0], p),
            (std::vector<double>{1, 0.75, 0.5, 0.25, 0, 3, 5, 7}));
}

TEST(Sweep, RangeErrorsAtTheirPlace) {
  using testing::expectDeckError;
  const std::string tail = "\n\nFEAP * * t\n 0 0 0 2 3 2\nEND\nSTOP\n";
  expectDeckError([&] { parseDeckText("SWEEp\n  x = 0:1" + tail, "s.inp"); }, "s.inp", 2, 7,
                  "a range of sweep values is lo:step:hi");
  expectDeckError([&] { parseDeckText("SWEEp\n  x = 0::1" + tail, "s.inp"); }, "s.inp", 2, 9,
                  "a part of the range '0::1' is empty");
  expectDeckError([&] { parseDeckText("SWEEp\n  1 2 3" + tail, "s.inp"); }, "s.inp", 2, 3,
                  "expected 'name = v1 v2 ...'");
  auto values = [&](const std::string& range) {
    const Deck d = parseDeckText("SWEEp\n  x = " + range + tail, "s.inp");
    Parameters p;
    return sweepValues(std::get<TopSweep>(d.items[0]).variables[0], p);
  };
  expectDeckError([&] { values("0:0:1"); }, "s.inp", 2, 9, "needs a finite step other than 0");
  expectDeckError([&] { values("0:-1:1"); }, "s.inp", 2, 9, "steps away from its end");
  expectDeckError([&] { values("0:1e-9:1"); }, "s.inp", 2, 9, "more values than this program runs");
  // Zipped with a range: the counts are compared when the values are known.
  const Deck d = parseDeckText("SWEEp\n  x = 0:1:4\n  y = 1 2" + tail, "s.inp");
  Parameters p;
  expectDeckError([&] { sweepRuns(std::get<TopSweep>(d.items[0]), p); }, "s.inp", 3, 3,
                  "'y' has 2 values and 'x' (line 2) 5");
}

TEST(Sweep, TaggedOutputsAndOverlay) {
  DeckTempDir dir;
  const std::string deck = "PARAmeter\n  L = 3\n  n = 2\n\nSWEEp\n  P = 10 20 2*15\n\n" +
                           testing::cantileverProblem(testing::rampBatch(2, "", "  PLOT,CURVe,-1\n"),
                                                      testing::rampData(kCurve)) +
                           "STOP\n";
  const auto r = testing::runDeckText(dir, "sw.inp", deck, false);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  EXPECT_EQ(r.outcome.runs, 3);
  for (double P : {10.0, 20.0, 30.0}) {
    const std::string stem = "sw_P=" + formatSweepValue(P);
    EXPECT_NEAR(lastValue(r.out / (stem + "_tplot.csv"), 2), testing::cantileverTip(P, 3, 2), 1e-12) << stem;
    EXPECT_TRUE(std::filesystem::exists(r.out / (stem + "_reac_1_2_vs_disp_3_2.svg"))) << stem;
    EXPECT_NE(r.console.find("  " + stem + ": 2 steps"), std::string::npos) << r.console;
  }
  const XmlNode overlay = XmlReader::parse(readText(r.out / "sw_reac_1_2_vs_disp_3_2.svg"));
  EXPECT_EQ(overlay.all("path", "series").size(), 3u);  // one curve per run
  EXPECT_EQ(legend(overlay), (std::vector<std::string>{"P = 10", "P = 20", "P = 30"}));
  EXPECT_NE(r.console.find("sw.inp: 3 runs, 6 steps"), std::string::npos) << r.console;
}

TEST(Sweep, ParametersAfterTheSweepDeriveFromIt) {
  DeckTempDir dir;
  // The load P = 2 q, with q swept.
  const std::string deck =
      "PARAmeter\n  L = 3\n  n = 2\n\nSWEEp\n  q = 5 10\n\nPARAmeter\n  P = 2*q\n\n" +
      testing::rampProblem(1, "", "");
  const auto r = testing::runDeckText(dir, "d.inp", deck);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  EXPECT_NEAR(lastValue(r.out / "d_q=5_tplot.csv", 2), testing::cantileverTip(10, 3, 2), 1e-12);
  EXPECT_NEAR(lastValue(r.out / "d_q=10_tplot.csv", 2), testing::cantileverTip(20, 3, 2), 1e-12);
  EXPECT_FALSE(std::filesystem::exists(r.out / "d_reac_1_2_vs_disp_3_2.svg"));  // no PLOT, no overlay
}

TEST(Sweep, TopLevelLoopStudyKeepsNumberedRunsAndGetsAnOverlay) {
  DeckTempDir dir;
  // FEAP's idiom: LOOP around the problem, PARAmeter block inside changing n.
  const std::string deck = "PARAmeter\n  L = 3\n  P = 10\n  n = 1\n\nLOOP,,3\n" +
                           testing::cantileverProblem(testing::rampBatch(1, "", "  PLOT,CURVe\n"),
                                                      testing::rampData("time reac_1_2\n")) +
                           "PARAmeter\n  n = 2*n\n\nNEXT\nSTOP\n";
  const auto r = testing::runDeckText(dir, "lp.inp", deck);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  const int nodes[] = {2, 3, 5};
  for (int k = 1; k <= 3; ++k) {
    const int n = nodes[k - 1] - 1;
    EXPECT_NEAR(lastValue(r.out / ("lp_" + std::to_string(k) + "_tplot.csv"), 2),
                testing::cantileverTip(10, 3, n), 1e-12);
  }
  const XmlNode overlay = XmlReader::parse(readText(r.out / "lp_reac_1_2_vs_time.svg"));
  EXPECT_EQ(overlay.all("path", "series").size(), 3u);
  EXPECT_EQ(legend(overlay), (std::vector<std::string>{"n = 1", "n = 2", "n = 4"}));
}

TEST(Sweep, RepeatedTagsInsideALoopGetRunNumbers) {
  DeckTempDir dir;
  const std::string deck = "PARAmeter\n  L = 3\n  n = 1\n\nLOOP,,2\nSWEEp\n  P = 1 2\n\n" +
                           testing::rampProblem(1, "", "") + "NEXT\nSTOP\n";
  const auto r = testing::runDeckText(dir, "rep.inp", deck);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  for (const char* stem : {"rep_1_P=1", "rep_2_P=2", "rep_3_P=1", "rep_4_P=2"})
    EXPECT_TRUE(std::filesystem::exists(r.out / (std::string(stem) + "_tplot.csv"))) << stem;
}

}  // namespace
}  // namespace c2d
