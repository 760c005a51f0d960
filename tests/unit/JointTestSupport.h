#pragma once
// What the joint tests (JointedElementTest, RigidJointTest) share: the
// integrators' step rules, the trial states of the tangent checks and the
// check itself.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "solvers/TimeIntegrator.h"
#include "tests/unit/ElementTestSupport.h"

namespace c2d::test {

// The scheme's rule for dt = 0.05 as the run's integrators form it.
inline StepRule integratorRule(Scheme s) {
  switch (s) {
    case Scheme::Static:
      return TimeIntegrator::statics().rule(0.05);
    case Scheme::Newmark:
      return TimeIntegrator::newmark(0.3, 0.6).rule(0.05);
    case Scheme::MidPoint:
      return TimeIntegrator::midPoint(0.1, 0.05).rule(0.05);
  }
  return {};
}

// Trial `trial` of a tangent check on the element x1-x2: a rigid turn of 0.8
// trial rad from t_n, perturbed by `scale`, with random rates and
// accelerations at t_n.
inline ElementKinematics trialKinematics(std::mt19937& gen, const Vec2& x1, const Vec2& x2,
                                         double scale, int trial) {
  const Vec2 o = Vec2::Zero();
  return {rigidMotion(x1, x2, 0.8 * trial, o, Vec2(0.2, -0.1)) + randomVec(gen, scale),
          rigidMotion(x1, x2, 0.8 * trial - 0.1, o, Vec2(0.1, 0)) + randomVec(gen, scale),
          randomVec(gen, 1.0), randomVec(gen, 5.0)};
}

// Evaluates e with its tangent under rule at three trial states, next(trial)
// for trial = 0, 1, 2, and calls check(trial, kin, r, k) after each; stops at
// the first fatal failure (call it under ASSERT_NO_FATAL_FAILURE).
template <class Next, class Check>
void checkAtTrials(Element& e, const StepRule& rule, Next next, Check check) {
  for (int trial = 0; trial < 3; ++trial) {
    const ElementKinematics kin = next(trial);
    ElemVec r;
    ElemMat k;
    ASSERT_TRUE(e.evaluate(kin, rule, true, r, k).ok);
    check(trial, kin, r, k);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

// The tangent k of e at kin against central differences of its residual,
// within tol of k's largest entry.
inline void expectTangentMatchesDifferences(Element& e, const ElementKinematics& kin,
                                            const StepRule& rule, const ElemMat& k, double tol,
                                            const std::string& label) {
  const ElemMat fd = centralDifferenceTangent(e, kin, rule);
  EXPECT_LT((fd - k).cwiseAbs().maxCoeff(), tol * k.cwiseAbs().maxCoeff()) << label << "\nK =\n"
                                                                           << k << "\nFD =\n"
                                                                           << fd;
}

}  // namespace c2d::test
