// The run's part of a restart file (macro/run/RunState.h): the watches' and
// the step control's state written and read back, and refused when it does not
// fit the model.
#include <gtest/gtest.h>

#include <sstream>

#include "macro/run/RunState.h"
#include "solvers/RestartFile.h"

namespace c2d {
namespace {

RunWatches::Saved someWatches() {
  RunWatches::Saved w;
  w.hingeCount = 3;
  w.maxMomentRatio = 0.97, w.peakGroundForce = 1234.5, w.peakGroundTime = 2.25;
  w.peakKinetic = 88.0, w.restRatio = 1e-4, w.lastMoving = 3.5;
  w.deepest.node = -1, w.deepest.depth = 0.0125, w.deepestTime = 2.5;
  w.jointsFormed = 2, w.jointsRuptured = 1, w.removed = 4, w.hinges = 5, w.fractures = 1;
  w.shears = 2, w.dynamicSeen = true;
  return w;
}

TEST(RunState, WrittenAndReadBackUnchanged) {
  const Model model;  // no elements, no nodes
  std::ostringstream log;
  RunWatches watches(log, model);
  EnergyWatch energy;
  StepControl steps(log, energy);
  watches.restore(someWatches());
  steps.restore({true, 1e-6, 0.01, 1, 9});
  const std::string bytes = runStateBytes(watches, steps);

  RunWatches watches2(log, model);
  StepControl steps2(log, energy);
  readRunState(bytes, model, watches2, steps2);
  const RunWatches::Saved a = watches.saved(), b = watches2.saved();
  EXPECT_EQ(b.hingeStep, a.hingeStep);
  EXPECT_EQ(b.hingeCount, a.hingeCount);
  EXPECT_EQ(b.maxMomentRatio, a.maxMomentRatio);
  EXPECT_EQ(b.peakGroundForce, a.peakGroundForce);
  EXPECT_EQ(b.peakGroundTime, a.peakGroundTime);
  EXPECT_EQ(b.peakKinetic, a.peakKinetic);
  EXPECT_EQ(b.restRatio, a.restRatio);
  EXPECT_EQ(b.lastMoving, a.lastMoving);
  EXPECT_EQ(b.deepest.node, a.deepest.node);
  EXPECT_EQ(b.deepest.depth, a.deepest.depth);
  EXPECT_EQ(b.deepestTime, a.deepestTime);
  EXPECT_EQ(b.jointsFormed, a.jointsFormed);
  EXPECT_EQ(b.jointsRuptured, a.jointsRuptured);
  EXPECT_EQ(b.removed, a.removed);
  EXPECT_EQ(b.hinges, a.hinges);
  EXPECT_EQ(b.fractures, a.fractures);
  EXPECT_EQ(b.shears, a.shears);
  EXPECT_EQ(b.dynamicSeen, a.dynamicSeen);
  const StepControl::Saved s = steps2.saved();
  EXPECT_TRUE(s.cutting);
  EXPECT_EQ(s.dtMin, 1e-6);
  EXPECT_EQ(s.dtNominal, 0.01);
  EXPECT_EQ(s.stepsSinceCut, 1);
  EXPECT_EQ(s.cuts, 9);
  // The same state gives the same bytes.
  EXPECT_EQ(runStateBytes(watches2, steps2), bytes);
}

TEST(RunState, RefusedWhenItDoesNotFitTheModel) {
  const Model model;
  std::ostringstream log;
  RunWatches watches(log, model);
  EnergyWatch energy;
  StepControl steps(log, energy);
  RunWatches::Saved w = someWatches();
  w.hingeStep = {0, 2, 0};  // three elements, the model has none
  watches.restore(w);
  const std::string bytes = runStateBytes(watches, steps);
  RunWatches watches2(log, model);
  StepControl steps2(log, energy);
  try {
    readRunState(bytes, model, watches2, steps2);
    FAIL() << "a state of three elements read into a model of none";
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("hinge steps do not match the element count"),
              std::string::npos)
        << e.what();
  }
  // A state cut short.
  watches.restore(someWatches());
  const std::string whole = runStateBytes(watches, steps);
  EXPECT_THROW(readRunState(whole.substr(0, whole.size() / 2), model, watches2, steps2),
               CheckpointError);
}

}  // namespace
}  // namespace c2d
