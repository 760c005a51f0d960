// PLOT (headless SVG): the mesh and deformed-shape pictures of a deck are
// well-formed SVG with one member path per element; the automatic displacement
// scale; PLOT,CURVe charts hold the TPLOt history (scale factors applied,
// closed-form values), are written when the command runs and completed at the
// end; deck errors are found before computing; --help knows the new commands.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "macro/output/SvgChart.h"
#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/Help.h"
#include "macro/run/ProblemRun.h"
#include "macro/run/RunOutputs.h"
#include "tests/unit/OutputTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;
using testing::readText;
using testing::XmlNode;
using testing::XmlReader;

const std::string kParams = "PARAmeter\n  L = 3\n  n = 4\n  P = 10\n\n";

// The points of an SVG path made of M/L commands.
int pathPoints(const std::string& d) {
  int n = 0;
  for (char c : d) n += c == 'M' || c == 'L';
  return n;
}

TEST(PlotCommand, MeshAndDeformedShapePictures) {
  DeckTempDir dir;
  const auto r = testing::runDeckText(
      dir, "beam.inp", kParams + testing::rampProblem(4, "  PLOT,MESH\n", "  PLOT,DEFOrmed\n"));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  const XmlNode mesh = XmlReader::parse(readText(r.out / "beam_mesh.svg"));
  EXPECT_EQ(mesh.name, "svg");
  EXPECT_EQ(mesh.all("path", "member").size(), 4u);  // one per element
  EXPECT_EQ(mesh.all("g", "nodes").at(0)->children.size(), 5u);
  EXPECT_EQ(mesh.all("path", "undeformed").size(), 0u);
  EXPECT_EQ(mesh.all("g", "supports").size(), 1u);

  // Step 4 is converged when PLOT runs (TIME has not committed it yet).
  const XmlNode def = XmlReader::parse(readText(r.out / "beam_deformed_0004.svg"));
  EXPECT_EQ(def.all("path", "member").size(), 4u);
  EXPECT_EQ(def.all("path", "undeformed").size(), 1u);
  // Tip deflection 1.9e-3 of a 3 m beam: automatic scale 1-2-5 drawing it at about L/10.
  const auto note = def.all("text", "scale-note");
  ASSERT_EQ(note.size(), 1u);
  const double scale = std::stod(note[0]->text.substr(note[0]->text.find("\xC3\x97") + 2));
  const double drawn = scale * std::abs(testing::cantileverTip(10, 3, 4));
  EXPECT_GT(drawn, 0.05 * 3);
  EXPECT_LT(drawn, 0.25 * 3);
  EXPECT_NE(r.log.find("PLOT   deformed shape: beam_deformed_0004.svg"), std::string::npos);
}

TEST(PlotCommand, AutomaticScale) {
  Model m;
  m.addNode(Vec2(0, 0));
  m.addNode(Vec2(10, 0));
  m.setElement(0, std::make_unique<testing::ReportingElement>(0, 1, 1));
  State s;
  s.resize(2);
  EXPECT_EQ(RunOutputs::automaticScale(m, s), 1.0);  // nothing to magnify
  s.u[4] = -0.01;
  EXPECT_EQ(RunOutputs::automaticScale(m, s), 100.0);  // 0.01 drawn as 1 = extent / 10
  s.u[4] = -0.03;
  const double k = RunOutputs::automaticScale(m, s);
  EXPECT_EQ(k, SvgChart::niceNumber(k, true));
  EXPECT_GT(k * 0.03, 0.5);
  EXPECT_LT(k * 0.03, 2.5);
  s.u[4] = -0.6;  // already 6 % of the extent: true scale
  EXPECT_EQ(RunOutputs::automaticScale(m, s), 1.0);
}

TEST(PlotCurve, ChartHoldsTheScaledHistory) {
  // Run one problem directly to read the plotted points back.
  DeckTempDir dir;
  const std::string path = dir.write(
      "c.inp", kParams + testing::cantileverProblem(
                             testing::rampBatch(4, "", "  PLOT,CURVe,-1,2\n"),
                             testing::rampData("disp_n+1_2 reac_1_2 tip_deflection_[m] twice_the_load\n")) +
                   "STOP\n");
  const Deck deck = parseDeck(path);
  Parameters params;
  std::get<ParamBlock>(deck.items[0]).apply(params);
  const SolutionCommands commands;
  std::ostringstream log;
  RunOptions ro;
  ro.outDir = dir.path();
  ro.stem = "c";
  ProblemRun run(std::get<Problem>(deck.items[1]), params, commands, ro, log);
  run.bind(false);
  run.run();
  const auto curves = run.outputs().curves(run.history());
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_EQ(curves[0].spec.xColumn, "disp_5_2");  // the node number as an expression, n = 4
  EXPECT_EQ(curves[0].spec.xLabel, "tip deflection [m]");
  EXPECT_EQ(curves[0].spec.yLabel, "twice the load");
  ASSERT_EQ(curves[0].points.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const double lambda = 0.25 * static_cast<double>(i + 1);
    EXPECT_NEAR(curves[0].points[i].first, -lambda * testing::cantileverTip(10, 3, 4), 1e-12);
    EXPECT_NEAR(curves[0].points[i].second, 2 * 10 * lambda, 1e-9);
  }
  const XmlNode svg = XmlReader::parse(readText(dir.path() / "c_reac_1_2_vs_disp_5_2.svg"));
  const auto series = svg.all("path", "series");
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(pathPoints(series[0]->attr("d")), 4);
  bool labelled = false;
  for (const XmlNode* t : svg.all("text")) labelled = labelled || t->text == "tip deflection [m]";
  EXPECT_TRUE(labelled);
}

