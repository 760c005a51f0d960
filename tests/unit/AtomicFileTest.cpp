// AtomicFile / AtomicAppendFile: the final path never holds an incomplete file.
#include "core/AtomicFile.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "tests/unit/OutputTestSupport.h"

namespace c2d {
namespace {

namespace fs = std::filesystem;
using testing::readFile;
using testing::TempDir;

TEST(AtomicFile, NothingAtTheFinalPathBeforeCommit) {
  TempDir dir;
  const fs::path path = dir / "result.txt";
  AtomicFile file(path);
  EXPECT_EQ(file.partPath(), dir / "result.txt.part");
  file.stream() << "line 1\nline 2\n";
  file.stream().flush();
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::exists(file.partPath()));
  file.commit();
  EXPECT_TRUE(file.committed());
  EXPECT_EQ(readFile(path), "line 1\nline 2\n");
  EXPECT_FALSE(fs::exists(file.partPath()));
}

TEST(AtomicFile, DestroyedWithoutCommitLeavesNothing) {
  TempDir dir;
  const fs::path path = dir / "result.txt";
  {
    AtomicFile file(path);
    file.stream() << "half of a result";
    file.stream().flush();
    ASSERT_TRUE(fs::exists(dir / "result.txt.part"));
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(dir / "result.txt.part"));
}

TEST(AtomicFile, PreviousFileSurvivesAnAbandonedWrite) {
  TempDir dir;
  const fs::path path = dir / "result.txt";
  AtomicFile::write(path, "old complete file\n");
  {
    AtomicFile file(path);
    file.stream() << "new but unfinished";
    file.stream().flush();
    EXPECT_EQ(readFile(path), "old complete file\n");
  }
  EXPECT_EQ(readFile(path), "old complete file\n");
  AtomicFile::write(path, "new complete file\n");
  EXPECT_EQ(readFile(path), "new complete file\n");
}

TEST(AtomicFile, CreatesTheDirectoryAndRefusesASecondCommit) {
  TempDir dir;
  const fs::path path = dir / "out" / "deep" / "r.vtu";
  AtomicFile file(path);
  file.stream() << "x";
  file.commit();
  EXPECT_EQ(readFile(path), "x");
  EXPECT_THROW(file.commit(), std::logic_error);
}

TEST(AtomicFile, UnwritablePlaceThrowsWithTheFileName) {
  TempDir dir;
  AtomicFile::write(dir / "plain", "a file, not a directory");
  try {
    AtomicFile file(dir / "plain" / "result.txt");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("plain"), std::string::npos) << e.what();
  }
}

TEST(AtomicAppendFile, EverySyncLeavesACompleteDocument) {
  TempDir dir;
  const fs::path path = dir / "list.xml";
  AtomicAppendFile file(path, "<list>\n", "</list>\n");
  file.append("  <item n=\"1\"/>\n");
  EXPECT_FALSE(fs::exists(path));  // nothing synced yet
  file.sync();
  EXPECT_EQ(readFile(path), "<list>\n  <item n=\"1\"/>\n</list>\n");
  file.append("  <item n=\"2\"/>\n");
  EXPECT_EQ(file.pendingBytes(), 16u);
  EXPECT_EQ(readFile(path), "<list>\n  <item n=\"1\"/>\n</list>\n");  // unchanged until the next sync
  file.sync();
  EXPECT_EQ(file.pendingBytes(), 0u);
  EXPECT_EQ(readFile(path), "<list>\n  <item n=\"1\"/>\n  <item n=\"2\"/>\n</list>\n");
  EXPECT_FALSE(fs::exists(dir / "list.xml.part"));
  file.close();
  EXPECT_THROW(file.append("late"), std::logic_error);
}

TEST(AtomicAppendFile, DestructorKeepsTheRecordsOfAnInterruptedRun) {
  TempDir dir;
  const fs::path path = dir / "history.csv";
  try {
    AtomicAppendFile file(path, "time,u\n");
    file.append("0,0\n");
    file.sync();
    file.append("0.1,0.5\n");
    throw std::runtime_error("analysis failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(readFile(path), "time,u\n0,0\n0.1,0.5\n");
  EXPECT_FALSE(fs::exists(dir / "history.csv.part"));
}

TEST(AtomicAppendFile, MinimumIntervalThrottlesButCloseWritesAll) {
  TempDir dir;
  const fs::path path = dir / "history.csv";
  AtomicAppendFile file(path, "t\n", "", std::chrono::hours(1));
  file.append("1\n");
  file.sync();  // the first sync always writes
  EXPECT_EQ(readFile(path), "t\n1\n");
  file.append("2\n");
  file.sync();  // within the interval: skipped
  EXPECT_EQ(readFile(path), "t\n1\n");
  EXPECT_GT(file.pendingBytes(), 0u);
  file.close();
  EXPECT_EQ(readFile(path), "t\n1\n2\n");
  EXPECT_TRUE(file.closed());
}

TEST(AtomicAppendFile, EmptyDocumentIsStillComplete) {
  TempDir dir;
  const fs::path path = dir / "c.pvd";
  { AtomicAppendFile file(path, "<a>\n", "</a>\n"); }
  EXPECT_EQ(readFile(path), "<a>\n</a>\n");
}

}  // namespace
}  // namespace c2d
