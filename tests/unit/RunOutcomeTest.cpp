// How a run ends, and what it leaves: a completed run has its log and
// collection under their names, and only it; a failed run keeps what it computed
// under names tagged "failed" (the time history of its converged steps, the
// collection, the log with the reason) and says so; an output that cannot be
// written (a full disk, a directory that cannot be made) is an I/O error with
// the path and the system's reason, exit status 3, and no file under the final
// name; SIGTERM stops a run at its next step with exit status 143 and its
// outputs tagged "interrupted". The summary's words: RunSummaryTest.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <thread>

#include "core/io/AtomicFile.h"
#include "macro/DeckRunner.h"
#include "macro/run/Interrupt.h"
#include "tests/unit/OutputTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

namespace fs = std::filesystem;
using testing::contains;
using testing::DeckTempDir;
using testing::readText;

const std::string kParams = "PARAmeter\n  L = 3\n  n = 2\n  P = 10\n\n";

// Three converged steps, then a step that cannot converge (tolerance 1e-300).
std::string failingDeck() {
  return kParams + testing::rampProblem(3, "  PVIEw,,1\n",
                                        "  TOL,,1e-300\n  TIME\n  LOOP,,1\n    TANG,,1\n  NEXT\n");
}

// A loading in a hundred million steps: it runs until it is stopped.
std::string endlessDeck() {
  return kParams + testing::rampProblem(100000000, "  PVIEw,,1000\n", "");
}

std::vector<std::string> partFiles(const fs::path& dir) {
  std::vector<std::string> parts;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".part") parts.push_back(e.path().filename().string());
  return parts;
}

