// The Newton loop's verdict after an iteration (solvers/NewtonVerdict.h): its
// checks and their order.
#include <gtest/gtest.h>

#include <vector>

#include "solvers/Analysis.h"
#include "solvers/NewtonVerdict.h"

namespace c2d {
namespace {

// A step's history with these energies; the last iteration converged or not.
std::vector<IterationInfo> history(const std::vector<double>& energies, bool converged) {
  std::vector<IterationInfo> h;
  for (std::size_t k = 0; k < energies.size(); ++k) {
    IterationInfo i;
    i.iteration = static_cast<int>(k) + 1;
    i.energy = energies[k];
    i.converged = converged && k + 1 == energies.size();
    h.push_back(i);
  }
  return h;
}

NewtonVerdict verdict(const std::vector<double>& energies, bool converged = false) {
  const std::vector<IterationInfo> h = history(energies, converged);
  return newtonVerdict(h.back(), h);
}

TEST(NewtonVerdict, ConvergedAndIteratingFollowTheConvergenceTest) {
  EXPECT_EQ(verdict({1.0, 1e-3, 1e-9}, true), NewtonVerdict::Converged);
  EXPECT_EQ(verdict({1.0, 1e-3, 1e-9}, false), NewtonVerdict::Iterating);
  EXPECT_EQ(verdict({1.0}, false), NewtonVerdict::Iterating);
}

TEST(NewtonVerdict, DivergedAboveTheBlowUpAfterFourIterationsEvenIfConverged) {
  // Four iterations are not enough to call it.
  EXPECT_EQ(verdict({1.0, 10, 1e10, 1e31}), NewtonVerdict::Iterating);
  EXPECT_EQ(verdict({1.0, 10, 1e10, 1e20, 1e31}), NewtonVerdict::Diverged);
  // At the ratio itself: not yet.
  EXPECT_EQ(verdict({1.0, 10, 1e10, 1e20, kNewtonBlowUp}), NewtonVerdict::Iterating);
  // The blow-up is checked before the convergence test's answer.
  EXPECT_EQ(verdict({1.0, 10, 1e10, 1e20, 1e31}, true), NewtonVerdict::Diverged);
}

TEST(NewtonVerdict, StalledWhenTheEnergyRepeatsWithPeriodOneOrTwo) {
  // A two-cycle over six iterations.
  EXPECT_EQ(verdict({1.0, 0.5, 0.2, 0.5, 0.2, 0.5}), NewtonVerdict::Stalled);
  // A fixed point.
  EXPECT_EQ(verdict({1.0, 0.3, 0.3, 0.3, 0.3, 0.3}), NewtonVerdict::Stalled);
  // Five iterations are too few to call it.
  EXPECT_EQ(verdict({1.0, 0.2, 0.5, 0.2, 0.5}), NewtonVerdict::Iterating);
  // Two repeats of the cycle only (the third back differs).
  EXPECT_EQ(verdict({1.0, 0.7, 0.9, 0.5, 0.2, 0.5, 0.2}), NewtonVerdict::Iterating);
  // A period of three is not a stall (the line search's cycles).
  EXPECT_EQ(verdict({1.0, 0.5, 0.2, 0.1, 0.5, 0.2, 0.1}), NewtonVerdict::Iterating);
  // A converged iteration is never a stall.
  EXPECT_EQ(verdict({1.0, 0.5, 0.2, 0.5, 0.2, 0.5}, true), NewtonVerdict::Converged);
}

TEST(NewtonVerdict, UnderALineSearchThatTookOverOnlyItsOwnIterationsCount) {
  // Plain Newton's two-cycle called the line search in at iteration 6.
  std::vector<IterationInfo> h = history({1.0, 0.5, 0.2, 0.5, 0.2, 0.5}, false);
  h.back().globalized = true;
  EXPECT_EQ(newtonVerdict(h.back(), h), NewtonVerdict::Iterating);
  // Its own iterations: five are too few to call a stall, even with the
  // plain iterations' cycle in the window.
  for (double e : {0.2, 0.5, 0.2, 0.5, 0.2}) {
    IterationInfo i;
    i.iteration = static_cast<int>(h.size()) + 1;
    i.energy = e;
    h.push_back(i);
    EXPECT_EQ(newtonVerdict(h.back(), h), NewtonVerdict::Iterating) << h.size();
  }
  // The sixth of its own that goes on cycling: stalled.
  IterationInfo i;
  i.iteration = static_cast<int>(h.size()) + 1;
  i.energy = 0.5;
  h.push_back(i);
  EXPECT_EQ(newtonVerdict(h.back(), h), NewtonVerdict::Stalled);
}

}  // namespace
}  // namespace c2d
