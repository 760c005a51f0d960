// The joint set-up of elements/Joints.h: Condensed joints wrapped once (or
// switched to the Shared form), a node held only by joints, and the
// equivalence of the Condensed and the Shared joint forms in whole static and
// dynamic analyses.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>

#include "core/DofMap.h"
#include "core/Model.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/ReissnerFrame.h"
#include "solvers/Analysis.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d {
namespace {

using test::solveStep;

MaterialSet beamMaterial() {
  MaterialSet m = test::resultantMaterial(Kinematics::Finite, true);  // the Reissner element's
  m.resEA = 5.0e3;
  m.resGA = 2.0e3;
  m.resEI = 10.0;
  m.density = 1.0;
  m.A = 1.0;
  m.I = 0.01;
  return m;
}

// Propped frame with an internal hinge: nodes 0-1-2 | 3-4-5, joint master 2,
// slave 3 (coincident), base 0 clamped, node 5 on a roller.
Model hingedBeam(JointForm form) {
  Model m;
  m.materials()[1] = beamMaterial();
  const Vec2 x[] = {{0, 0}, {0.6, 0.15}, {1.2, 0.2}, {1.2, 0.2}, {1.8, 0.1}, {2.4, -0.1}};
  m.resizeNodes(6);
  for (int i = 0; i < 6; ++i) m.setCoord(i, x[i]);
  const std::array<int, 2> conn[] = {{0, 1}, {1, 2}, {3, 4}, {4, 5}};
  for (int e = 0; e < 4; ++e)
    m.setElement(e, std::make_unique<ReissnerFrame>(m.materials()[1], conn[e], m.coord(conn[e][0]),
                                                    m.coord(conn[e][1])));
  m.bound(0) = {1, 1, 1};
  m.bound(5) = {0, 1, 0};
  m.force(2) = {0.8, -3.0, 0.0};
  m.force(4) = {0.0, -2.0, 0.5};
  m.force(5) = {-1.0, 0.0, 0.2};
  m.joints().push_back({2, 3, form});
  return m;
}

TEST(JointedElementSetup, CondensedJointsAreWrappedOnceAndOtherwiseShared) {
  Model m = hingedBeam(JointForm::Condensed);
  const int version = m.topologyVersion();
  EXPECT_EQ(installJoints(m), 1);
  EXPECT_GT(m.topologyVersion(), version);
  ASSERT_EQ(jointedElements(m).size(), 1u);
  const JointedElement* je = jointedElements(m)[0];
  EXPECT_EQ(je->slaveNode(), 3);
  EXPECT_EQ(je->masterNode(), 2);
  EXPECT_EQ(je->slaveEnd(), 0);
  EXPECT_EQ(m.element(2).nodes(), (std::array<int, 2>{2, 4}));
  // Idempotent.
  const int v2 = m.topologyVersion();
  EXPECT_EQ(installJoints(m), 0);
  EXPECT_EQ(m.topologyVersion(), v2);
  EXPECT_EQ(jointedElements(m).size(), 1u);
  const DofMap dofs(m);
  EXPECT_FALSE(dofs.used(3));  // the slave left the global system

  // Two elements at the slave, or a loaded slave: Shared form.
  Model two = hingedBeam(JointForm::Condensed);
  two.setElement(4, std::make_unique<ReissnerFrame>(two.materials()[1], std::array{3, 5},
                                                    two.coord(3), two.coord(5)));
  EXPECT_EQ(installJoints(two), 1);
  EXPECT_EQ(two.joints()[0].form, JointForm::Shared);
  EXPECT_TRUE(jointedElements(two).empty());
  Model loaded = hingedBeam(JointForm::Condensed);
  loaded.force(3)[2] = 1.0;
  installJoints(loaded);
  EXPECT_EQ(loaded.joints()[0].form, JointForm::Shared);
  // A chain: the slave is the master of a further joint.
  Model chain = hingedBeam(JointForm::Condensed);
  chain.resizeNodes(7);
  chain.setCoord(6, chain.coord(3));
  chain.joints().push_back({3, 6, JointForm::Condensed});
  installJoints(chain);
  EXPECT_EQ(chain.joints()[0].form, JointForm::Shared);
}

TEST(JointedElementSetup, NodeHeldOnlyByJointsHasNoRotationEquation) {
  // Both elements at node 2 jointed there (element 1 through a second slave,
  // node 6): nothing puts a moment on node 2's rotation, which is then no
  // equation, and the static solution exists (the joint is a plain pin).
  Model m = hingedBeam(JointForm::Condensed);
  installJoints(m);
  EXPECT_GE(DofMap(m).eq(2, 2), 0);
  m.resizeNodes(7);
  m.setCoord(6, m.coord(2));
  auto inner =
      std::make_unique<ReissnerFrame>(m.materials()[1], std::array{1, 6}, m.coord(1), m.coord(6));
  m.setElement(1, std::make_unique<JointedElement>(std::move(inner), 1, 2));
  m.bumpTopology();
  const DofMap dofs(m);
  EXPECT_TRUE(dofs.used(2));
  EXPECT_GE(dofs.eq(2, 0), 0);
  EXPECT_EQ(dofs.eq(2, 2), -1);
  EXPECT_FALSE(dofs.used(6));
  Analysis an(m);
  an.setTolerance(1e-20);
  an.setDt(1);
  ASSERT_TRUE(an.advance());
  IterationInfo info;
  for (int i = 0; i < 30 && !info.converged; ++i) ASSERT_TRUE(an.iterate(false, true, info));
  EXPECT_TRUE(info.converged);
  EXPECT_EQ(an.state().u[2 * kNodeDofs + 2], 0.0);  // the rotation kept its value
}

// Nodal displacements (slave node from the joint) after n steps of dt.
Eigen::VectorXd run(JointForm form, const TimeIntegrator& ti, int steps, double dt) {
  Model m = hingedBeam(form);
  installJoints(m);
  Analysis an(m);
  an.setIntegrator(ti);
  an.setTolerance(1e-28);
  an.setDt(dt);
  if (!ti.dynamic()) an.setLoadFunction(1, ProportionalLoad::ramp());
  for (int s = 0; s < steps; ++s) {
    EXPECT_TRUE(solveStep(an)) << "step " << s;
  }
  an.commit();
  syncSlaveNodes(m, an.state());
  return an.state().u;
}

class JointedElementEquivalence : public ::testing::TestWithParam<int> {};

TEST_P(JointedElementEquivalence, CondensedAndSharedFormsGiveTheSameMotion) {
  const int which = GetParam();
  const TimeIntegrator ti = which == 0   ? TimeIntegrator::statics()
                            : which == 1 ? TimeIntegrator::midPoint(0, 0)
                            : which == 2 ? TimeIntegrator::midPoint(0.2, 0.1)
                                         : TimeIntegrator::newmark(0.25, 0.5);
  const int steps = which == 0 ? 6 : 25;
  const double dt = which == 0 ? 1.0 / 6 : 0.02;
  const Eigen::VectorXd a = run(JointForm::Condensed, ti, steps, dt);
  const Eigen::VectorXd b = run(JointForm::Shared, ti, steps, dt);
  const double scale = b.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.05);  // a visibly nonlinear response
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-9 * scale)
      << "a = " << a.transpose() << "\nb = " << b.transpose();
  // The hinge opens: slave and master rotations differ.
  EXPECT_GT(std::abs(b(3 * 3 + 2) - b(2 * 3 + 2)), 1e-2);
  EXPECT_EQ(a.segment<2>(9), a.segment<2>(6));
}

INSTANTIATE_TEST_SUITE_P(JointedElement, JointedElementEquivalence, ::testing::Values(0, 1, 2, 3));

}  // namespace
}  // namespace c2d
