// One softening hinge per localization zone (elements/LocalizationZones): the
// elements of a member within the zone length of an open midpoint hinge are
// held (no hinge of their own, moment at most Mu), the member ends at
// connections, corners and joints, and a rod whose adjacent elements would
// both open hinges in flight opens one per zone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <vector>

#include "core/Model.h"
#include "core/StepRule.h"
#include "elements/Joints.h"
#include "elements/LocalizationZones.h"
#include "elements/ReissnerFrame.h"
#include "solvers/Analysis.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d {
namespace {

// Elements along the polyline through `points` (one element between two
// consecutive points) with the hinged rod's laws and shortest piece lb.
Model chain(const std::vector<Vec2>& points, double lb) {
  Model m;
  m.materials()[1] = test::hingedRodMaterial(10.0);
  m.materials().at(1).softening->pieceLength = lb;
  m.resizeNodes(static_cast<int>(points.size()));
  for (int i = 0; i < static_cast<int>(points.size()); ++i) m.setCoord(i, points[i]);
  for (int i = 0; i + 1 < static_cast<int>(points.size()); ++i)
    m.setElement(i, std::make_unique<ReissnerFrame>(m.materials().at(1), std::array{i, i + 1},
                                                    m.coord(i), m.coord(i + 1)));
  return m;
}

ReissnerFrame& frame(Model& m, int e) {
  return dynamic_cast<ReissnerFrame&>(innermost(m.element(e)));
}

void openHinge(Model& m, int e) {
  HingedBendingState s = frame(m, e).section();
  s.hingeActive = true;
  frame(m, e).setSection(s);
}

std::set<int> heldElements(Model& m) {
  std::set<int> held;
  for (int e = 0; e < m.numElements(); ++e)
    if (frame(m, e).held()) held.insert(e);
  return held;
}

TEST(LocalizationZones, HoldTheMembersElementsWithinTheZoneOfAnOpenHinge) {
  // Eight elements of 0.125 m in line, then a corner and two more.
  std::vector<Vec2> p;
  for (int i = 0; i <= 8; ++i) p.emplace_back(0.125 * i, 0);
  p.emplace_back(1.0, 0.125);
  p.emplace_back(1.0, 0.25);
  Model m = chain(p, 0.3);
  m.bound(0) = m.bound(10) = {0, 0, 1};       // ends clamped: they carry moment
  EXPECT_EQ(LocalizationZones().hold(m), 0);  // no hinge open
  openHinge(m, 3);
  // Midpoints 0.125 and 0.25 m from the hinge's: held; 0.375 m: not.
  EXPECT_EQ(LocalizationZones().hold(m), 4);
  EXPECT_EQ(heldElements(m), (std::set<int>{1, 2, 4, 5}));
  // At the last element before the corner: the member ends there.
  openHinge(m, 3);
  HingedBendingState closed = frame(m, 3).section();
  closed.hingeActive = false;
  frame(m, 3).setSection(closed);
  openHinge(m, 7);
  LocalizationZones().hold(m);
  EXPECT_EQ(heldElements(m), (std::set<int>{5, 6}));
  // Lb = 0: no zone (the laws as the paper gives them).
  m.materials().at(1).softening->pieceLength = 0;
  EXPECT_EQ(LocalizationZones().hold(m), 0);
  // A joint ends the member: element 6 moved to a slave of node 6.
  m.materials().at(1).softening->pieceLength = 0.3;
  const int slave = m.addNode(m.coord(6));
  m.element(6).setNodes({slave, 7});
  m.joints().push_back(Joint{6, slave, JointForm::Condensed});
  ASSERT_EQ(installJoints(m), 1);
  m.bound(0) = m.bound(10) = {0, 0, 1};
  LocalizationZones().hold(m);
  // The joint carries no moment: it holds its zone on both sides (4 and 5 at
  // the master, 6 at the slave; 7's hinge is open), element 6 also 7's.
  EXPECT_EQ(heldElements(m), (std::set<int>{4, 5, 6}));
  closed = frame(m, 7).section();
  closed.hingeActive = false;
  frame(m, 7).setSection(closed);
  LocalizationZones().hold(m);
  EXPECT_EQ(heldElements(m), (std::set<int>{4, 5, 6, 7}));  // the corner ends it
}

// A member goes on through a joint's master: a column through a connection
// whose beam has a joint (the beam's end on a slave at the column's node).
TEST(LocalizationZones, AMemberGoesOnThroughAJointsMaster) {
  std::vector<Vec2> p;
  for (int i = 0; i <= 8; ++i) p.emplace_back(0.125 * i, 0);
  Model m = chain(p, 0.3);
  m.bound(0) = m.bound(8) = {0, 0, 1};
  const int slave = m.addNode(m.coord(2)), top = m.addNode(Vec2(0.25, 0.125));
  m.bound(top) = {0, 0, 1};
  m.setElement(8, std::make_unique<ReissnerFrame>(m.materials().at(1), std::array{slave, top},
                                                  m.coord(slave), m.coord(top)));
  m.joints().push_back(Joint{2, slave, JointForm::Condensed});
  ASSERT_EQ(installJoints(m), 1);
  openHinge(m, 3);
  LocalizationZones().hold(m);
  // 1 and 2 left of the hinge (through node 2), 4 and 5 right; the beam's
  // element 8 from its jointed end.
  EXPECT_EQ(heldElements(m), (std::set<int>{1, 2, 4, 5, 8}));
}

// An end that carries no moment holds its zone as an open hinge does: a free
// end, a pinned end, a joint's nodes (next to them the moment grows as V x
// from zero, and within Lb = Mu/Vu it cannot reach Mu); a clamped end, a
// nodal moment or a connection of more members does not.
TEST(LocalizationZones, EndsThatCarryNoMomentHoldTheirZones) {
  std::vector<Vec2> p;
  for (int i = 0; i <= 8; ++i) p.emplace_back(0.125 * i, 0);
  Model m = chain(p, 0.3);
  // Free at both ends: 0.0625 and 0.1875 m from each, held; 0.3125: not.
  EXPECT_EQ(LocalizationZones().hold(m), 4);
  EXPECT_EQ(heldElements(m), (std::set<int>{0, 1, 6, 7}));
  m.bound(0) = {1, 1, 0};  // pinned: the same
  m.bound(8) = {0, 0, 1};  // clamped: none
  LocalizationZones().hold(m);
  EXPECT_EQ(heldElements(m), (std::set<int>{0, 1}));
  m.force(0)[2] = 1.0;  // a nodal moment at the pin: none
  EXPECT_EQ(LocalizationZones().hold(m), 0);
  // A corner at node 8 (a second element there, its far end clamped): the
  // elements at a node carry its moment between them.
  m.force(0)[2] = 0;
  m.bound(0) = {0, 0, 1};
  m.bound(8) = {0, 0, 0};
  const int tip = m.addNode(Vec2(1.0, 0.125));
  m.setElement(8, std::make_unique<ReissnerFrame>(m.materials().at(1), std::array{8, tip},
                                                  m.coord(8), m.coord(tip)));
  m.bound(tip) = {0, 0, 1};
  EXPECT_EQ(LocalizationZones().hold(m), 0);
  // A joint at node 4 (element 4 moved to a slave there): elements 2, 3 and
  // 4, 5 held; a hinge open within the zone (one opened before the joint) is
  // not held and holds its own.
  const int slave = m.addNode(m.coord(4));
  m.element(4).setNodes({slave, 5});
  m.joints().push_back(Joint{4, slave, JointForm::Condensed});
  ASSERT_EQ(installJoints(m), 1);
  LocalizationZones().hold(m);
  EXPECT_EQ(heldElements(m), (std::set<int>{2, 3, 4, 5}));
  openHinge(m, 5);
  LocalizationZones().hold(m);
  EXPECT_EQ(heldElements(m), (std::set<int>{2, 3, 4, 6, 7}));
}

// A held element bent past Mu: its moment stays at Mu (the plastic curvature
// takes the rest), it reports no demand, and its tangent is the residual's
// derivative (static and mid-point rules, an element turned by 0.7 rad).
TEST(LocalizationZones, AHeldElementStaysAtMuWithItsTangentExact) {
  const MaterialSet mat = test::hingedRodMaterial(10.0);
  const Vec2 x1(0.3, -0.2), x2 = x1 + 0.25 * Vec2(std::cos(0.7), std::sin(0.7));
  StepRule stat, mid;
  mid.scheme = Scheme::MidPoint;
  mid.alpha = 0.1;
  mid.ca = 4 / (1e-2 * 1e-2);
  mid.av = -4 / 1e-2;
  mid.aa = -1;
  for (const StepRule* rule : {&stat, &mid}) {
    ReissnerFrame e(mat, {0, 1}, x1, x2);
    e.setHeld(true);
    ElementKinematics kin;
    kin.d.setZero();
    kin.dn.setZero();
    kin.vn.setZero();
    kin.an.setZero();
    kin.d(2) = -0.04;  // curvature 0.16/0.25 = 0.64: EI K = 640, far past Mu = 2.4
    kin.d(5) = 0.12;
    ElemVec r;
    ElemMat k;
    ASSERT_TRUE(e.evaluate(kin, *rule, true, r, k));
    EXPECT_NEAR(e.section().M, 2.4, 1e-12);
    EXPECT_EQ(e.hingeDemand(), 0.0);
    EXPECT_FALSE(e.hinge().active);
    const ElemMat fd = test::centralDifferenceTangent(e, kin, *rule, 1e-7);
    EXPECT_LT((k - fd).norm(), 1e-6 * k.norm());
    e.setHeld(false);  // released: the same state opens its hinge
    ASSERT_TRUE(e.evaluate(kin, *rule, true, r, k));
    EXPECT_GT(e.hingeDemand(), 1.0);
  }
}

// A rod of 1 m in n FINIte elements (the hinged rod's laws, softening modulus
// ks), pinned at its top end and released horizontally under gravity (the
// flying rod of InelasticReissner with a finer mesh), for 0.3 s: the moment
// peaks a quarter of the way along, where adjacent elements reach Mu within
// 0.3 ms of each other. With ks = -0.5 no hinge fails (no joint) by then.
struct Outcome {
  std::vector<int> opened;  // elements, in the order their hinges opened
  double worstRatio = 0;    // largest |M|/Mu of a committed state
  double balance = 0;       // energy balance error, relative to the peak
};

Outcome dropRod(double lb, double ks = -0.5, int n = 16) {
  std::vector<Vec2> p;
  for (int i = 0; i <= n; ++i) p.emplace_back(1.0 * i / n, 0);
  Model m = chain(p, lb);
  for (int e = 0; e < n; ++e) {  // the softening modulus ks
    m.materials().at(1).softening->Ks = ks;
    m.setElement(e, std::make_unique<ReissnerFrame>(m.materials().at(1), std::array{e, e + 1},
                                                    m.coord(e), m.coord(e + 1)));
  }
  m.gravity() = Vec2(0, -9.81);
  m.bound(0) = {1, 1, 0};
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0.1, 0.1));
  an.setDt(0.005);
  Outcome out;
  an.onHingeActivated = [&](int e, const HingeInfo&) { out.opened.push_back(e); };
  double peak = 0, balance0 = 0, worst = 0;
  for (int s = 0; s < 60; ++s) {
    EXPECT_TRUE(an.advance());
    IterationInfo info;
    for (int i = 0; i < 40 && !info.converged; ++i) EXPECT_TRUE(an.iterate(true, true, info));
    EXPECT_TRUE(info.converged) << "step " << s;
    if (!info.converged) break;
    EXPECT_TRUE(an.commit());
    for (const auto& [e, h] : an.hingeCarriers())
      if (h->hinge().ultimate > 0)
        out.worstRatio =
            std::max(out.worstRatio, std::abs(h->hinge().moment) / h->hinge().ultimate);
    const Energy en = an.energy();
    if (s == 0) balance0 = en.balance();
    peak = std::max({peak, en.kinetic, std::abs(en.external), en.dissipated});
    worst = std::max(worst, std::abs(en.balance() - balance0));
  }
  out.balance = worst / peak;
  return out;
}

