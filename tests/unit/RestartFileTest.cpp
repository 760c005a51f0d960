// Restart files read back (solvers/RestartFile): bad files are clear errors
// naming the file (truncated, not a restart file, trailing data, corrupted,
// another format version), in a deck too; a crafted count, a file that is not
// a regular one or one larger than the model can explain is refused before
// anything is allocated or read.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/io/Checkpoint.h"
#include "core/Model.h"
#include "solvers/Analysis.h"
#include "solvers/RestartFile.h"
#include "tests/unit/RestartTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckResult;
using testing::DeckTempDir;
using testing::expectRan;
using testing::kLoads;
using testing::kPortal;
using testing::kStart;
using testing::kTplot;
using testing::readText;
using testing::runDeckText;

TEST(Restart, BadFilesAreClearErrors) {
  DeckTempDir dir;
  const std::string data = std::string(kLoads) + kTplot;
  expectRan(runDeckText(dir, "first.inp", kPortal + kStart + "  SAVE,mid\nEND\n" + data));
  const std::filesystem::path out = dir.path() / "out";
  const std::string good = readText(out / "mid.rst");
  ASSERT_GT(good.size(), 100u);
  auto expectError = [&](const std::string& bytes, const std::string& what) {
    std::ofstream(out / "bad.rst", std::ios::binary) << bytes;
    Model model;
    Analysis analysis(model);
    try {
      loadRestart(out / "bad.rst", model, analysis);
      ADD_FAILURE() << "no error for " << what;
    } catch (const CheckpointError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("bad.rst"), std::string::npos) << msg;
      EXPECT_NE(msg.find(what), std::string::npos) << msg;
    }
  };
  expectError(good.substr(0, good.size() / 2), "truncated");
  expectError(good.substr(0, 12), "truncated");
  expectError("FEAP * * not a restart file\n", "not a collapse2d restart file");
  expectError(good + "x", "trailing data");
  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 0x10;
  expectError(flipped, "corrupted");
  std::string version = good;
  version[8] = 99;
  expectError(version, "format version 99");

  // In a deck: the error names the command and the file; a missing file too.
  std::ofstream(out / "cut.rst", std::ios::binary) << good.substr(0, good.size() - 9);
  const DeckResult r = runDeckText(dir, "rest.inp", kPortal + std::string("  REST,cut\n  REST,none\nEND\n"));
  EXPECT_EQ(r.outcome.exitCode, 2) << r.console;
  EXPECT_NE((r.console + r.outcome.message).find("REST: restart file"), std::string::npos) << r.console << r.outcome.message;
  EXPECT_NE((r.console + r.outcome.message).find("cut.rst': truncated"), std::string::npos) << r.console << r.outcome.message;
}

// A crafted file whose checksum is right: a count larger than the bytes left
// is refused before anything is allocated for it; a file that is not a
// regular one (a link to /dev/zero, a FIFO) or is larger than the model can
// explain is refused before it is read.
TEST(Restart, CraftedCountsAndFilesAreRefusedBeforeAnythingIsAllocated) {
  DeckTempDir dir;
  const std::string data = std::string(kLoads) + kTplot;
  expectRan(runDeckText(dir, "first.inp", kPortal + kStart + "  SAVE,mid\nEND\n" + data));
  const std::filesystem::path out = dir.path() / "out";
  const std::string good = readText(out / "mid.rst");
  auto expectError = [&](const std::filesystem::path& file, const std::string& what) {
    Model model;
    Analysis analysis(model);
    try {
      loadRestart(file, model, analysis);
      ADD_FAILURE() << "no error for " << what;
    } catch (const CheckpointError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(file.filename().string()), std::string::npos) << msg;
      EXPECT_NE(msg.find(what), std::string::npos) << msg;
    }
  };
  // The node count (after the MODL tag) made 2^31 - 1, the checksum made right.
  std::string crafted = good;
  const std::size_t modl = crafted.find("MODL", 24);
  ASSERT_NE(modl, std::string::npos);
  const std::uint64_t nodes = 0x7fffffff;
  std::memcpy(crafted.data() + modl + 4, &nodes, 8);
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 24; i + 8 < crafted.size(); ++i)
    h = (h ^ static_cast<unsigned char>(crafted[i])) * 1099511628211ull;
  std::memcpy(crafted.data() + crafted.size() - 8, &h, 8);
  std::ofstream(out / "crafted.rst", std::ios::binary) << crafted;
  expectError(out / "crafted.rst", "a count of 2147483647 items where");

  std::filesystem::create_symlink("/dev/zero", out / "zero.rst");
  expectError(out / "zero.rst", "not a regular file");
  ASSERT_EQ(::mkfifo((out / "fifo.rst").c_str(), 0600), 0);
  expectError(out / "fifo.rst", "not a regular file");
  // An empty model explains 64 MiB at most: a sparse file of 65 MiB is refused.
  std::ofstream(out / "huge.rst", std::ios::binary) << good;
  std::filesystem::resize_file(out / "huge.rst", std::uintmax_t{65} << 20);
  expectError(out / "huge.rst", "bytes, more than the 67108864");
}

}  // namespace
}  // namespace c2d
