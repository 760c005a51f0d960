// AtomicFile / AtomicAppendFile: the final path never holds an incomplete file.
#include "core/io/AtomicFile.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "tests/unit/OutputTestSupport.h"

namespace c2d {
namespace {

namespace fs = std::filesystem;
using testing::readText;
using testing::DeckTempDir;

TEST(AtomicFile, NothingAtTheFinalPathBeforeCommit) {
  DeckTempDir dir;
  const fs::path path = dir / "result.txt";
  AtomicFile file(path);
  EXPECT_EQ(file.partPath(), testing::partFileOf(path));
  EXPECT_EQ(file.partPath().parent_path(), path.parent_path());
  file.stream() << "line 1\nline 2\n";
  file.stream().flush();
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::exists(file.partPath()));
  file.commit();
  EXPECT_TRUE(file.committed());
  EXPECT_EQ(readText(path), "line 1\nline 2\n");
  EXPECT_FALSE(fs::exists(file.partPath()));
}

TEST(AtomicFile, DestroyedWithoutCommitLeavesNothing) {
  DeckTempDir dir;
  const fs::path path = dir / "result.txt";
  {
    AtomicFile file(path);
    file.stream() << "half of a result";
    file.stream().flush();
    ASSERT_FALSE(testing::partFileOf(path).empty());
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(testing::partFileOf(path).empty());
}

TEST(AtomicFile, PreviousFileSurvivesAnAbandonedWrite) {
  DeckTempDir dir;
  const fs::path path = dir / "result.txt";
  AtomicFile::write(path, "old complete file\n");
  {
    AtomicFile file(path);
    file.stream() << "new but unfinished";
    file.stream().flush();
    EXPECT_EQ(readText(path), "old complete file\n");
  }
  EXPECT_EQ(readText(path), "old complete file\n");
  AtomicFile::write(path, "new complete file\n");
  EXPECT_EQ(readText(path), "new complete file\n");
}

TEST(AtomicFile, CreatesTheDirectoryAndRefusesASecondCommit) {
  DeckTempDir dir;
  const fs::path path = dir / "out" / "deep" / "r.vtu";
  AtomicFile file(path);
  file.stream() << "x";
  file.commit();
  EXPECT_EQ(readText(path), "x");
  EXPECT_THROW(file.commit(), std::logic_error);
}

TEST(AtomicFile, UnwritablePlaceThrowsWithTheFileName) {
  DeckTempDir dir;
  AtomicFile::write(dir / "plain", "a file, not a directory");
  try {
    AtomicFile file(dir / "plain" / "result.txt");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("plain"), std::string::npos) << e.what();
  }
}

TEST(AtomicFile, TaggedNameKeepsTheExtension) {
  EXPECT_EQ(AtomicFile::tagged("out/a_tplot.csv", "failed"), fs::path("out/a_tplot.failed.csv"));
  EXPECT_EQ(AtomicFile::tagged("a.pvd", "interrupted"), fs::path("a.interrupted.pvd"));
  EXPECT_EQ(AtomicFile::tagged("Oname", "failed"), fs::path("Oname.failed"));
}

TEST(AtomicFile, KeepCommitsUnderTheTaggedName) {
  DeckTempDir dir;
  AtomicFile file(dir / "h.csv");
  file.stream() << "t\n0\n";
  EXPECT_EQ(file.keep("failed"), dir / "h.failed.csv");
  EXPECT_EQ(readText(dir / "h.failed.csv"), "t\n0\n");
  EXPECT_FALSE(fs::exists(dir / "h.csv"));
  EXPECT_TRUE(testing::partFileOf(dir / "h.csv").empty());
}

// A link planted under the name a writer used to write through (the fixed
// "<path>.part" of old), or under the final name, is never written through:
// the victim keeps its text; the result replaces the link.
TEST(AtomicFile, APlantedLinkIsNeverWrittenThrough) {
  DeckTempDir dir;
  const fs::path victim = dir / "victim.txt";
  AtomicFile::write(victim, "precious\n");
  const fs::path path = dir / "run.out";
  fs::create_symlink(victim, dir / "run.out.part");
  AtomicFile::write(path, "the log\n");
  EXPECT_EQ(readText(victim), "precious\n");
  EXPECT_EQ(readText(path), "the log\n");
  fs::remove(path);
  fs::create_symlink(victim, path);
  AtomicFile::write(path, "the log again\n");
  EXPECT_EQ(readText(victim), "precious\n");
  EXPECT_FALSE(fs::is_symlink(path));
  EXPECT_EQ(readText(path), "the log again\n");
}

// Two writers of one path at once (two merges of one folder) each write
// through a temporary of their own: both commit, the last one's text stays.
TEST(AtomicFile, TwoWritersOfOnePathDoNotCollide) {
  DeckTempDir dir;
  const fs::path path = dir / "joined.csv";
  AtomicFile a(path), b(path);
  EXPECT_NE(a.partPath(), b.partPath());
  a.stream() << "from a\n";
  b.stream() << "from b\n";
  a.commit();
  EXPECT_EQ(readText(path), "from a\n");
  b.commit();
  EXPECT_EQ(readText(path), "from b\n");
}

// A full disk: every write fails with ENOSPC (SimulatedWriteFailure).
TEST(AtomicFile, FullDiskIsAnIoErrorWithTheReasonAndLeavesNothing) {
  DeckTempDir dir;
  const fs::path path = dir / "result.txt";
  const SimulatedWriteFailure full("result.txt", ENOSPC);
  try {
    AtomicFile::write(path, "a result that does not fit\n");
    FAIL() << "no exception";
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("result.txt'"), std::string::npos) << what;
    EXPECT_NE(what.find(std::strerror(ENOSPC)), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(AtomicFile, CheckReportsAFailedWriteDuringTheRun) {
  DeckTempDir dir;
  const fs::path path = dir / "run.out";
  const SimulatedWriteFailure full("run.out", ENOSPC);
  AtomicFile file(path);
  file.check();  // nothing written yet
  const std::string line(1000, 'x');
  // More than a stream buffer: the stream writes (and fails) on its own.
  for (int i = 0; i < 100; ++i) file.stream() << line << '\n';
  try {
    file.check(std::chrono::milliseconds(0));
    FAIL() << "no exception";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(std::strerror(ENOSPC)), std::string::npos) << e.what();
  }
  EXPECT_THROW(file.commit(), IoError);
  EXPECT_FALSE(fs::exists(path));
}

TEST(AtomicFile, MissingDirectoryUnderAFileIsAnIoErrorWithTheReason) {
  DeckTempDir dir;
  AtomicFile::write(dir / "plain", "x");
  try {
    AtomicFile file(dir / "plain" / "sub" / "r.txt");
    FAIL() << "no exception";
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("plain/sub"), std::string::npos) << what;
    EXPECT_NE(what.find(std::strerror(ENOTDIR)), std::string::npos) << what;
  }
}

TEST(AtomicAppendFile, EverySyncLeavesACompleteDocumentUnderPart) {
  DeckTempDir dir;
  const fs::path path = dir / "list.xml";
  const fs::path part = dir / "list.xml.part";
  AtomicAppendFile file(path, "<list>\n", "</list>\n");
  EXPECT_EQ(file.partPath(), part);
  file.append("  <item n=\"1\"/>\n");
  EXPECT_FALSE(fs::exists(part));  // nothing synced yet
  file.sync();
  EXPECT_EQ(readText(part), "<list>\n  <item n=\"1\"/>\n</list>\n");
  file.append("  <item n=\"2\"/>\n");
  EXPECT_EQ(file.pendingBytes(), 16u);
  EXPECT_EQ(readText(part), "<list>\n  <item n=\"1\"/>\n</list>\n");  // unchanged until the next sync
  file.sync();
  EXPECT_EQ(file.pendingBytes(), 0u);
  EXPECT_EQ(readText(part), "<list>\n  <item n=\"1\"/>\n  <item n=\"2\"/>\n</list>\n");
  // Only a completed document gets the final name.
  EXPECT_FALSE(fs::exists(path));
  file.close();
  EXPECT_EQ(readText(path), "<list>\n  <item n=\"1\"/>\n  <item n=\"2\"/>\n</list>\n");
  EXPECT_FALSE(fs::exists(part));
  EXPECT_THROW(file.append("late"), std::logic_error);
}

TEST(AtomicAppendFile, DestructorLeavesThePartOfAnInterruptedRun) {
  DeckTempDir dir;
  const fs::path path = dir / "history.csv";
  try {
    AtomicAppendFile file(path, "time,u\n");
    file.append("0,0\n");
    file.sync();
    file.append("0.1,0.5\n");
    throw std::runtime_error("analysis failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(readText(dir / "history.csv.part"), "time,u\n0,0\n0.1,0.5\n");
  EXPECT_FALSE(fs::exists(path));
}

TEST(AtomicAppendFile, KeepWritesTheTaggedNameAndRemovesThePart) {
  DeckTempDir dir;
  AtomicAppendFile file(dir / "c.pvd", "<a>\n", "</a>\n");
  file.append("  <b/>\n");
  file.sync();
  EXPECT_EQ(file.keep("failed"), dir / "c.failed.pvd");
  EXPECT_EQ(readText(dir / "c.failed.pvd"), "<a>\n  <b/>\n</a>\n");
  EXPECT_FALSE(fs::exists(dir / "c.pvd.part"));
  EXPECT_FALSE(fs::exists(dir / "c.pvd"));
  EXPECT_TRUE(file.closed());
}

TEST(AtomicAppendFile, MinimumIntervalThrottlesButCloseWritesAll) {
  DeckTempDir dir;
  const fs::path path = dir / "history.csv";
  const fs::path part = dir / "history.csv.part";
  AtomicAppendFile file(path, "t\n", "", std::chrono::hours(1));
  file.append("1\n");
  file.sync();  // the first sync always writes
  EXPECT_EQ(readText(part), "t\n1\n");
  file.append("2\n");
  file.sync();  // within the interval: skipped
  EXPECT_EQ(readText(part), "t\n1\n");
  EXPECT_GT(file.pendingBytes(), 0u);
  file.close();
  EXPECT_EQ(readText(path), "t\n1\n2\n");
  EXPECT_TRUE(file.closed());
}

TEST(AtomicAppendFile, EmptyDocumentIsStillComplete) {
  DeckTempDir dir;
  const fs::path path = dir / "c.pvd";
  {
    AtomicAppendFile file(path, "<a>\n", "</a>\n");
    file.close();
  }
  EXPECT_EQ(readText(path), "<a>\n</a>\n");
}

}  // namespace
}  // namespace c2d
