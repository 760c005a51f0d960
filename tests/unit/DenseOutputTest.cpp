// The dense output of a step (solvers/DenseOutput.h): the motion between the
// committed state at t_n and the converged one at t_n+1, sampled at a time in
// between, against motions it must reproduce exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Model.h"
#include "solvers/DenseOutput.h"

namespace c2d {
namespace {

// Two nodes; values at t_n from u0, v0 and a constant acceleration `acc`
// (every dof alike), the state at t_n + h from the exact motion.
State constantAcceleration(double tn, double h, double acc) {
  State s;
  s.resize(2);
  for (Eigen::Index i = 0; i < s.u.size(); ++i) {
    const double u0 = 0.1 * static_cast<double>(i + 1), v0 = -0.7 + 0.3 * static_cast<double>(i);
    s.un[i] = u0;
    s.vn[i] = v0;
    s.an[i] = acc;
    s.u[i] = u0 + v0 * h + 0.5 * acc * h * h;
    s.v[i] = v0 + acc * h;
    s.a[i] = acc;
  }
  s.tn = tn;
  s.t = tn + h;
  s.dt = h;
  s.step = 7;
  s.propn = 0.5;
  s.prop = 0.9;
  return s;
}

TEST(DenseOutput, AMotionOfConstantAccelerationIsSampledExactly) {
  // Under the energy conserving scheme (u_n+1 - u_n)/h = (v_n + v_n+1)/2: the
  // Hermite interpolant is that motion, rotations (dofs 3 and 6) included.
  const double tn = 1.25, h = 0.01, acc = -9.81;
  const State s = constantAcceleration(tn, h, acc);
  for (double f : {0.0, 0.3, 0.5, 0.9, 1.0}) {
    const double t = tn + f * h;
    const State x = denseState(s, t, TimeIntegrator::midPoint(0, 0));
    EXPECT_EQ(x.t, t);
    EXPECT_EQ(x.step, s.step);
    EXPECT_EQ(x.tn, s.tn);
    for (Eigen::Index i = 0; i < s.u.size(); ++i) {
      const double tau = t - tn;
      EXPECT_NEAR(x.u[i], s.un[i] + s.vn[i] * tau + 0.5 * acc * tau * tau, 1e-15) << i;
      EXPECT_NEAR(x.v[i], s.vn[i] + acc * tau, 1e-12) << i;
      EXPECT_NEAR(x.a[i], acc, 1e-12) << i;
    }
    EXPECT_NEAR(x.prop, 0.5 + 0.4 * f, 1e-12);
  }
}

TEST(DenseOutput, TheEndsAreTheStatesThemselves) {
  State s = constantAcceleration(0, 0.02, 3.0);
  s.u[4] += 0.003;  // any end values, not only those of a smooth motion
  s.v[2] -= 0.4;
  const TimeIntegrator newmark = TimeIntegrator::newmark(0.25, 0.5);
  const State end = denseState(s, s.t, newmark), start = denseState(s, s.tn, newmark);
  EXPECT_EQ(end.u, s.u);
  EXPECT_EQ(end.v, s.v);
  for (Eigen::Index i = 0; i < s.u.size(); ++i) {
    EXPECT_NEAR(start.u[i], s.un[i], 1e-15);
    EXPECT_NEAR(start.v[i], s.vn[i], 1e-15);
  }
  // Outside [t_n, t_n+1] the nearer end, labelled with its own time.
  EXPECT_EQ(denseState(s, s.t + 1, newmark).t, s.t);
  EXPECT_EQ(denseState(s, s.tn - 1, newmark).t, s.tn);
}

TEST(DenseOutput, StaticStepsAreLinearInTheirPseudoTime) {
  // No rates in statics: the values and the load factor go linearly.
  State s = constantAcceleration(1, 0.1, 0);
  s.v.setZero();
  s.vn.setZero();
  const State x = denseState(s, 1.025, TimeIntegrator::statics());
  for (Eigen::Index i = 0; i < s.u.size(); ++i)
    EXPECT_NEAR(x.u[i], 0.75 * s.un[i] + 0.25 * s.u[i], 1e-15);
  EXPECT_NEAR(x.prop, 0.6, 1e-15);
}

TEST(DenseOutput, AppliesUntilTheStateMovesOn) {
  Model model;
  model.resizeNodes(2);
  const TimeIntegrator scheme = TimeIntegrator::midPoint(0, 0);
  State s = constantAcceleration(2, 0.01, 1.0);
  DenseOutput out;
  // A step that ends on the scheduled time (to round-off) needs no sample.
  out.schedule(s, s.t - 1e-14);
  EXPECT_FALSE(out.scheduled(s));
  EXPECT_EQ(&out.outputState(model, s, scheme), &s);
  out.schedule(s, 2.004);
  ASSERT_TRUE(out.scheduled(s));
  const State& shown = out.outputState(model, s, scheme);
  EXPECT_NE(&shown, &s);
  EXPECT_EQ(shown.t, 2.004);
  // A commit (or any step) and the state is shown as it is.
  s.commit();
  EXPECT_FALSE(out.scheduled(s));
  EXPECT_EQ(&out.outputState(model, s, scheme), &s);
}

}  // namespace
}  // namespace c2d
