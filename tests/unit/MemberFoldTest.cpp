// elements/MemberFold: RC members (with a hinge law) bent through more than a
// quarter turn between their ends are found, with the inner element's nodes
// and the fold; members bent less, and elastic members however bent, are not.
// A condensed joint's relative rotation counts at its end; a failed hinge
// that made no joint is named as the fold's cause.
#include <gtest/gtest.h>

#include <memory>
#include <numbers>

#include "core/Model.h"
#include "core/State.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/MemberFold.h"
#include "elements/ReissnerFrame.h"

namespace c2d {
namespace {

MaterialSet frame(int number, bool withStrength) {
  MaterialSet mat;
  mat.number = number;
  mat.elementType = "FRAMe";
  mat.kinematics = Kinematics::Finite;
  mat.resEA = 1e6;
  mat.resGA = 5e5;
  mat.resEI = 1e3;
  if (withStrength) {
    mat.hardening = HardeningData{1.0, 2.0, 400, 40};
    mat.softening = SofteningData{2.4, -8, 0.6};
  }
  return mat;
}

TEST(MemberFold, OnlyRcMembersBentBeyondAQuarterTurn) {
  // Four elements along x: 1-3 with a hinge law, 4 elastic.
  Model m;
  m.materials()[1] = frame(1, true);
  m.materials()[2] = frame(2, false);
  m.resizeNodes(5);
  for (int i = 0; i <= 4; ++i) m.setCoord(i, Vec2(i, 0));
  for (int i = 0; i < 4; ++i) {
    const MaterialSet& mat = m.materials().at(i < 3 ? 1 : 2);
    m.setElement(i, std::make_unique<ReissnerFrame>(mat, std::array{i, i + 1}, m.coord(i),
                                                    m.coord(i + 1)));
  }
  State s;
  s.resize(m.numNodes());
  const double theta[5] = {0.0, 2.0, 2.5, 2.5 - 0.51 * std::numbers::pi, 10.0};
  for (int i = 0; i <= 4; ++i) s.u[3 * i + 2] = theta[i];
  const std::vector<MemberFold> folds = foldedMembers(m, s);
  ASSERT_EQ(folds.size(), 2u);  // elements 1 (2 rad) and 3 (0.51 pi); 2 (0.5) and 4 (elastic) not
  EXPECT_EQ(folds[0].element, 0);
  EXPECT_NEAR(folds[0].fold, 2.0, 1e-15);
  EXPECT_EQ(folds[0].nodes[0], 0);
  EXPECT_EQ(folds[0].nodes[1], 1);
  EXPECT_EQ(folds[1].element, 2);
  EXPECT_NEAR(folds[1].fold, 0.51 * std::numbers::pi, 1e-12);
  EXPECT_FALSE(folds[0].failedHinge);
  // Element 1's hinge fully softened (M = 0) without a joint: the fold says
  // so (the log names it as the cause).
  HingedBendingState failed;
  failed.hingeActive = failed.hingeFailed = true;
  failed.jump.alpha = failed.jump.xi = 2.0;
  dynamic_cast<ReissnerFrame&>(m.element(0)).setSection(failed);
  const std::vector<MemberFold> withFailed = foldedMembers(m, s);
  ASSERT_EQ(withFailed.size(), 2u);
  EXPECT_TRUE(withFailed[0].failedHinge);
  EXPECT_FALSE(withFailed[1].failedHinge);

  // A condensed joint at node 1 of element 1 whose relative rotation takes
  // the inner end back to node 0's rotation: not folded.
  const int slave = m.addNode(m.coord(1));
  m.element(0).setNodes({0, slave});
  m.joints().push_back(Joint{1, slave, JointForm::Condensed});
  ASSERT_EQ(installJoints(m), 1);
  s.resize(m.numNodes());
  jointedElements(m).front()->setRelativeState(-2.0);
  const std::vector<MemberFold> after = foldedMembers(m, s);
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(after[0].element, 2);
}

}  // namespace
}  // namespace c2d
