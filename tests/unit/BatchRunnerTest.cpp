// Batch runs (collapse2d run): every deck in a child process, at most N at
// once; a failing deck does not stop the others, the results come back in deck
// order with their figures, the table lists every deck, the exit status is the
// first failure's; decks whose outputs would collide are refused.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "macro/batch/BatchRunner.h"
#include "macro/DeckRunner.h"
#include "macro/run/Interrupt.h"
#include "tests/unit/OutputTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;

const std::string kParams = "PARAmeter\n  L = 3\n  n = 2\n  P = 10\n\n";

TEST(Batch, FailingDeckDoesNotStopTheOthers) {
  DeckTempDir dir;
  const std::string good = kParams + testing::rampProblem(3, "", "");
  const std::string a = dir.write("a.inp", good);
  const std::string bad =
      dir.write("bad.inp", kParams + testing::cantileverProblem("  TANX,,1\n", ""));
  const std::string c = dir.write("c.inp", good);
  BatchOptions o;
  o.deck.outDir = dir.path() / "out";
  o.jobs = 2;
  const SolutionCommands commands;
  std::ostringstream out;
  const auto results = runBatch({a, bad, c}, o, deckCalls(commands), out);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results[0].deck, a);
  EXPECT_TRUE(results[0].ok()) << results[0].output;
  EXPECT_EQ(results[0].steps, 3);
  EXPECT_EQ(results[0].runs, 1);
  EXPECT_GE(results[0].iterations, 3);
  EXPECT_FALSE(results[1].ok());
  EXPECT_EQ(results[1].exitCode, kExitDeckError);
  EXPECT_EQ(results[1].status(), "deck error");
  // A deck's error goes to standard error, as a run's does, not to the summaries.
  EXPECT_NE(results[1].errors.find("unknown solution command 'TANX'"), std::string::npos) << results[1].errors;
  EXPECT_EQ(results[1].output.find("unknown solution command 'TANX'"), std::string::npos) << results[1].output;
  EXPECT_TRUE(results[2].ok()) << results[2].output;
  EXPECT_EQ(batchExitCode(results), kExitDeckError);
  // The other decks ran to the end.
  EXPECT_TRUE(std::filesystem::exists(o.deck.outDir / "a_tplot.csv"));
  EXPECT_TRUE(std::filesystem::exists(o.deck.outDir / "c_tplot.csv"));
  // Each child's console output reaches the batch's, in one piece (its errors
  // the batch's standard error).
  EXPECT_EQ(out.str().find("unknown solution command 'TANX'"), std::string::npos);
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
  const std::string good = dir.write("g.inp", kParams + testing::rampProblem(1, "", ""));
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
  EXPECT_EQ(batchExitCode(runBatch({good}, o, deckCalls(commands), out)), 0);
  const auto r = runBatch({good, failing}, o, deckCalls(commands), out);
  EXPECT_TRUE(r[0].ok());
  EXPECT_EQ(r[1].exitCode, kExitAnalysisFailed) << r[1].output;
  EXPECT_EQ(batchExitCode(r), kExitAnalysisFailed);
}

// A loading in a hundred million steps: it runs until it is stopped.
std::string endlessDeck() { return kParams + testing::rampProblem(100000000, "", ""); }