TEST(PlotCurve, WrittenWhenRunAndCompletedAtTheEnd) {
  DeckTempDir dir;
  // Two steps, the plot, two more steps.
  const std::string batch = "  PROP,,1\n  DT,,0.25\n  TPLOt\n"
                            "  LOOP,,2\n    TIME\n    LOOP,,5\n      TANG,,1\n    NEXT\n  NEXT\n"
                            "  PLOT,CURVe\n"
                            "  LOOP,,2\n    TIME\n    LOOP,,5\n      TANG,,1\n    NEXT\n  NEXT\n";
  const auto r = testing::runDeckText(
      dir, "c.inp", kParams + testing::cantileverProblem(batch, testing::rampData("time disp_5_2\n")));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  // When PLOT ran, one step was committed (the second is committed by the next TIME).
  EXPECT_NE(r.log.find("PLOT   curve: c_disp_5_2_vs_time.svg"), std::string::npos) << r.log;
  const XmlNode svg = XmlReader::parse(readText(r.out / "c_disp_5_2_vs_time.svg"));
  ASSERT_EQ(svg.all("path", "series").size(), 1u);
  EXPECT_EQ(pathPoints(svg.all("path", "series")[0]->attr("d")), 4);
}

TEST(PlotCommand, DeckErrorsBeforeComputing) {
  DeckTempDir dir;
  struct Case {
    std::string batch, data, where, text;
  };
  const std::vector<Case> cases = {
      {"  PLOT,DEFX\n", "", ":29:8: error: ", "unknown PLOT kind 'DEFX'"},
      {"  PLOT,CURV\n", "disp_5_2 reac_9_2\n", ":41:10: error: ", "no TPLOt column 'reac_9_2'"},
      {"  PLOT,CURV\n", "disp_5_2 reac_1_2 u\n", ":41:19: error: ", "labels come as a pair"},
      {"  PLOT,CURV\n", "disp_5_2 force_1_2\n", ":41:10: error: ", "'force_1_2' is not a TPLOt column"},
  };
  for (const Case& c : cases) {
    const auto r = testing::runDeckText(
        dir, "e.inp", kParams + testing::cantileverProblem(testing::rampBatch(2, c.batch, ""), testing::rampData(c.data)));
    EXPECT_EQ(r.outcome.exitCode, kExitDeckError) << c.text;
    EXPECT_NE(r.outcome.message.find(c.where), std::string::npos) << r.outcome.message;
    EXPECT_NE(r.outcome.message.find(c.text), std::string::npos) << r.outcome.message;
    EXPECT_FALSE(std::filesystem::exists(r.out / "e_tplot.csv"));  // nothing computed
  }
  // A curve without any TPLOt in its problem.
  const auto r = testing::runDeckText(
      dir, "f.inp", kParams + testing::cantileverProblem("  TANG,,1\n  PLOT,CURV\n", "time prop\n"));
  EXPECT_EQ(r.outcome.exitCode, kExitDeckError);
  EXPECT_NE(r.outcome.message.find("this problem has no TPLOt"), std::string::npos) << r.outcome.message;
}

TEST(PlotCommand, HelpListsTheNewCommands) {
  const SolutionCommands commands;
  for (const char* word : {"PLOT", "PVIEw", "SWEEp"}) {
    std::ostringstream os;
    ASSERT_TRUE(printCommandHelp(os, commands, word)) << word;
    EXPECT_NE(os.str().find(word), std::string::npos);
  }
  std::ostringstream all;
  printAllHelp(all, commands);
  for (const char* text : {"PLOT,kind,p1,p2", "PVIEw,option,inc", "SWEEp", "name = v1 v2 ...",
                           "xcolumn ycolumn [xlabel ylabel]"})
    EXPECT_NE(all.str().find(text), std::string::npos) << text;
}

}  // namespace
}  // namespace c2d
