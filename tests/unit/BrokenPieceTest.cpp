// Broken stays broken: a free piece of a member that breaks on the ground
// breaks once, where it carries a moment, and its broken hinge does not come
// back at full strength (elements/HingeToJoint.h, elements/Joints.h
// freeEnd).
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckResult;
using testing::DeckTempDir;
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
  EXPECT_NE(r.log.find(" 1 joint formed, 0 ruptured"), std::string::npos) << r.log;
}

}  // namespace
}  // namespace c2d
