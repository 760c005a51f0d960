// Batch runs (collapse2d run): every deck in a child process, at most N at
// once; a failing deck does not stop the others, the results come back in deck
// order with their figures, the table lists every deck, the exit status is the
// first failure's; decks whose outputs would collide are refused.
#include <gtest/gtest.h>

#include <sstream>

#include "macro/BatchRunner.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;

const std::string kParams = "PARAmeter\n  L = 3\n  n = 2\n  P = 10\n\n";

TEST(Batch, FailingDeckDoesNotStopTheOthers) {
  DeckTempDir dir;
  const std::string good = kParams + testing::cantileverProblem(testing::rampBatch(3, "", ""), testing::rampData());
  const std::string a = dir.write("a.inp", good);
  const std::string bad = dir.write("bad.inp", kParams + testing::cantileverProblem("  TANX,,1\n", ""));
  const std::string c = dir.write("c.inp", good);
  BatchOptions o;
  o.deck.outDir = dir.path() / "out";
  o.jobs = 2;
  const SolutionCommands commands;
  std::ostringstream out;
  const auto results = runBatch({a, bad, c}, o, commands, out);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results[0].deck, a);
  EXPECT_TRUE(results[0].ok()) << results[0].output;
  EXPECT_EQ(results[0].steps, 3);
  EXPECT_EQ(results[0].runs, 1);
  EXPECT_GE(results[0].iterations, 3);
  EXPECT_FALSE(results[1].ok());
  EXPECT_EQ(results[1].exitCode, kExitDeckError);
  EXPECT_EQ(results[1].status(), "deck error");
  EXPECT_NE(results[1].output.find("unknown solution command 'TANX'"), std::string::npos) << results[1].output;
  EXPECT_TRUE(results[2].ok()) << results[2].output;
  EXPECT_EQ(batchExitCode(results), kExitDeckError);
  // The other decks ran to the end.
  EXPECT_TRUE(std::filesystem::exists(o.deck.outDir / "a_tplot.csv"));
  EXPECT_TRUE(std::filesystem::exists(o.deck.outDir / "c_tplot.csv"));
  // Each child's console output reaches the batch's, in one piece.
  EXPECT_NE(out.str().find("unknown solution command 'TANX'"), std::string::npos);
  EXPECT_NE(out.str().find(a + ": 3 steps"), std::string::npos) << out.str();

  std::ostringstream table;
  printBatchTable(table, results);
  const std::string t = table.str();
  for (const std::string& d : {a, bad, c}) EXPECT_NE(t.find(d), std::string::npos) << t;
  EXPECT_NE(t.find("deck error"), std::string::npos) << t;
  EXPECT_NE(t.find("3 decks: 2 ok, 1 failed"), std::string::npos) << t;
}

TEST(Batch, AllGoodIsExitZeroAndAnalysisFailureIsTwo) {
  DeckTempDir dir;
  const std::string good =
      dir.write("g.inp", kParams + testing::cantileverProblem(testing::rampBatch(1, "", ""), testing::rampData()));
  // One Newton iteration of a loop that never converges (tolerance 0 is refused,
  // so ask for an impossible one): the analysis fails with status 2.
  const std::string failing = dir.write(
      "nc.inp", kParams + testing::cantileverProblem("  TOL,,1e-300\n  PROP,,1\n  DT,,1\n  TIME\n"
                                                     "  LOOP,,1\n    TANG,,1\n  NEXT\n",
                                                     "\n"));
  BatchOptions o;
  o.deck.outDir = dir.path() / "out";
  o.deck.quiet = true;
  const SolutionCommands commands;
  std::ostringstream out;
  EXPECT_EQ(batchExitCode(runBatch({good}, o, commands, out)), 0);
  const auto r = runBatch({good, failing}, o, commands, out);
  EXPECT_TRUE(r[0].ok());
  EXPECT_EQ(r[1].exitCode, kExitAnalysisFailed) << r[1].output;
  EXPECT_EQ(batchExitCode(r), kExitAnalysisFailed);
}

TEST(Batch, CollidingOutputsAreRefused) {
  EXPECT_EQ(batchStemClash({"a/x.inp", "b/y.inp"}), "");
  EXPECT_NE(batchStemClash({"a/x.inp", "b/x.inp"}).find("a/x.inp and b/x.inp"), std::string::npos);
}

}  // namespace
}  // namespace c2d
