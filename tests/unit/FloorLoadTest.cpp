// Floor loads (QLOAd) and lumped nodal masses (MASS) driven from C++: the
// period of a tip mass on a massless cantilever, the energy account of a floor
// carried as mass in the mid-point scheme, the lumped loads and masses.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/FloorLoad.h"
#include "core/Model.h"
#include "elements/ElementFactory.h"
#include "solvers/Analysis.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/FrameMaterialSupport.h"

namespace c2d {
namespace {

constexpr double kPi = std::numbers::pi;

// A straight member of n elements from (0,0) to (l,0), node 0 clamped (or pinned
// with the far end on a roller when simplySupported).
Model beam(double l, int n, double ei, Kinematics kin, bool simplySupported, double rhoA = 0) {
  Model m;
  MaterialSet mat =
      test::resultantFrame(kin, 1e7, 1e7, ei, rhoA > 0 ? 1.0 : 0.0, rhoA, rhoA > 0 ? 1e-6 : 0.0);
  mat.shear = kin == Kinematics::Finite;
  m.materials()[1] = mat;
  for (int i = 0; i <= n; ++i) m.addNode(Vec2(l * i / n, 0));
  for (int e = 0; e < n; ++e)
    m.setElement(e, makeElement(m.materials().at(1), {e, e + 1}, m.coord(e), m.coord(e + 1)));
  if (simplySupported) {
    m.bound(0) = {1, 1, 0};
    m.bound(n) = {0, 1, 0};
  } else {
    m.bound(0) = {1, 1, 1};
  }
  return m;
}

bool step(Analysis& an) {
  if (!an.advance()) return false;
  IterationInfo info;
  for (int i = 0; i < 30; ++i) {
    if (!an.iterate(false, true, info)) return false;
    if (info.converged) return true;
  }
  return false;
}

TEST(FloorLoad, LumpedLoadsAndMasses) {
  Model m = beam(4, 4, 48000, Kinematics::Small, true);
  m.gravity() = Vec2(0, -10);
  m.elementLoads().push_back({1, Vec2(2, -20), false});
  m.elementLoads().push_back({2, Vec2(0, -20), true});
  m.nodalMass(4) = {3, 3, 0.5};
  const Eigen::VectorXd f = floorLoadVector(m);
  EXPECT_DOUBLE_EQ(f[1 * 3 + 0], 1.0);    // element 2 (nodes 1, 2): qx L/2
  EXPECT_DOUBLE_EQ(f[1 * 3 + 1], -10.0);  // qy L/2
  EXPECT_DOUBLE_EQ(f[2 * 3 + 1], -20.0);  // elements 2 and 3 share node 2
  EXPECT_DOUBLE_EQ(f[3 * 3 + 1], -10.0);
  EXPECT_DOUBLE_EQ(f[4 * 3 + 1], -30.0);  // weight of the nodal mass m2 g
  EXPECT_DOUBLE_EQ(f[4 * 3 + 2], 0.0);    // no moments
  const Eigen::VectorXd mass = lumpedNodalMass(m);
  EXPECT_DOUBLE_EQ(mass[1 * 3 + 1], 0.0);  // a load only
  EXPECT_DOUBLE_EQ(mass[2 * 3 + 0], 1.0);  // |q|/|g| = 2 per length, half of L = 1
  EXPECT_DOUBLE_EQ(mass[3 * 3 + 1], 1.0);
  EXPECT_DOUBLE_EQ(mass[4 * 3 + 2], 0.5);
}

// A tip mass m on a massless cantilever (Euler-Bernoulli, exact stiffness 3EI/L^3)
// released under a sudden tip load: the period is 2 pi sqrt(m L^3 / 3EI) (with the
// trapezoidal rule's elongation, 2 atan(omega h/2) per step, taken out), and
// kinetic + strain - external work stays constant after the first step (the zero
// initial acceleration is not in equilibrium).
TEST(FloorLoad, TipMassPeriodAndEnergy) {
  const double l = 2, ei = 48000, mass = 2, f = -10;
  Model m = beam(l, 4, ei, Kinematics::Small, false);
  m.nodalMass(4) = {mass, mass, 0};
  m.force(4) = {0, f, 0};
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::newmark(0.25, 0.5));
  const double omega = std::sqrt(3 * ei / (l * l * l) / mass), period = 2 * kPi / omega;
  const double h = period / 100;
  an.setDt(h);
  const double vStatic = f * l * l * l / (3 * ei);
  std::vector<double> t, x;
  double e1 = 0, scale = 0, drift = 0;
  for (int n = 1; n <= 400; ++n) {
    ASSERT_TRUE(step(an)) << "step " << n;
    ASSERT_TRUE(an.commit());
    const Energy en = an.energy();
    if (n == 1) e1 = en.total();
    scale = std::max(scale, std::abs(en.kinetic) + std::abs(en.strain));
    drift = std::max(drift, std::abs(en.total() - e1));
    t.push_back(an.state().t);
    x.push_back(an.state().u[4 * 3 + 1] - vStatic);
  }
  EXPECT_LT(drift, 1e-10 * scale);
  EXPECT_GT(scale, 0.0);
  std::vector<double> roots;
  for (std::size_t i = 0; i + 1 < x.size(); ++i)
    if ((x[i] > 0) != (x[i + 1] > 0))
      roots.push_back(t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i]));
  ASSERT_GE(roots.size(), 6u);
  const double measured = 2 * (roots.back() - roots.front()) / (roots.size() - 1);
  const double discrete = 2 * kPi * h / (2 * std::atan(omega * h / 2));
  EXPECT_NEAR(measured, discrete, 2e-3 * period);
  EXPECT_NEAR(measured, period, 3e-3 * period);
}

// A floor carried as mass on a geometrically exact cantilever falling under
// gravity with the energy conserving mid-point scheme: the energy account
// (kinetic with the floor's mass, strain, work of the floor load) is exact.
TEST(FloorLoad, FloorMassEnergyConservingScheme) {
  Model m = beam(3, 6, 2000, Kinematics::Finite, false, 0.1);
  m.gravity() = Vec2(0, -9.81);
  for (int e = 0; e < 6; ++e) m.elementLoads().push_back({e, Vec2(0, -5), true});
  m.nodalMass(6) = {0.5, 0.5, 0};
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setDt(0.01);
  double scale = 0, drift = 0, kinetic = 0;
  for (int n = 1; n <= 60; ++n) {
    ASSERT_TRUE(step(an)) << "step " << n;
    ASSERT_TRUE(an.commit());
    const Energy en = an.energy();
    scale = std::max(scale, std::abs(en.kinetic) + std::abs(en.strain) + std::abs(en.external));
    drift = std::max(drift, std::abs(en.total()));
    kinetic = std::max(kinetic, en.kinetic);
  }
  EXPECT_GT(kinetic, 0.0);
  EXPECT_LT(drift, 1e-9 * scale);
}

}  // namespace
}  // namespace c2d
