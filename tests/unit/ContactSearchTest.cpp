// The member contact's search (core/contact/ContactSearch, core/contact/SweptBoxes;
// the grid: ContactGridTest): the pairs excluded by joints and the reference
// configuration, and the lists kept over a step's iterations: every pair within
// reach, every pair that touches.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "ContactTestSupport.h"
#include "core/contact/ContactGrid.h"
#include "core/contact/MemberContact.h"
#include "core/contact/SweptBoxes.h"
#include "elements/Joints.h"
#include "solvers/TimeIntegrator.h"

namespace c2d {
namespace {

using test::addRod;
using test::newRod;
using test::rod;

// --- pairs of a model ---------------------------------------------------------

TEST(MemberContactModel, JointsAndTheReferenceConfigurationExcludePairs) {
  // Two links meeting at a joint at a right angle (radius 0.05 each, contact
  // distance 0.1), elements 0.08 long: the node next to the joint on either
  // link is within 0.1 of the other link's first element in the reference
  // configuration; the joint's master and slave are one node for contact.
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 10, 1.0, 2.5e-3 / 3);  // r = sqrt(3 I/A) = 0.05
  const int a = newRod(m, Vec2(0, 0.4), Vec2(0, 0), 5);
  const int b = m.numNodes() - 1;
  const int c = m.addNode(Vec2(0, 0));
  addRod(m, c, Vec2(0.4, 0), 5);
  m.joints().push_back({b, c, JointForm::Shared});
  installJoints(m);
  m.memberContact() = MemberContactData{1e3, 0, -1};
  Assembler as(m);
  as.refresh();
  ASSERT_NE(as.memberContact(), nullptr);
  EXPECT_NEAR(as.memberContact()->radius(0), 0.05, 1e-12);
  State s;
  s.resize(m.numNodes());
  const auto& pairs = as.memberContact()->candidates(m, s);
  auto has = [&](int node, int element) {
    return std::any_of(pairs.begin(), pairs.end(), [&](const ContactPair& p) {
      return p.node == node && p.element == element;
    });
  };
  const int firstOfLink2 = 5, lastOfLink1 = 4;
  EXPECT_FALSE(has(b, firstOfLink2));      // the joint's own node
  EXPECT_FALSE(has(b - 1, firstOfLink2));  // 0.08 from it in the reference configuration
  EXPECT_FALSE(has(c + 1, lastOfLink1));
  // Further along, the pairs are candidates (within the search margin).
  EXPECT_TRUE(has(b - 2, firstOfLink2));
  EXPECT_TRUE(has(c + 2, lastOfLink1));
  (void)a;
  // No pair of a node with its own elements.
  for (const ContactPair& p : pairs) {
    const auto nodes = m.element(p.element).nodes();
    EXPECT_NE(p.node, nodes[0]);
    EXPECT_NE(p.node, nodes[1]);
  }
}

// A rod from (0, 0) to (2, 0) in 8 elements and a bar from a to b in n (r =
// 0.05 both), with member contact k = 1e3: the bar's first node.
int rodAndBar(Model& m, const Vec2& a, const Vec2& b, int n) {
  m.materials()[1] = rod(1, 1e4, 1e4, 10, 1.0, 2.5e-3 / 3);
  newRod(m, Vec2(0, 0), Vec2(2, 0), 8);
  const int bar = newRod(m, a, b, n);
  m.memberContact() = MemberContactData{1e3, 0, -1};
  return bar;
}

TEST(MemberContactModel, TheStepsNearListHoldsEveryPairWithinReach) {
  // Two crossing rods, the second moved across the first by Newton-like
  // increments: every candidate within reach by its boxes is in the list
  // SweptBoxes::near keeps, while the nodes move by less than a quarter of
  // its slack and after a move beyond (when it is found afresh; kept for
  // good, it missed the pairs the crossing point reached).
  Model m;
  const int bar = rodAndBar(m, Vec2(0.3, -0.6), Vec2(1.2, -1.1), 6);  // displaced up below
  Assembler as(m);
  as.refresh();
  MemberContact& mc = *as.memberContact();
  State s;
  s.resize(m.numNodes());
  for (int n = bar; n < m.numNodes(); ++n) s.u(3 * n + 1) = s.un(3 * n + 1) = 0.8;
  SweptBoxes swept;
  const double slack = 0.25 * mc.margin();
  int reached = 0;
  for (int iteration = 0; iteration < 40; ++iteration) {
    // Steps down and along of a third of the list's slack: the list is kept
    // for some and found afresh after a few, between the candidates' searches.
    const double dy = -slack / 3, dx = 0.1 * slack * std::sin(iteration);
    for (int n = bar; n < m.numNodes(); ++n) {
      s.u(3 * n) += dx;
      s.u(3 * n + 1) += dy;
    }
    const auto& candidates = mc.candidates(m, s);
    swept.update(m, s);
    const std::vector<int>& near =
        swept.near(s, candidates, mc.candidatesVersion(), mc.slack(), slack);
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (!swept.reach(candidates[i], mc.slack())) continue;
      ++reached;
      EXPECT_TRUE(std::find(near.begin(), near.end(), static_cast<int>(i)) != near.end())
          << "iteration " << iteration << ", pair " << candidates[i].node << "-"
          << candidates[i].element;
    }
  }
  EXPECT_GT(reached, 40);  // the rods were within reach in every iteration
}

