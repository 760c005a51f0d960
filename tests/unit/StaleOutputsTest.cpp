// A complete rerun into a folder where the same deck was interrupted: the
// tagged outputs the interrupted run kept and its ParaView frames and deformed
// shapes beyond the new run's are gone (they looked like the new run's), while
// the files of other stems stay.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;

const std::string kParams = "PARAmeter\n  L = 3\n  n = 2\n  P = 10\n\n";

TEST(StaleOutputs, ACompleteRerunRemovesWhatAnInterruptedRunOfItsStemLeft) {
  DeckTempDir dir;
  const std::filesystem::path out = dir.path() / "out";
  std::filesystem::create_directories(out);
  auto touch = [&](const std::string& name) { std::ofstream(out / name) << "old\n"; };
  char frame[32];
  for (int i = 0; i < 114; ++i) {
    std::snprintf(frame, sizeof frame, "rr_%04d.vtu", i);
    touch(frame);
  }
  const std::vector<std::string> stale = {"rr.interrupted.out", "rr_tplot.interrupted.csv",
                                          "rr.interrupted.pvd", "rr_tplot_2.interrupted.csv",
                                          "rr.failed.out",      "rr_deformed_0077.svg"};
  for (const auto& f : stale) touch(f);
  // Other stems, and files of this stem that are not a run's numbered outputs.
  const std::vector<std::string> others = {"rr_1_0000.vtu", "rrx_0000.vtu", "other.interrupted.out",
                                           "rr_notes.txt", "rr_0001.vtu.bak"};
  for (const auto& f : others) touch(f);

  const auto r =
      testing::runDeckText(dir, "rr.inp", kParams + testing::rampProblem(4, "  PVIEw,,2\n", ""));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  for (const auto& f : stale) EXPECT_FALSE(std::filesystem::exists(out / f)) << f;
  for (const auto& f : others) EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  int frames = 0;
  for (const auto& e : std::filesystem::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    frames +=
        name.rfind("rr_", 0) == 0 && e.path().extension() == ".vtu" && name != "rr_1_0000.vtu";
  }
  EXPECT_EQ(frames, 3);  // t = 0, 0.5, 1: the new run's collection
  EXPECT_TRUE(std::filesystem::exists(out / "rr.pvd"));
}

}  // namespace
}  // namespace c2d