TEST(Batch, TimeoutStopsAHangingDeckAndTheTableSaysSo) {
  DeckTempDir dir;
  const std::string endless = dir.write("endless.inp", endlessDeck());
  const std::string good = dir.write("g.inp", kParams + testing::rampProblem(1, "", ""));
  BatchOptions o;
  o.deck.outDir = dir.path() / "out";
  o.deck.quiet = true;
  o.jobs = 2;
  o.timeout = 1.0;
  const SolutionCommands commands;
  std::ostringstream out;
  const auto r = runBatch({endless, good}, o, deckCalls(commands), out);
  EXPECT_TRUE(r[0].timedOut);
  EXPECT_EQ(r[0].status(), "timed out");
  EXPECT_EQ(r[0].exitCode, kExitTimedOut);
  EXPECT_GE(r[0].seconds, 1.0);
  EXPECT_LT(r[0].seconds, 1.0 + kGraceSeconds);  // it stopped at SIGTERM, not SIGKILL
  EXPECT_TRUE(r[1].ok()) << r[1].output;
  EXPECT_EQ(batchExitCode(r), kExitTimedOut);
  EXPECT_NE(out.str().find("endless.inp: timed out after 1 s"), std::string::npos) << out.str();
  // The stopped deck kept what it computed.
  EXPECT_TRUE(std::filesystem::exists(o.deck.outDir / "endless.interrupted.out"));
  EXPECT_TRUE(std::filesystem::exists(o.deck.outDir / "endless_tplot.interrupted.csv"));
  std::ostringstream table;
  printBatchTable(table, r);
  EXPECT_NE(table.str().find("timed out"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("(1 timed out)"), std::string::npos) << table.str();
}

TEST(Batch, SignalToTheBatchStopsEveryRunningDeck) {
  // The batch in a process of its own (it installs the handlers, as main does);
  // SIGTERM to it reaches both running decks, the third is not started, and the
  // table says which were interrupted.
  DeckTempDir dir;
  const std::string e1 = dir.write("e1.inp", endlessDeck());
  const std::string e2 = dir.write("e2.inp", endlessDeck());
  const std::string g = dir.write("g.inp", kParams + testing::rampProblem(1, "", ""));
  const std::filesystem::path outDir = dir.path() / "out";
  const std::filesystem::path tableFile = dir.path() / "table.txt";
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    installInterruptHandlers();
    BatchOptions o;
    o.deck.outDir = outDir;
    o.deck.quiet = true;
    o.jobs = 2;
    const SolutionCommands commands;
    std::ostringstream out;
    const auto r = runBatch({e1, e2, g}, o, deckCalls(commands), out);
    std::ostringstream table;
    printBatchTable(table, r);
    std::ofstream(tableFile) << table.str() << out.str();
    ::_exit(pendingInterrupt() ? interruptExitCode(pendingInterrupt()) : batchExitCode(r));
  }
  // Both decks have started their logs.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while ((testing::partFileOf(outDir / "e1.out").empty() || testing::partFileOf(outDir / "e2.out").empty()) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  std::ifstream in(tableFile);
  const std::string table((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The table's row of a deck.
  auto row = [&](const std::string& deck) {
    const auto b = table.find(deck + " ");
    return b == std::string::npos ? std::string() : table.substr(b, table.find('\n', b) - b);
  };
  EXPECT_NE(row(e1).find("interrupted (SIGTERM)"), std::string::npos) << table;
  EXPECT_NE(row(e2).find("interrupted (SIGTERM)"), std::string::npos) << table;
  EXPECT_NE(row(g).find("not run"), std::string::npos) << table;
  EXPECT_NE(table.find("interrupted: 2 stopped, 1 not run"), std::string::npos) << table;
  // Each deck stopped at a step of its own and kept its outputs: the children
  // ended (the batch waited for them) and left nothing half-written.
  for (const char* stem : {"e1", "e2"}) {
    EXPECT_TRUE(std::filesystem::exists(outDir / (std::string(stem) + ".interrupted.out"))) << stem;
    EXPECT_TRUE(testing::partFileOf(outDir / (std::string(stem) + ".out")).empty()) << stem;
  }
}

TEST(Batch, CollidingOutputsAreRefused) {
  EXPECT_EQ(batchStemClash({"a/x.inp", "b/y.inp"}), "");
  EXPECT_NE(batchStemClash({"a/x.inp", "b/x.inp"}).find("a/x.inp and b/x.inp"), std::string::npos);
}

}  // namespace
}  // namespace c2d