// Pairs of opened hinges whose midpoints lie nearer than lb.
int pairsWithin(const std::vector<int>& opened, double lb) {
  int pairs = 0;
  for (std::size_t a = 0; a < opened.size(); ++a)
    for (std::size_t b = a + 1; b < opened.size(); ++b)
      pairs += opened[a] != opened[b] && 0.0625 * std::abs(opened[a] - opened[b]) < lb;
  return pairs;
}

TEST(LocalizationZones, OneHingePerZoneInARodWhoseAdjacentElementsWouldBothOpen) {
  const Outcome free = dropRod(0);
  const Outcome zoned = dropRod(0.3);
  // Without zones adjacent elements open hinges of their own: elements 4 and 5
  // 0.24 ms apart, then 6, 7, 8 and 9 (six hinges in a row).
  EXPECT_GT(pairsWithin(free.opened, 0.3), 0);
  EXPECT_EQ(free.opened.size(), 6u);
  // With them, no two hinges within 0.3 m (4, then 9), and no member above Mu:
  // the held elements stay at Mu at most.
  EXPECT_GT(zoned.opened.size(), 0u);
  EXPECT_EQ(pairsWithin(zoned.opened, 0.3), 0);
  // None within 0.3 m of the pinned end or the free tip (neither carries a
  // moment): element 4 (midpoint 0.28 m from the pin) opened without that.
  for (int e : zoned.opened) {
    EXPECT_GE(0.0625 * (e + 0.5), 0.3) << "element " << e;
    EXPECT_LE(0.0625 * (e + 0.5), 0.7) << "element " << e;
  }
  EXPECT_LT(zoned.worstRatio, 1 + 1e-6);
  EXPECT_LT(zoned.balance, 1e-8);
  EXPECT_LT(free.worstRatio, 1 + 1e-6);
}

}  // namespace
}  // namespace c2d
