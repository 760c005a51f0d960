// The step control's bookkeeping of a Newton loop (macro/run/StepControl.h):
// how a loop ended and what its failure says, without step cutting; its part
// of a restart file. The cutting itself: StepCuttingTest and the decks.
#include <gtest/gtest.h>

#include <sstream>

#include "macro/run/EnergyWatch.h"
#include "macro/run/StepControl.h"

namespace c2d {
namespace {

TEST(StepControl, TheLoopsVerdictNamesWhyItEndedUnconverged) {
  std::ostringstream log;
  const EnergyWatch energy;
  StepControl steps(log, energy);
  steps.loopBegins();
  EXPECT_FALSE(steps.diverged());
  EXPECT_EQ(steps.unconverged(12), "did not converge in 12 iterations");
  EXPECT_EQ(steps.ends(NewtonVerdict::Stalled), Flow::ExitLoop);
  EXPECT_FALSE(steps.diverged());
  EXPECT_EQ(steps.unconverged(12), "stalled (its energy repeats)");
  steps.loopBegins();
  EXPECT_EQ(steps.ends(NewtonVerdict::Diverged), Flow::ExitLoop);
  EXPECT_TRUE(steps.diverged());
  EXPECT_EQ(steps.unconverged(12), "diverged");
  // A new loop forgets the verdict.
  steps.loopBegins();
  EXPECT_FALSE(steps.diverged());
  EXPECT_EQ(steps.unconverged(3), "did not converge in 3 iterations");
}

TEST(StepControl, WithoutCuttingAFailedIterationIsTheRunsFailure) {
  std::ostringstream log;
  const EnergyWatch energy;
  StepControl steps(log, energy);
  steps.loopBegins();
  EXPECT_FALSE(steps.cutting());
  EXPECT_FALSE(steps.iterationFailed("singular tangent at node 3, dof 2"));
  EXPECT_FALSE(steps.diverged());
  EXPECT_TRUE(log.str().empty()) << log.str();
}

TEST(StepControl, PartsAndTheRestartStateRoundTrip) {
  std::ostringstream log;
  const EnergyWatch energy;
  StepControl steps(log, energy);
  EXPECT_EQ(steps.parts(), 0);
  steps.partBegins();
  steps.partBegins();
  EXPECT_EQ(steps.parts(), 2);
  steps.restore({true, 1e-6, 0.01, 1, 7});
  EXPECT_TRUE(steps.cutting());
  EXPECT_EQ(steps.cuts(), 7);
  const StepControl::Saved s = steps.saved();
  EXPECT_TRUE(s.cutting);
  EXPECT_DOUBLE_EQ(s.dtMin, 1e-6);
  EXPECT_DOUBLE_EQ(s.dtNominal, 0.01);
  EXPECT_EQ(s.stepsSinceCut, 1);
  EXPECT_EQ(s.cuts, 7);
}

}  // namespace
}  // namespace c2d
