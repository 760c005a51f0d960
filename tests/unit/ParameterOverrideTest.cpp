// Values given from outside the deck (--set NAME=VALUE, collapse2d.run's
// params): they replace what the deck's PARAmeter records assign, what derives
// from them follows, and a name the deck does not assign or a study sets for
// each run is refused with its reason.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "macro/DeckRunner.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Record.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;

Field fieldAt(const std::string& text, int line) { return Field{text, {"d.inp", line, 3}}; }

TEST(ParameterOverride, TheGivenValueTakesTheRecordsPlace) {
  Parameters p;
  p.setOverrides({{"P", 30}});
  EXPECT_TRUE(p.overridden("p"));
  EXPECT_EQ(p.overridesUnused(), (std::vector<std::string>{"p"}));
  Parameters copy = p;  // as a problem's run copies the table
  copy.assign("p", 10, fieldAt("p", 4));
  copy.assign("q", 2 * copy.get("p"), fieldAt("q", 5));
  EXPECT_EQ(copy.get("P"), 30);
  EXPECT_EQ(copy.get("q"), 60);
  EXPECT_EQ(copy.origin("p")->line, 4);      // errors still point at the deck's record
  EXPECT_TRUE(p.overridesUnused().empty());  // the copies share the record of use
  Parameters plain;
  plain.assign("p", 10, fieldAt("p", 4));
  EXPECT_EQ(plain.get("p"), 10);
}

struct Given {
  DeckOutcome outcome;
  std::string log;
  std::filesystem::path out;
};

Given runGiven(const DeckTempDir& dir, const std::string& text,
               std::map<std::string, double> given) {
  const std::string path = dir.write("d.inp", text);
  DeckOptions o;
  o.outDir = dir.path() / "out";
  o.quiet = true;
  o.params = std::move(given);
  const SolutionCommands commands;
  std::ostringstream console;
  Given g{runDeck(path, o, commands, console), {}, o.outDir};
  g.log = testing::readText(o.outDir / "d.out");
  return g;
}

double lastTip(const std::filesystem::path& csv) {
  return testing::readCsv(csv).column("disp_3_2").back();
}

const std::string kCantilever = "PARAmeter\n  L = 3\n  n = 2\n  q = 5\n  P = 2*q\n\n" +
                                testing::rampProblem(1, "", "") + "STOP\n";

TEST(ParameterOverride, ARunTakesTheGivenValueAndWhatDerivesFromIt) {
  DeckTempDir dir;
  const Given g = runGiven(dir, kCantilever, {{"q", 15}});
  ASSERT_EQ(g.outcome.exitCode, 0) << g.outcome.message;
  // P = 2 q = 30 at the tip of the 3 m cantilever, in closed form.
  EXPECT_NEAR(lastTip(g.out / "d_tplot.csv"), testing::cantileverTip(30, 3, 2), 1e-12);
  EXPECT_NE(g.log.find("given: q = 15 (in place of the deck's value)"), std::string::npos) << g.log;
  const Given plain = runGiven(dir, kCantilever, {});
  EXPECT_NEAR(lastTip(plain.out / "d_tplot.csv"), testing::cantileverTip(10, 3, 2), 1e-12);
}

TEST(ParameterOverride, ANameTheDeckDoesNotAssignIsAUsageError) {
  DeckTempDir dir;
  const Given g = runGiven(dir, kCantilever, {{"qq", 15}});
  EXPECT_EQ(g.outcome.exitCode, kExitUsage);
  EXPECT_NE(g.outcome.message.find("parameter 'qq' is given"), std::string::npos)
      << g.outcome.message;
  EXPECT_NE(g.outcome.message.find("did you mean 'q'"), std::string::npos) << g.outcome.message;
  EXPECT_FALSE(std::filesystem::exists(g.out / "d_tplot.csv"));  // nothing computed
}

TEST(ParameterOverride, ASweptOrDrawnNameIsADeckErrorAtItsRecord) {
  DeckTempDir dir;
  const std::string swept = "PARAmeter\n  L = 3\n  n = 2\n\nSWEEp\n  P = 5 10\n\n" +
                            testing::rampProblem(1, "", "") + "STOP\n";
  const Given g = runGiven(dir, swept, {{"P", 15}});
  EXPECT_EQ(g.outcome.exitCode, kExitDeckError);
  ASSERT_TRUE(g.outcome.errorAt.has_value());
  EXPECT_EQ(g.outcome.errorAt->line, 6);
  EXPECT_NE(g.outcome.message.find("'P' is swept by this study"), std::string::npos)
      << g.outcome.message;
  const std::string drawn = "PARAmeter\n  L = 3\n  n = 2\n\nENSEmble,,2,1\n  P = UNIForm 5 10\n\n" +
                            testing::rampProblem(1, "", "") + "STOP\n";
  const Given h = runGiven(dir, drawn, {{"P", 15}});
  EXPECT_EQ(h.outcome.exitCode, kExitDeckError);
  ASSERT_TRUE(h.outcome.errorAt.has_value());
  EXPECT_EQ(h.outcome.errorAt->line, 6);
  EXPECT_NE(h.outcome.message.find("'P' is drawn by this study"), std::string::npos)
      << h.outcome.message;
}

}  // namespace
}  // namespace c2d
