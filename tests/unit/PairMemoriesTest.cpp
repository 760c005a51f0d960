// What member contact pairs carry from step to step (core/contact/PairMemories):
// a friction spring let go out of reach, pairs set free inside their contact
// distance, the held side of a ruptured joint's end node, the energy a commit
// releases (held pairs let go, turns inside a step, nodes pushed past the
// centre line).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "ContactTestSupport.h"
#include "core/contact/CrushingLaw.h"
#include "core/contact/MemberContact.h"
#include "core/contact/MemberCrossing.h"
#include "core/contact/SpringFriction.h"
#include "solvers/ProportionalLoad.h"
#include "solvers/TimeIntegrator.h"

namespace c2d {
namespace {

using test::newRod;
using test::position;
using test::rod;
using test::solveStep;

TEST(MemberContactModel, APairInMemoryOutOfReachLetsGoOfItsFrictionSpring) {
  // A commit's passes visit the pairs that may touch and those in memory
  // (MemberContact::touching): a pair whose node has left the segment's reach
  // with its friction spring stretched lets go of it, the spring's energy
  // counted as dissipated, and its memory is dropped.
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 10, 1.0, 2.5e-3 / 3);  // r = 0.05
  newRod(m, Vec2(0, 0), Vec2(2, 0), 8);
  const int bar = newRod(m, Vec2(0.9, 0.2), Vec2(0.9, 1.2), 4);  // its lowest node 0.2 above
  const double k = 1e3, stretch = 0.01;
  m.memberContact() = MemberContactData{k, 0, -1, 1, 0.5};
  Assembler as(m);
  as.refresh();
  MemberContact& mc = *as.memberContact();
  State s;
  s.resize(m.numNodes());
  const std::vector<ContactPair>& candidates = mc.candidates(m, s);
  const auto pair = std::find_if(candidates.begin(), candidates.end(),
                                 [&](const ContactPair& p) { return p.node == bar; });
  ASSERT_NE(pair, candidates.end());  // a candidate of the search's margin
  s.pairs = {PairMemory{pair->key(), 0.0, 0.0, stretch, pair->h, 0}};
  mc.openPairs(m, s);
  const StepRule rule = TimeIntegrator::midPoint(0, 0).rule(0.01);
  EXPECT_NEAR(as.contactDissipation(s, rule), springFrictionEnergy(k, stretch), 1e-15);
  as.commitContact(s);
  EXPECT_TRUE(s.pairs.empty());
}

// Two rods meeting end to end at x = 1 at a right angle, their end nodes
// coincident but not tied (a joint that ruptured): rod a along x from 0 to 1,
// rod b up from (1, 0), four elements each; section radius sqrt(3 I / A) =
// 0.0158 (contact distance 0.0316), member contact k = 1e3.
// Statics, no loads.
struct RupturedCorner {
  Model m;
  int a = 0, b = 0;
  std::unique_ptr<Assembler> as;
  State s;
  StepRule rule = TimeIntegrator::statics().rule(1.0);
  Eigen::VectorXd factors;
  RupturedCorner() {
    m.materials()[1] = rod(1, 1e4, 1e4, 1e4, 10, 2.5e-3 / 3);
    a = newRod(m, Vec2(0, 0), Vec2(1, 0), 4);
    b = newRod(m, Vec2(1, 0), Vec2(1, 1), 4);
    m.memberContact() = MemberContactData{1e3, 0, -1};
    as = std::make_unique<Assembler>(m);
    as->refresh();
    s.resize(m.numNodes());
    factors = Eigen::VectorXd::Zero(3 * m.numNodes());
  }
};

TEST(MemberContactModel, MembersSetFreeInsideTheirDistanceStartAtZeroForce) {
  // The ruptured corner: each end node lies on the
  // other rod's end, inside the contact distance. They start at zero force
  // (the offsets); one end moved into the other rod's span past its centre
  // line is pushed back.
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  Assembler& as = *corner;
  as.openContacts(s);
  ASSERT_FALSE(s.pairs.empty());
  for (const PairMemory& p : s.pairs) EXPECT_GT(p.offset, 0.0);
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  EXPECT_EQ(as.contactForces().cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(as.contactEnergy(s), 0.0);
  // Rod b's end node (b) moved down into rod a's last element, past its
  // centre line (it came from above): pushed back up.
  s.u(3 * b + 0) = -0.1;
  s.u(3 * b + 1) = -0.01;
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  EXPECT_GT(as.contactEnergy(s), 0.0);
}

TEST(MemberContactModel, ARupturedJointsEndNodeIsHeldOnItsMembersSide) {
  // The ruptured corner: rod b's end node lies on rod a's centre
  // line, at its end, so its side is a toss-up; it is held on the side where
  // rod b lies (above). Rod b moved 1 mm down, it is pushed back, and a
  // commit there does not turn it to the wrong side: the contact still pushes
  // up at the next step. Clear of the line, the pair lets the held side go.
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  Assembler& as = *corner;
  as.openContacts(s);
  // The pair (node b, rod a's last element) and (rod a's end node, rod b's first).
  const int lastA = 3, firstB = 4;
  auto pairOf = [&](int node, int element) -> const PairMemory* {
    for (const PairMemory& p : c.s.pairs)
      if (p.key == ContactPair{node, element}.key()) return &p;
    return nullptr;
  };
  ASSERT_NE(pairOf(b, lastA), nullptr);
  EXPECT_EQ(pairOf(b, lastA)->side, 1);
  ASSERT_NE(pairOf(a + 4, firstB), nullptr);
  EXPECT_EQ(pairOf(a + 4, firstB)->side, 1);  // rod a lies left of rod b (up its axis)
  for (int n = b; n <= b + 4; ++n) s.u(3 * n + 1) = -0.001;  // rod b moved down 1 mm
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  const double below = as.contactEnergy(s);
  // Rod a's end node is now 1 mm inside rod b's first element, on its line:
  // it meets that element's end face (x - w / 2, w = 0.01 h).
  const double face = 0.001 - 0.005 * 2 * std::sqrt(2.5e-4);
  EXPECT_NEAR(below, 0.5 * 1e3 * (0.001 * 0.001 + face * face), 1e-12);
  as.commitContact(s);
  s.commit();
  EXPECT_EQ(pairOf(b, lastA)->side, 1);
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  EXPECT_NEAR(as.contactEnergy(s), below, 1e-15);
  EXPECT_EQ(as.pushedThrough(), 0);
  // Above the line by 2 mm it is still held; clear of it by a quarter of the
  // contact distance (0.25 * 0.0316 m), the side at t_n takes over.
  for (const auto& [y, held] : {std::pair{0.002, 1}, std::pair{0.01, 0}}) {
    for (int n = b; n <= b + 4; ++n) s.u(3 * n + 1) = y;
    ASSERT_TRUE(as.assemble(s, rule, factors, false));
    as.commitContact(s);
    s.commit();
    ASSERT_NE(pairOf(b, lastA), nullptr);
    EXPECT_EQ(pairOf(b, lastA)->side, held) << y;
  }
}

TEST(MemberContactModel, RupturedJointsPiecesPressedTipToTipDoNotPassEachOther) {
  // A ruptured joint's two pieces lying end to end, kinked 0.1 rad at the
  // joint (each end node on the other's end, held on the side its own piece
  // lies), pressed together along their axes: piece a clamped at its far
  // end, piece b's far end on a roller pushed by 2 kN (contact k = 2e3,
  // distance 0.035 m). With the whole distance offset the pairs' reach is
  // zero there: b's end node slid into a's span along a's line (pushed only
  // across it, by k 0.1 x), and the pieces ended crossed, their tips 0.19 m
  // past each other. The held end faces push it back out along the segment:
  // the tips overlap by less than the force over k (0.6 mm).
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 50.0, 1.0, 1e-4);  // r = 0.0173
  const int a = newRod(m, Vec2(-1, 0), Vec2(0, 0), 4);
  const int b = newRod(m, Vec2(0, 0), Vec2(1, -0.1), 4);
  m.bound(a) = {1, 1, 1};
  m.bound(b + 4) = {0, 1, 1};
  m.force(b + 4) = {-2.0, 0, 0};
  m.memberContact() = MemberContactData{2e3, 1, -1};
  Analysis an(m);
  an.setLoadFunction(1, ProportionalLoad::table({{0.0, 0.0}, {0.2, 1.0}, {10.0, 1.0}}));
  an.setIntegrator(TimeIntegrator::midPoint(0.1, 0));
  an.setDt(0.01);
  State& s = an.state();
  for (int step = 0; step < 100; ++step) {
    ASSERT_TRUE(solveStep(an)) << "step " << step;
    an.commit();
  }
  EXPECT_TRUE(findCrossings(m, s).empty());
  const double overlap = position(m, s, a + 4).x() - position(m, s, b).x();
  EXPECT_LT(overlap, 2.0 / 2e3);
}

TEST(MemberContactModel, ACommitReleasesWhatAHeldPairNoLongerStores) {
  // Rod b's end node, held above rod a, ends a step beyond rod a's end and
  // below its line (the held side's wedge presses it: p = (d^2 - e^2) / rho
  // > 0) but farther from the segment than the contact distance: at the
  // committed state alone the pair is apart. What it stored is released at
  // the commit, so that the energy before the commit less the released
  // equals the energy after it. (Rod a's end node, inside rod b's tilted
  // first element by 5.5 cm, is 3.3 cm from its line: beyond its end face's
  // cap, the contact distance 3.16 cm.)
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  Assembler& as = *corner;
  as.openContacts(s);
  s.u(3 * b + 0) = 0.04;
  s.u(3 * b + 1) = -0.05;
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  const double before = as.contactEnergy(s);
  EXPECT_GT(before, 0.0);
  const double released = as.commitContact(s);
  s.commit();
  EXPECT_NEAR(before - released, as.contactEnergy(s), 1e-12);
  EXPECT_EQ(as.contactEnergy(s), 0.0);
}

TEST(MemberContactModel, AHeldPairsTurnInsideTheStepIsReleasedOnce) {
  // The ruptured corner with crushing pairs (e = 0.5): rod b's end node, held
  // above rod a, ends the step 1 cm below its centre line, having moved down
  // at t_n and up at t_n+1: the pair's turn fell inside the step, and its
  // loading point becomes the peak its mass came back from. The energy
  // before the commit less the released must be the energy after it (the
  // crushing the new loading point took was booked twice: the account's
  // balance stood off by that much at such commits).
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  m.memberContact() = MemberContactData{1e3, 0, -1, 0.5, 0};
  Assembler& as = *corner;
  as.restartContactSearch();
  as.openContacts(s);
  s.u(3 * b + 1) = -0.01;
  s.vn(3 * b + 1) = -1.0;
  s.v(3 * b + 1) = 0.5;
  ASSERT_TRUE(as.assemble(s, rule, factors, false));
  const double before = as.contactEnergy(s);
  EXPECT_GT(before, 0.0);
  const double released = as.commitContact(s);
  s.commit();
  const double after = as.contactEnergy(s);
  EXPECT_GT(released, 0.0);  // the turn's crushing
  EXPECT_LT(after, before);
  EXPECT_NEAR(before - released, after, 1e-12);
}

TEST(MemberContactModel, OpeningPairsKeepsOneMemoryPerPair) {
  // The ruptured corner, the pair (rod b's end node, rod a's last element)
  // already in memory: opening the others (whose keys sort before it) must
  // not give it a second memory.
  RupturedCorner c;
  auto& [m, a, b, corner, s, rule, factors] = c;
  Assembler& as = *corner;
  const std::uint64_t known = ContactPair{b, 3}.key();
  s.pairs.push_back({known, 0.0, 0.01, 0.0, 0.0316, 0});
  as.openContacts(s);
  ASSERT_GT(s.pairs.size(), 1u);
  int copies = 0;
  for (const PairMemory& p : s.pairs) copies += p.key == known;
  EXPECT_EQ(copies, 1);
  EXPECT_TRUE(std::is_sorted(s.pairs.begin(), s.pairs.end(),
                             [](const PairMemory& x, const PairMemory& y) { return x.key < y.key; }));
}

TEST(MemberContactModel, ANodePushedPastTheCentreLineReleasesWhatItsOldSideStored) {
  // A rod and a rod standing on it whose lower end ends the step 0.01 below
  // the first rod's centre line: seen from above its penetration is h + 0.01,
  // from below h - 0.01 (h the contact distance). The commit sees it from
  // below from then on, and returns the energy k ((h + 0.01)^2 - (h - 0.01)^2)
  // / 2 as released; the stored energy drops by as much.
  Model m;
  m.materials()[1] = rod(1, 1e4, 1e4, 1e4, 10, 2.5e-3 / 3);
  newRod(m, Vec2(0, 0), Vec2(2, 0), 2);
  const int stand = newRod(m, Vec2(0.5, 1.0), Vec2(0.5, 2.0), 2);
  const double k = 1e3;
  m.memberContact() = MemberContactData{k, 0, -1};
  Assembler as(m);
  as.refresh();
  const double h = 2 * as.memberContact()->radius(0);
  ASSERT_GT(h, 0.02);
  State s;
  s.resize(m.numNodes());
  for (int n = stand; n < stand + 3; ++n) {
    s.un(3 * n + 1) = -0.99;  // 0.01 above the centre line
    s.u(3 * n + 1) = -1.01;   // 0.01 below it
  }
  const Eigen::VectorXd factors = Eigen::VectorXd::Zero(3 * m.numNodes());
  ASSERT_TRUE(as.assemble(s, TimeIntegrator::statics().rule(1.0), factors, false));
  const double above = h + 0.01, below = h - 0.01;
  const double before = as.contactEnergy(s);
  EXPECT_NEAR(before, 0.5 * k * above * above, 1e-12);
  const double released = as.commitContact(s);
  EXPECT_NEAR(released, 0.5 * k * (above * above - below * below), 1e-12);
  EXPECT_EQ(as.pushedThrough(), 1);
  s.commit();
  EXPECT_NEAR(as.contactEnergy(s), before - released, 1e-12);
}

}  // namespace
}  // namespace c2d
