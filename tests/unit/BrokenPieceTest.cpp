// Broken stays broken: a free piece of a member that breaks on the ground
// breaks once, where it carries a moment, and its broken hinge does not come
// back at full strength (elements/HingeToJoint.h, elements/Joints.h
// freeEnd).
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckResult;
using testing::DeckTempDir;
using testing::readCsv;
using testing::runDeckText;

// Two FINIte elements with the six-storey frame's column section and laws (Mu
// = 250 kN m), a floor's mass at the middle node, dropped 20 m, tilted, onto
// the main example's crushing ground: the impact breaks one element at Mu.
const char* kPiece = R"(FEAP * * a free two-element piece dropped 20 m
  0 0 0 2 3 2

COORdinates
  1 0 0 20
  2 0 1.5 20.3
  3 0 3 20.2

ELEMents
  1 0 1 1 2
  2 0 1 2 3

MATErial,1 columns
  FRAMe
    RESUltant STIFfness 3.6e6 1.2e6 48000
    CROSs section 0.12 1.6e-3
    DENSity,,2.5
    HARDening BILInear 100 245 12450 195
    SOFTening LINEar 250 -723 0.6
    FINIte

MASS
  2 0 10 10 0

CONTact
  GROUnd,,0,1e5,1,0.5,0.3

GRAVity,,0,-9.81

END
BATCh
  DYNAmic,ENERgy,0.1,0.1
  AUTO,CUT,1e-6,1
  DT,,0.01
  LOOP,,100000
    TIME,REST,6,1e-5,0.5
    LOOP,,30
      TANG,,1
    NEXT
  NEXT
END
STOP
)";

TEST(BrokenPiece, AFreeTwoElementPieceBreaksOnceAtItsMiddleOnTheGround) {
  DeckTempDir dir;
  const DeckResult r = runDeckText(dir, "piece.inp", kPiece);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message << r.log;
  // One hinge opens at Mu, softens and becomes a joint at the middle node
  // (the free ends 1 and 3 carry no moment), and that is all: no hinge opens
  // again at Mu where the piece has broken.
  const std::regex formed(
      "joint  formed at t = [^:]*: element [12], fully softened hinge, at node "
      "([0-9]+) \\(slave node 4\\)");
  std::smatch joint;
  ASSERT_TRUE(std::regex_search(r.log, joint, formed)) << r.log;
  EXPECT_EQ(joint[1], "2");
  const std::size_t jointAt = r.log.find("joint  formed");
  EXPECT_EQ(r.log.find("joint  formed", jointAt + 1), std::string::npos) << r.log;
  // Both elements reach Mu at the middle node within the impact (the moment
  // is continuous there); no hinge opens after the piece has broken.
  const std::size_t opened = r.log.find("activated at t = ");
  ASSERT_NE(opened, std::string::npos) << r.log;
  EXPECT_LT(opened, jointAt);
  EXPECT_EQ(r.log.find("activated at t = ", jointAt), std::string::npos) << r.log;
  EXPECT_NE(r.log.find(" 1 softened fully into joint, 0 members parted past the rotation capacity"), std::string::npos) << r.log;
}

// A double pendulum of two elements (hand-given laws, rupture rotation 0.5
// rad), pinned at node 1 and joined at nodes 2-3, swings down from the
// horizontal: the joint ruptures in flight at t = 0.33 s and the outer
// element flies free. The rupture gives the freed piece the slave's state
// (the master's translation and rates, its own rotation): its kinetic and
// stored energy are those it had, nothing is released or stored there, and
// its centre falls at g from that instant (no kick). Node 3, the joint's
// slave, is the freed piece's node there.
const char* kRupturedPendulum = R"(FEAP * * a double pendulum whose joint ruptures
  0 0 0 2 3 2

COORdinates
  1 0 0 10
  2 0 1.5 10
  3 0 1.5 10
  4 0 3 10

ELEMents
  1 0 1 1 2
  2 0 1 3 4

MATErial,1
  FRAMe
    RESUltant STIFfness 3.6e6 1.2e6 48000
    CROSs section 0.12 1.6e-3
    DENSity,,2.5
    HARDening BILInear 100 245 12450 195
    SOFTening LINEar 265 -723 0.5
    FINIte

JOINt
  2 3

BOUNdary
  1 0 1 1 0

GRAVity,,0,-9.81

END
BATCh
  DYNAmic,ENERgy,0.1,0.1
  DT,,0.01
  TPLOt
  LOOP,,80
    TIME
    LOOP,,30
      TANG,,1
    NEXT
  NEXT
END
velo,3,2
velo,4,2
ener

STOP
)";

