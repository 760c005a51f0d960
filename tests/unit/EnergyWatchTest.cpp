// The run's watch on its energy account (macro/run/EnergyWatch.h): the
// balance's drift and the energy a motion gains without work, which no
// mechanism of the model can give and Newmark's trapezoidal rule does with
// nonlinear members (decks/rc/column_schemes.inp).
#include <gtest/gtest.h>

#include <sstream>

#include "macro/run/EnergyWatch.h"
#include "tests/unit/OutputTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

Energy energy(double kinetic, double strain, double external, double dissipated) {
  Energy e;
  e.kinetic = kinetic;
  e.strain = strain;
  e.external = external;
  e.dissipated = dissipated;
  return e;
}

TEST(EnergyWatch, CountsTheDissipationsDecreaseInDynamicStepsOnly) {
  EnergyWatch w;
  // Start: 10 kJ stored, nothing put in since.
  w.onCommit(energy(0, 10, 0, 0), true, 0, 0);
  // A dynamic step that dissipates 0.5: no gain.
  w.onCommit(energy(1, 8.5, 0, 0.5), true, 1, 0.1);
  EXPECT_EQ(w.gained(), 0);
  // A static step whose dissipation falls by 0.2 (its trapezoidal work's
  // quadrature error): not a gain, no mass moves.
  w.onCommit(energy(0, 9.7, 0, 0.3), false, 2, 0.2);
  EXPECT_EQ(w.gained(), 0);
  // Dynamic steps giving back 0.05 then 0.1 (below, then beyond 1 % of the
  // 10 kJ put in): the gain and where it passed the tolerance.
  w.onCommit(energy(0.05, 9.7, 0, 0.25), true, 3, 0.3);
  EXPECT_NEAR(w.gained(), 0.005, 1e-15);
  EXPECT_EQ(w.gainStep(), 0);
  w.onCommit(energy(0.15, 9.7, 0, 0.15), true, 4, 0.4);
  EXPECT_NEAR(w.gained(), 0.015, 1e-15);
  EXPECT_EQ(w.gainStep(), 4);
  EXPECT_EQ(w.gainTime(), 0.4);
  // The balance closed throughout (10 kJ): no error.
  EXPECT_LT(w.error(), 1e-15);
  // External work raises the energy put in, and with it the gain's measure.
  w.onCommit(energy(0.15, 29.7, 20, 0.15), true, 5, 0.5);
  EXPECT_NEAR(w.gained(), 0.15 / 30, 1e-15);
  EXPECT_EQ(w.gainStep(), 4);
}

TEST(EnergyWatch, WhatContactsRestoredOfTheSchemesDecayIsNoGain) {
  EnergyWatch w;
  w.onCommit(energy(0, 10, 0, 0), true, 0, 0);
  // The scheme's decay takes 0.4 kJ from an impact ...
  w.onCommit(energy(1, 8.6, 0, 0.4), true, 1, 0.1);
  // ... and its contact gives 0.3 of it back at the next commit: the
  // dissipation falls by 0.3, all of it restored.
  Energy back = energy(1.3, 8.6, 0, 0.1);
  back.restored = 0.3;
  w.onCommit(back, true, 2, 0.2);
  EXPECT_LT(w.gained(), 1e-15);
  // A fall beyond what was restored is a gain: 0.05 of the 10 kJ put in.
  Energy more = energy(1.45, 8.6, 0, -0.05);
  more.restored = 0.4;
  w.onCommit(more, true, 3, 0.3);
  EXPECT_NEAR(w.gained(), 0.005, 1e-15);
}

TEST(EnergyWatch, TheRestartFileKeepsItsAccount) {
  EnergyWatch a;
  a.onCommit(energy(0, 10, 0, 0), true, 0, 0);
  a.onCommit(energy(0.2, 10, 0, -0.2), true, 1, 0.1);
  std::stringstream bytes;
  a.save(bytes);
  EnergyWatch b;
  b.load(bytes);
  for (EnergyWatch* w : {&a, &b}) w->onCommit(energy(0.3, 10, 0, -0.3), true, 2, 0.2);
  EXPECT_EQ(a.gained(), b.gained());
  EXPECT_EQ(a.gainStep(), b.gainStep());
  EXPECT_EQ(a.gainTime(), b.gainTime());
  EXPECT_EQ(a.error(), b.error());
  EXPECT_NEAR(b.gained(), 0.03, 1e-15);
}

TEST(EnergyWatch, NewmarksRuleSwingingAnRcMemberAboutNZeroIsWarnedAbout) {
  // decks/rc/column_schemes.inp: the same column under Newmark, then under
  // the mid-point scheme.
  const testing::DeckTempDir dir;
  const testing::DeckResult r = testing::runDeckText(
      dir, "column_schemes.inp",
      testing::readText(std::string(C2D_SOURCE_DIR) + "/decks/rc/column_schemes.inp"));
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message;
  const std::string& text = r.log;
  const std::size_t second = text.find("RC column swinging about N = 0, energy conserving");
  ASSERT_NE(second, std::string::npos);
  const std::string newmark = text.substr(0, second), midPoint = text.substr(second);
  EXPECT_NE(newmark.find("warning: the motion gained"), std::string::npos);
  EXPECT_NE(newmark.find("of it by step 518"), std::string::npos);
  EXPECT_EQ(midPoint.find("energy gained"), std::string::npos);
  EXPECT_EQ(midPoint.find("warning:"), std::string::npos);
}

}  // namespace
}  // namespace c2d
