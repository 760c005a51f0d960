// Named plans (SWEEp's PLAN record) and blasts switched off (BLASt's ON field):
// the names in stems, tables, legends and the study's table; their errors at
// their place; legends and titles that fit their picture.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "macro/output/SvgChart.h"
#include "macro/DeckRunner.h"
#include "macro/studies/EnsembleTable.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/OutputTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;

// The sliding block (decks/ensemble/sliding_block.inc) as a study of two named
// plans, two samples each.
std::string study(const std::string& sweep) {
  return "ENSEmble,,2,1\n  mu = UNIForm 0.2 0.6\n\nSWEEp\n" + sweep +
         "\n\nINCLude," C2D_SOURCE_DIR "/decks/ensemble/sliding_block.inc\n\nSTOP\n";
}

TEST(NamedPlans, NamesAreTheStemsLabelsAndTheTablesColumn) {
  DeckTempDir dir;
  const testing::DeckResult r =
      testing::runDeckText(dir, "np.inp", study("  PLAN = gentle steep\n  a = 0.3 0.4"), false);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  for (const char* stem : {"np_gentle_s1", "np_gentle_s2", "np_steep_s1", "np_steep_s2"})
    EXPECT_TRUE(std::filesystem::exists(r.out / (std::string(stem) + "_tplot.csv"))) << stem;
  const EnsembleData d = readEnsembleTable(testing::readText(r.out / "np_ensemble.csv"), 1);
  EXPECT_TRUE(d.named);
  ASSERT_EQ(d.runs.size(), 4u);
  EXPECT_EQ(d.runs[0].name, "gentle");
  EXPECT_EQ(d.runs[3].name, "steep");
  EXPECT_EQ(d.swept, std::vector<std::string>{"a"});
  EXPECT_EQ(d.runs[3].swept, std::vector<double>{0.4});
  const std::string plans = testing::readText(r.out / "np_plans.csv");
  EXPECT_EQ(plans.rfind("plan,name,a,samples,", 0), 0u) << plans;
  EXPECT_NE(plans.find("\n2,steep,0.4,2,"), std::string::npos) << plans;
  EXPECT_EQ(testing::readText(r.out / "np_sensitivity.csv").rfind("plan,name,a,input", 0), 0u);
  // The console's plan table and verdict name the plans.
  EXPECT_NE(r.console.find("gentle"), std::string::npos) << r.console;
  EXPECT_NE(r.console.find("best plan: 1 (gentle)"), std::string::npos) << r.console;
}

TEST(NamedPlans, UnnamedStudiesKeepTheirTables) {
  DeckTempDir dir;
  const testing::DeckResult r = testing::runDeckText(dir, "un.inp", study("  a = 0.3 0.4"));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  EXPECT_TRUE(std::filesystem::exists(r.out / "un_a=0.3_s1_tplot.csv"));
  EXPECT_FALSE(readEnsembleTable(testing::readText(r.out / "un_ensemble.csv"), 1).named);
  EXPECT_EQ(testing::readText(r.out / "un_plans.csv").rfind("plan,a,samples,", 0), 0u);
}

TEST(NamedPlans, BadNamesAreDeckErrorsAtTheirPlace) {
  DeckTempDir dir;
  auto error = [&](const std::string& sweep) {
    return testing::runDeckText(dir, "bad.inp", study(sweep)).outcome.message;
  };
  EXPECT_NE(error("  PLAN = left left\n  a = 0.3 0.4")
                .find("bad.inp:5:15: error: plan name 'left' is given twice"),
            std::string::npos);
  EXPECT_NE(
      error("  PLAN = left\n  a = 0.3 0.4").find("bad.inp:6:3: error: 'a' has 2 values and 'PLAN'"),
      std::string::npos);
  EXPECT_NE(error("  PLAN = left right").find("a SWEEp of plan names alone"), std::string::npos);
  EXPECT_NE(error("  PLAN = 0:1:1 x\n  a = 0.3 0.4").find("is no plan name"), std::string::npos);
}

TEST(NamedPlans, ALongLegendEntryFitsItsPicture) {
  SvgChart chart;
  chart.setSize(400, 300);
  const std::string name(300, 'x');
  chart.addSeries(name, std::vector<std::pair<double, double>>{{0, 0}, {1, 1}});
  const std::string svg = chart.svg();
  const std::size_t at = svg.find(">" + name + "<");
  ASSERT_NE(at, std::string::npos);
  const std::size_t open = svg.rfind("<text", at);
  const std::string element = svg.substr(open, at - open);
  const std::size_t len = element.find("textLength=\"");
  ASSERT_NE(len, std::string::npos) << element;
  const double width = std::stod(element.substr(len + 12));
  const double x = std::stod(element.substr(element.find("x=\"") + 3));
  EXPECT_LE(x + width, 400.0) << element;
}

}  // namespace
}  // namespace c2d