int lineCount(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

TEST(RunOutcome, CompletedRunHasItsFilesUnderTheirNamesOnly) {
  DeckTempDir dir;
  const auto r =
      testing::runDeckText(dir, "ok.inp", kParams + testing::rampProblem(3, "  PVIEw,,1\n", ""));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  EXPECT_TRUE(contains(r.log, "run complete")) << r.log;
  EXPECT_TRUE(fs::exists(r.out / "ok_tplot.csv"));
  EXPECT_TRUE(fs::exists(r.out / "ok.pvd"));
  EXPECT_TRUE(partFiles(r.out).empty());
}

TEST(RunOutcome, FailedRunKeepsWhatItComputedUnderFailedNames) {
  DeckTempDir dir;
  const auto r = testing::runDeckText(dir, "fail.inp", failingDeck());
  ASSERT_EQ(r.outcome.exitCode, kExitAnalysisFailed) << r.outcome.message;
  const std::string& msg = r.outcome.message;
  EXPECT_TRUE(contains(msg, "computed results kept: ")) << msg;
  EXPECT_TRUE(contains(msg, "fail.failed.out")) << msg;
  EXPECT_TRUE(contains(msg, "fail_tplot.failed.csv")) << msg;
  EXPECT_TRUE(contains(msg, "fail.failed.pvd")) << msg;
  // Nothing that looks like a completed run.
  EXPECT_FALSE(fs::exists(r.out / "fail.out"));
  EXPECT_FALSE(fs::exists(r.out / "fail_tplot.csv"));
  EXPECT_FALSE(fs::exists(r.out / "fail.pvd"));
  EXPECT_TRUE(partFiles(r.out).empty());
  // The converged steps' rows: the header, the initial state and three steps.
  const std::string tplot = readText(r.out / "fail_tplot.failed.csv");
  EXPECT_GE(lineCount(tplot), 4) << tplot;
  const testing::XmlNode pvd = testing::XmlReader::parse(readText(r.out / "fail.failed.pvd"));
  EXPECT_EQ(pvd.all("DataSet").size(), 4u);
  const std::string log = readText(r.out / "fail.failed.out");
  EXPECT_TRUE(contains(log, "*** run failed")) << log;
  EXPECT_TRUE(contains(log, "did not converge")) << log;
  EXPECT_FALSE(contains(log, "run complete")) << log;
}

// A full disk under one file: every write to it fails with ENOSPC
// (SimulatedWriteFailure), so that the file's own code path meets the failure.

TEST(RunOutcome, FullDiskUnderTheLogIsAnIoError) {
  DeckTempDir dir;
  const SimulatedWriteFailure full("full.out", ENOSPC);
  const auto r = testing::runDeckText(dir, "full.inp", kParams + testing::rampProblem(2, "", ""));
  EXPECT_EQ(r.outcome.exitCode, kExitInternal);
  const std::string& msg = r.outcome.message;
  EXPECT_TRUE(contains(msg, "I/O error")) << msg;
  EXPECT_FALSE(contains(msg, "internal error")) << msg;
  EXPECT_TRUE(contains(msg, "full.out'")) << msg;
  EXPECT_TRUE(contains(msg, std::strerror(ENOSPC))) << msg;
  EXPECT_FALSE(fs::exists(r.out / "full.out"));
}

TEST(RunOutcome, FullDiskUnderTheTimeHistoryIsAnIoError) {
  DeckTempDir dir;
  const SimulatedWriteFailure full("tp_tplot.csv", ENOSPC);
  const auto r = testing::runDeckText(dir, "tp.inp", kParams + testing::rampProblem(2, "", ""));
  EXPECT_EQ(r.outcome.exitCode, kExitInternal);
  const std::string& msg = r.outcome.message;
  EXPECT_TRUE(contains(msg, "I/O error: cannot write")) << msg;
  EXPECT_TRUE(contains(msg, "tp_tplot.csv'")) << msg;
  EXPECT_TRUE(contains(msg, std::strerror(ENOSPC))) << msg;
  EXPECT_FALSE(fs::exists(r.out / "tp_tplot.csv"));
  EXPECT_FALSE(fs::exists(r.out / "tp.out"));
  EXPECT_TRUE(contains(readText(r.out / "tp.failed.out"), std::strerror(ENOSPC)));
}

TEST(RunOutcome, SingularTangentNamesTheNodeOfTheMechanism) {
  // decks/newton/mechanism.inp: a bar on two rollers under a horizontal force.
  // Each solver stops the run where the tangent is singular and names the
  // horizontal motion of node 2: the block LU and KLU by the dof of the zero
  // pivot; CHOLMOD ends with a round-off pivot, so the solve's check of
  // K du = R does it, by the largest component of the correction.
  const fs::path deck = fs::path(C2D_SOURCE_DIR) / "decks" / "newton" / "mechanism.inp";
  const std::pair<const char*, const char*> cases[] = {
      {"auto", "no stiffness at node 2, dof 1"},
      {"klu", "no stiffness at node 2, dof 1"},
      {"cholmod", "the solve leaves"},
  };
  for (const auto& [solver, report] : cases) {
    DeckTempDir dir;
    DeckOptions o;
    o.outDir = dir.path();
    o.quiet = true;
    o.solver = solver;
    const SolutionCommands commands;
    std::ostringstream console;
    const DeckOutcome r = runDeck(deck.string(), o, commands, console);
    EXPECT_EQ(r.exitCode, kExitAnalysisFailed) << solver;
    EXPECT_TRUE(contains(r.message, "singular tangent")) << solver << ": " << r.message;
    EXPECT_TRUE(contains(r.message, report)) << solver << ": " << r.message;
    EXPECT_TRUE(contains(r.message, "node 2, dof 1")) << solver << ": " << r.message;
  }
}

TEST(RunOutcome, OutputDirectoryThatCannotBeMadeIsAnIoError) {
  DeckTempDir dir;
  dir.write("plain", "a file where the output directory should be");
  const std::string deck = dir.write("d.inp", kParams + testing::rampProblem(1, "", ""));
  DeckOptions o;
  o.outDir = dir.path() / "plain" / "out";
  o.quiet = true;
  const SolutionCommands commands;
  std::ostringstream console;
  const DeckOutcome r = runDeck(deck, o, commands, console);
  EXPECT_EQ(r.exitCode, kExitInternal);
  EXPECT_TRUE(contains(r.message, "I/O error")) << r.message;
  EXPECT_TRUE(contains(r.message, "plain/out")) << r.message;
  EXPECT_TRUE(contains(r.message, std::strerror(ENOTDIR))) << r.message;
}

// Waits (at most `seconds`) until pred holds.
template <class Pred>
bool waitFor(Pred pred, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!pred()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

// The exit status of a child, -1 when it did not end within `seconds` (then killed).
int waitChild(pid_t pid, double seconds) {
  int status = 0;
  if (!waitFor([&] { return ::waitpid(pid, &status, WNOHANG) == pid; }, seconds)) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

TEST(RunOutcome, SigtermStopsTheRunWhichKeepsItsResults) {
  DeckTempDir dir;
  const std::string deck = dir.write("long.inp", endlessDeck());
  const fs::path out = dir.path() / "out";
  const fs::path messageFile = dir.path() / "message.txt";
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    installInterruptHandlers();
    DeckOptions o;
    o.outDir = out;
    o.quiet = true;
    const SolutionCommands commands;
    std::ostringstream console;
    const DeckOutcome r = runDeck(deck, o, commands, console);
    std::ofstream(messageFile) << r.message;
    ::_exit(r.exitCode);
  }
  // Stopped once it has written some steps.
  const bool running = waitFor(
      [&] {
        std::error_code ec;
        return fs::file_size(out / "long_0001.vtu", ec) > 0 && !ec;
      },
      60);
  ::kill(pid, SIGTERM);
  ASSERT_TRUE(running) << "the run wrote nothing";
  EXPECT_EQ(waitChild(pid, 60), 128 + SIGTERM);
  const std::string msg = readText(messageFile);
  EXPECT_TRUE(contains(msg, "interrupted by SIGTERM at step ")) << msg;
  EXPECT_TRUE(contains(msg, "computed results kept: ")) << msg;
  EXPECT_FALSE(fs::exists(out / "long.out"));
  EXPECT_FALSE(fs::exists(out / "long_tplot.csv"));
  EXPECT_FALSE(fs::exists(out / "long.pvd"));
  EXPECT_TRUE(partFiles(out).empty());
  const std::string log = readText(out / "long.interrupted.out");
  EXPECT_TRUE(contains(log, "*** run interrupted"))
      << log.substr(log.size() > 2000 ? log.size() - 2000 : 0);
  EXPECT_GT(lineCount(readText(out / "long_tplot.interrupted.csv")), 1000);
  const testing::XmlNode pvd = testing::XmlReader::parse(readText(out / "long.interrupted.pvd"));
  EXPECT_GE(pvd.all("DataSet").size(), 2u);
}

}  // namespace
}  // namespace c2d