TEST(MemberContactModel, TheNearListHoldsEveryPairThatTouches) {
  // A bar wandering over a rod's end in Newton-like increments (random, up
  // to the list's hold), round its end, across its line and into its span
  // from either side, steps committed now and then: every pair evaluate()
  // finds a force on is in nearby()'s near list, kept over the step's
  // iterations, and the list leaves out pairs its boxes keep (those that
  // cannot touch while it holds: MemberContact::mayTouch).
  Model m;
  const int bar = rodAndBar(m, Vec2(2.3, -0.4), Vec2(2.3, -1.0), 3);
  Assembler as(m);
  as.refresh();
  MemberContact& mc = *as.memberContact();
  State s;
  s.resize(m.numNodes());
  const double hold = SweptBoxes::holds(0.25 * mc.margin());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> step(-hold, hold);
  const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  PairVec f;
  PairMat k;
  int touched = 0, left = 0;
  for (int iteration = 0; iteration < 3000; ++iteration) {
    // Round the rod's end (2, 0) at 0.3 from it and through its span, by a
    // drift of a fifth of the hold and a scatter of a third.
    const double angle = 0.002 * iteration;
    const Vec2 target(2.0 - 1.2 * std::sin(angle), 0.3 * std::cos(3 * angle) - 0.4 * std::cos(angle));
    const Vec2 x(m.coord(bar).x() + s.u(3 * bar), m.coord(bar).y() + s.u(3 * bar + 1));
    Vec2 drift = target - x;
    if (drift.norm() > 0.2 * hold) drift *= 0.2 * hold / drift.norm();
    for (int n = bar; n < m.numNodes(); ++n) {
      s.u(3 * n) += drift.x() + step(random) / 3;
      s.u(3 * n + 1) += drift.y() + step(random) / 3;
    }
    if (iteration % 7 == 0) s.commit();  // a new step: the lists found afresh
    const MemberContact::Nearby nearby = mc.nearby(m, s, mc.slack());
    left += static_cast<int>(nearby.reach.size() - nearby.near.size());
    for (std::size_t i = 0; i < nearby.candidates.size(); ++i) {
      if (!mc.evaluate(static_cast<int>(i), m, s, rule, false, f, k)) continue;
      ++touched;
      EXPECT_TRUE(std::binary_search(nearby.near.begin(), nearby.near.end(), static_cast<int>(i)))
          << "iteration " << iteration << ", pair " << nearby.candidates[i].node << "-"
          << nearby.candidates[i].element;
    }
  }
  EXPECT_GT(touched, 100);  // the bar pressed on the rod on both sides
  EXPECT_GT(left, 1000);    // and the list left out pairs its boxes kept
  // A node beside the rod's line beyond its end at t_n, across the line at
  // the step's first iterate (0.5 from it), then into the span by less than
  // the hold: from the side it came from it presses (the penetration h plus
  // its distance), and the list, found at the first iterate, holds it.
  State c;
  c.resize(m.numNodes());
  const auto place = [&](State& st, bool committed, double x, double y) {
    for (int n = bar; n < m.numNodes(); ++n) {
      st.u(3 * n) = x - m.coord(bar).x();
      st.u(3 * n + 1) = y - m.coord(bar).y() - 0.3 * (n - bar);
    }
    if (committed) st.commit();
  };
  place(c, true, 2.3, 0.02);
  place(c, false, 2.0 + 0.4 * hold, -0.5);
  (void)mc.nearby(m, c, mc.slack());  // found here
  place(c, false, 2.0 - 0.4 * hold, -0.5);
  const MemberContact::Nearby nearby = mc.nearby(m, c, mc.slack());
  int pressed = 0;
  for (std::size_t i = 0; i < nearby.candidates.size(); ++i) {
    if (nearby.candidates[i].node != bar ||
        !mc.evaluate(static_cast<int>(i), m, c, rule, false, f, k))
      continue;
    ++pressed;
    EXPECT_TRUE(std::binary_search(nearby.near.begin(), nearby.near.end(), static_cast<int>(i)));
  }
  EXPECT_EQ(pressed, 1);
}

}  // namespace
}  // namespace c2d