TEST(BrokenPiece, APieceFreedByARuptureInFlightKeepsItsEnergyAndFallsAtG) {
  DeckTempDir dir;
  const DeckResult r = runDeckText(dir, "pendulum.inp", kRupturedPendulum);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message << r.log;
  const std::regex ruptured("joint  ruptured at t = ([0-9.e+-]+): element 2 separates at node 2");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.log, m, ruptured)) << r.log;
  const double tr = std::stod(m[1]);
  const auto csv = readCsv(r.out / "pendulum_tplot.csv");
  const auto t = csv.column("time"), kin = csv.column("kinetic"), bal = csv.column("balance"),
             dis = csv.column("dissipated"), vy3 = csv.column("velo_3_2"),
             vy4 = csv.column("velo_4_2");
  ASSERT_GT(t.size(), 60u);
  double peak = 0;
  for (double k : kin) peak = std::max(peak, k);
  ASSERT_GT(peak, 1.0);
  for (std::size_t i = 1; i < t.size(); ++i) {
    // Nothing gained or booked away at the rupture or anywhere else.
    EXPECT_NEAR(bal[i], bal[0], 1e-10 * peak) << "t = " << t[i];
    EXPECT_GE(dis[i] - dis[i - 1], -1e-10 * peak) << "t = " << t[i];
    // Once free, the piece's centre (its two nodes' equal masses) falls at
    // g: dv_y = -g dt every step (its momentum, kept by the scheme).
    if (t[i - 1] > tr + 1e-9) {
      const double dv = 0.5 * (vy3[i] + vy4[i] - vy3[i - 1] - vy4[i - 1]);
      EXPECT_NEAR(dv, -9.81 * (t[i] - t[i - 1]), 1e-9) << "t = " << t[i];
    }
  }
}

// The same pendulum with a shortest piece Lb = 2 m: its joint lies 1.5 m from
// either free end (the pin at node 1, the tip at node 4), so it does not
// rupture past thetaR; the log says so once, naming the free end.
TEST(BrokenPiece, AJointWithinTheShortestPieceOfAFreeEndIsHeldAndLoggedOnce) {
  DeckTempDir dir;
  std::string deck = kRupturedPendulum;
  const std::string soft = "SOFTening LINEar 265 -723 0.5";
  deck.replace(deck.find(soft), soft.size(), soft + " 0 2");
  const DeckResult r = runDeckText(dir, "held.inp", deck);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message << r.log;
  EXPECT_EQ(r.log.find("joint  ruptured"), std::string::npos) << r.log;
  const std::string held = "element 2 at node 2, relative rotation ";
  const std::size_t at = r.log.find("joint  held at t = ");
  ASSERT_NE(at, std::string::npos) << r.log;
  EXPECT_NE(r.log.find(held, at), std::string::npos);
  EXPECT_NE(r.log.find("within the shortest piece Lb = 2.000000e+00 of the free end at node 1", at),
            std::string::npos);
  EXPECT_EQ(r.log.find("joint  held", at + 1), std::string::npos);  // once
}

// One element of a SECTion column (0.4 x 0.4 m) standing on its foot on a
// ground with friction mu = 0.5, gravity tilted by 0.7 g (an incline steeper
// than mu): the friction at the foot holds it back while gravity pulls its
// top on, so it topples (free rotations at both ends: nothing holds it
// upright), its top down from 1.5 m to the ground within a second.
const char* kStandingPiece = R"(FEAP * * a piece standing on one frictional foot
  0 0 0 2 3 2

COORdinates
  1 0 0 0
  2 0 0 1.5

ELEMents
  1 0 1 1 2

MATErial,1
  FRAMe
    SECTion RECTangular 0.4 0.4 30e3 500e3
    REBAr 0.05 9.42e-4 0.35 9.42e-4
    DENSity,,2.5
    FINIte

CONTact
  GROUnd,,0,1e5,0,0.5,0.3

GRAVity,,0.7*9.81,-9.81

END
BATCh
  DYNAmic,ENERgy,0.1,0.1
  DT,,0.01
  TPLOt
  LOOP,,100
    TIME
    LOOP,,30
      TANG,,1
    NEXT
  NEXT
END
disp,2,2

STOP
)";

TEST(BrokenPiece, APieceStandingOnOneFrictionalFootTopples) {
  DeckTempDir dir;
  const DeckResult r = runDeckText(dir, "stand.inp", kStandingPiece);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message << r.log;
  const auto csv = readCsv(r.out / "stand_tplot.csv");
  const auto t = csv.column("time"), y = csv.column("disp_2_2");
  ASSERT_FALSE(t.empty());
  ASSERT_GE(t.back(), 0.99);
  double lowest = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] <= 1.0) lowest = std::min(lowest, y[i]);
  // The top (1.5 m up) reaches the ground: it lies on its side.
  EXPECT_LT(lowest, -1.4);
}

}  // namespace
}  // namespace c2d
