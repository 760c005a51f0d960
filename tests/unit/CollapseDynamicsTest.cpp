// Collapse-phase dynamics with whole analyses (Analysis + mid-point scheme):
// pendulums with revolute joints (verification.md V5), energy and momentum of
// the energy conserving/decaying scheme (V7, V8), and penalty contact with the
// ground (V6).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "core/Assembler.h"
#include "core/contact/GroundContact.h"
#include "core/Model.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/ReissnerFrame.h"
#include "solvers/Analysis.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/ContactTestSupport.h"

namespace c2d {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;

// Resultant stiffnesses; mass rhoA per length and rotary inertia rhoI per length.
MaterialSet rodMaterial(double ea, double ga, double ei, double rhoA, double rhoI) {
  MaterialSet m;
  m.number = 1;
  m.elementType = "FRAMe";
  m.kinematics = Kinematics::Finite;
  m.resEA = ea;
  m.resGA = ga;
  m.resEI = ei;
  m.density = 1.0;
  m.A = rhoA;
  m.I = rhoI;
  return m;
}

// Appends n elements on a straight line from node `from` to a new end point;
// returns the last node.
int addRod(Model& m, int from, const Vec2& to, int n) {
  const Vec2 x0 = m.coord(from);
  int prev = from;
  for (int i = 1; i <= n; ++i) {
    const int node = m.addNode(x0 + (to - x0) * (double(i) / n));
    m.setElement(m.numElements(),
                 std::make_unique<ReissnerFrame>(m.materials().at(1), std::array{prev, node},
                                                 m.coord(prev), m.coord(node)));
    prev = node;
  }
  return prev;
}

// A chain of rods hanging from a fixed pivot (node 0), link i at angle angles[i]
// from the downward vertical, consecutive links joined by Condensed joints (the
// first to the pivot). Returns the first and last node of every link.
std::vector<std::array<int, 2>> buildChain(Model& m, const MaterialSet& mat,
                                           const std::vector<double>& angles, double l, int n) {
  m.materials()[1] = mat;
  m.gravity() = Vec2(0, -kG);
  const int pivot = m.addNode(Vec2::Zero());
  m.bound(pivot) = {1, 1, 1};
  std::vector<std::array<int, 2>> links;
  int master = pivot;
  for (double a : angles) {
    const Vec2 joint = m.coord(master);  // a copy: addNode reallocates the coordinates
    const int start = m.addNode(joint);
    const int end = addRod(m, start, m.coord(master) + l * Vec2(std::sin(a), -std::cos(a)), n);
    m.joints().push_back({master, start, JointForm::Condensed});
    links.push_back({start, end});
    master = end;
  }
  installJoints(m);
  return links;
}

// One time step with Newton iterations; prints the iteration history when it
// does not converge (unless quiet).
bool solveStep(Analysis& an, int maxIterations = 40, bool quiet = false) {
  if (!an.advance()) return false;
  IterationInfo info;
  for (int i = 0; i < maxIterations; ++i) {
    if (!an.iterate(false, false, info)) return false;
    if (info.converged) return true;
  }
  if (quiet) return false;
  for (const IterationInfo& h : an.stepHistory())
    std::printf("  iteration %d: residual %.3e energy %.3e\n", h.iteration, h.residual, h.energy);
  return false;
}

Vec2 position(const Model& m, const State& s, int node) {
  return m.coord(node) + s.u.segment<2>(3 * node);
}

// Angle from the downward vertical of the chord from node a to node b.
double chordAngle(const Model& m, const State& s, int a, int b) {
  const Vec2 d = position(m, s, b) - position(m, s, a);
  return std::atan2(d.x(), -d.y());
}

// Roots of y(t) from cubic interpolation through the four samples around each
// sign change.
std::vector<double> zeroCrossings(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> roots;
  for (size_t i = 1; i + 2 < y.size(); ++i) {
    if ((y[i] > 0) == (y[i + 1] > 0)) continue;
    auto p = [&](double x, double& dp) {
      double v = 0;
      dp = 0;
      for (size_t a = i - 1; a <= i + 2; ++a) {
        double la = 1, dla = 0;
        for (size_t b = i - 1; b <= i + 2; ++b) {
          if (b == a) continue;
          dla = dla * (x - t[b]) / (t[a] - t[b]) + la / (t[a] - t[b]);
          la *= (x - t[b]) / (t[a] - t[b]);
        }
        v += y[a] * la;
        dp += y[a] * dla;
      }
      return v;
    };
    double x = t[i] - y[i] * (t[i + 1] - t[i]) / (y[i + 1] - y[i]);
    for (int it = 0; it < 20; ++it) {
      double dp = 0;
      const double v = p(x, dp);
      x -= v / dp;
    }
    roots.push_back(x);
  }
  return roots;
}

double periodFromCrossings(const std::vector<double>& c) {
  EXPECT_GE(c.size(), 3u);
  return 2 * (c.back() - c.front()) / double(c.size() - 1);
}

// Complete elliptic integral of the first kind K(k), by the arithmetic-geometric mean.
double ellipticK(double k) {
  double a = 1, b = std::sqrt(1 - k * k);
  for (int i = 0; i < 40; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return kPi / (2 * a);
}

// Period lengthening of the mid-point (trapezoidal) rule for frequency omega, step h.
double midPointElongation(double omega, double h) {
  return omega * h / (2 * std::atan(omega * h / 2));
}

// Stiff rod: a rigid pendulum for all practical purposes (stretch under the
// pendulum loads ~1e-5, a period change ~3e-6), uniform mass, no rotary
// inertia. Much stiffer rods put the residual's round-off (EA * 1e-16) above
// what the Newton energy test can resolve for small motions.
MaterialSet stiffRod() { return rodMaterial(1e6, 1e6, 1e4, 1.0, 0.0); }

double singlePendulumPeriod(double theta0, int stepsPerPeriod, double expectedPeriod,
                            double periods) {
  Model m;
  const double l = 1.0;
  const auto links = buildChain(m, stiffRod(), {theta0}, l, 6);
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  const double h = expectedPeriod / stepsPerPeriod;
  an.setDt(h);
  std::vector<double> t{0}, y{theta0};
  const int steps = static_cast<int>(periods * stepsPerPeriod);
  for (int s = 0; s < steps; ++s) {
    EXPECT_TRUE(solveStep(an)) << "step " << s;
    an.commit();
    syncSlaveNodes(m, an.state());
    t.push_back(an.state().t);
    y.push_back(chordAngle(m, an.state(), links[0][0], links[0][1]));
  }
  return periodFromCrossings(zeroCrossings(t, y));
}

TEST(CollapseDynamicsPendulum, SmallAmplitudePeriodIsT0WithTheMidPointElongation) {
  const double l = 1.0, theta0 = 0.02;
  const double t0 = 2 * kPi * std::sqrt(2 * l / (3 * kG));
  const double tAmp = t0 * 2 / kPi * ellipticK(std::sin(theta0 / 2));
  const int n = 40;
  const double h = tAmp / n;
  const double expected = tAmp * midPointElongation(2 * kPi / tAmp, h);
  const double measured = singlePendulumPeriod(theta0, n, tAmp, 3.3);
  // The elongation is 2.1e-3 at 40 steps per period: the check resolves it 100 times.
  EXPECT_GT(expected / t0 - 1, 2e-3);
  EXPECT_NEAR(measured / expected, 1.0, 2e-5) << "measured " << measured << ", T0 " << t0;
}

TEST(CollapseDynamicsPendulum, FiniteAmplitudePeriodFollowsTheEllipticIntegral) {
  const double l = 1.0, theta0 = 1.5;
  const double t0 = 2 * kPi * std::sqrt(2 * l / (3 * kG));
  const double tAmp = t0 * 2 / kPi * ellipticK(std::sin(theta0 / 2));
  EXPECT_GT(tAmp / t0, 1.15);
  // The mid-point rule's period error is O(h^2) (for this amplitude about 1.8
  // times the linear formula's): extrapolate from 300 and 600 steps per period.
  const double t300 = singlePendulumPeriod(theta0, 300, tAmp, 2.3);
  const double t600 = singlePendulumPeriod(theta0, 600, tAmp, 2.3);
  const double extrapolated = (4 * t600 - t300) / 3;
  EXPECT_GT(t300, t600);
  // What remains is the rods' stretch under the swinging loads (about 1e-5).
  EXPECT_NEAR(extrapolated / tAmp, 1.0, 2e-5)
      << "extrapolated " << extrapolated << ", elliptic " << tAmp;
}

TEST(CollapseDynamicsPendulum, DoublePendulumFrequenciesAre3MinusPlus6OverSqrt7) {
  // Small amplitude: the coupling cos(theta1 - theta2) shifts the second mode by
  // about (theta1 - theta2)^2/2 relative (4e-4 at theta1 = 0.01).
  const double l = 1.0, eps = 0.001;
  for (int mode = 0; mode < 2; ++mode) {
    const double lambda = mode == 0 ? 3 - 6 / std::sqrt(7.0) : 3 + 6 / std::sqrt(7.0);
    // Linearised mode: (3/2 - 4 lambda/3) theta1 = (lambda/2) theta2.
    const double ratio = (3.0 - 8.0 * lambda / 3.0) / lambda;
    Model m;
    const auto links = buildChain(m, stiffRod(), {eps, eps * ratio}, l, 4);
    Analysis an(m);
    an.setIntegrator(TimeIntegrator::midPoint(0, 0));
    const double omega = std::sqrt(lambda * kG / l), period = 2 * kPi / omega;
    const int n = 60;
    const double h = period / n;
    an.setDt(h);
    std::vector<double> t{0}, y1{eps}, y2{eps * ratio};
    for (int s = 0; s < 3.3 * n; ++s) {
      ASSERT_TRUE(solveStep(an)) << "step " << s;
      an.commit();
      syncSlaveNodes(m, an.state());
      t.push_back(an.state().t);
      y1.push_back(chordAngle(m, an.state(), links[0][0], links[0][1]));
      y2.push_back(chordAngle(m, an.state(), links[1][0], links[1][1]));
    }
    const double expected = period * midPointElongation(omega, h);
    const double measured = periodFromCrossings(zeroCrossings(t, y1));
    EXPECT_NEAR(measured / expected, 1.0, 2e-5) << "mode " << mode;
    // A pure mode: both links cross zero together.
    const auto c1 = zeroCrossings(t, y1), c2 = zeroCrossings(t, y2);
    ASSERT_EQ(c1.size(), c2.size());
    for (size_t i = 0; i < c1.size(); ++i) EXPECT_NEAR(c1[i], c2[i], 1e-4 * period);
  }
}

// --- energy and momentum (V7, V8) ------------------------------------------

struct Momentum {
  Vec2 p = Vec2::Zero();   // linear momentum
  Vec2 mx = Vec2::Zero();  // mass times centre of mass
  double mass = 0;
};

Momentum momentum(const Model& m, const State& s) {
  Momentum out;
  for (int e = 0; e < m.numElements(); ++e) {
    const Element& el = m.element(e);
    const auto nodes = el.nodes();
    ElemVec v, x, one;
    for (int a = 0; a < 2; ++a) {
      v.segment<3>(3 * a) = s.v.segment<3>(3 * nodes[a]);
      x.segment<2>(3 * a) = position(m, s, nodes[a]);
      x(3 * a + 2) = 0;
    }
    const ElemVec mv = el.mass() * v, mxv = el.mass() * x;
    out.p += mv.segment<2>(0) + mv.segment<2>(3);
    out.mx += mxv.segment<2>(0) + mxv.segment<2>(3);
    one << 1, 0, 0, 1, 0, 0;
    out.mass += (el.mass() * one).sum();
  }
  return out;
}

// A flexible free beam centred at the origin.
Model freeBeam() {
  Model m;
  m.materials()[1] = rodMaterial(1e4, 4e3, 20.0, 1.0, 0.02);
  const int first = m.addNode(Vec2(-1.0, 0.2));
  addRod(m, first, Vec2(1.0, -0.2), 5);
  return m;
}

// Initial velocity field: translation vc, spin about the origin, a bending component.
void setVelocities(const Model& m, State& s, const Vec2& vc, double spin, double bending) {
  s.resize(m.numNodes());
  for (int n = 0; n < m.numNodes(); ++n) {
    const Vec2 r = m.coord(n);
    const Vec2 v =
        vc + spin * Vec2(-r.y(), r.x()) + bending * std::cos(kPi * r.x() / 2) * Vec2(0, 1);
    s.v.segment<2>(3 * n) = v;
    s.v(3 * n + 2) = spin - bending * kPi / 2 * std::sin(kPi * r.x() / 2);
  }
  s.vn = s.v;
}

TEST(CollapseDynamicsEnergy, FreeFlyingBeamConservesEnergyAndMomentumAtLargeSteps) {
  Model m = freeBeam();
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  setVelocities(m, an.state(), Vec2(1.0, 0.3), 0.8, 0.6);
  const double dt = 0.05;  // 50 times the period of the axial modes
  an.setDt(dt);
  const double e0 = an.energy().total();
  const Momentum m0 = momentum(m, an.state());
  double worst = 0;
  for (int s = 0; s < 2000; ++s) {
    ASSERT_TRUE(solveStep(an)) << "step " << s;
    an.commit();
    worst = std::max(worst, std::abs(an.energy().total() - e0));
  }
  const Momentum m1 = momentum(m, an.state());
  EXPECT_LT(worst, 1e-10 * e0) << "E0 = " << e0;
  // Exact up to round-off, which accumulates over the 2000 steps (the same with
  // a Newton tolerance of 1e-24).
  EXPECT_LT((m1.p - m0.p).norm(), 1e-11 * m0.p.norm());
  // The centre of mass moves with p/m exactly.
  const Vec2 c = m1.mx / m1.mass, c0 = m0.mx / m0.mass;
  EXPECT_LT((c - c0 - m0.p / m0.mass * an.state().t).norm(), 1e-10 * c.norm());
  EXPECT_GT(an.state().t, 99.0);
}

TEST(CollapseDynamicsPredictor, RigidTranslationIsPredictedExactly) {
  // A free beam drifting at constant velocity: the prediction u_n + dt v_n is
  // the solution. Its residual is round-off of zero forces, which no relative
  // test can judge: the corrections fall below the resolution of the positions
  // at once, and the step ends at its first or second iteration.
  for (const TimeIntegrator& ti :
       {TimeIntegrator::midPoint(0, 0), TimeIntegrator::midPoint(0.1, 0.1),
        TimeIntegrator::newmark(0.25, 0.5)}) {
    Model m = freeBeam();
    Analysis an(m);
    an.setIntegrator(ti);
    setVelocities(m, an.state(), Vec2(2.0, -0.5), 0, 0);
    an.setDt(0.1);
    for (int s = 0; s < 20; ++s) {
      ASSERT_TRUE(solveStep(an)) << "step " << s;
      EXPECT_LE(an.stepHistory().size(), 2u) << "step " << s;
      an.commit();
    }
    const State& st = an.state();
    for (int n = 0; n < m.numNodes(); ++n) {
      EXPECT_NEAR(st.u(3 * n), 2.0 * st.t, 1e-12);
      EXPECT_NEAR(st.u(3 * n + 1), -0.5 * st.t, 1e-12);
    }
  }
}

TEST(CollapseDynamicsEnergy, FreeBeamSpinsMoreThanTenTurns) {
  Model m = freeBeam();
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  const double omega = 2 * kPi;
  setVelocities(m, an.state(), Vec2::Zero(), omega, 0);
  an.setDt(0.01);
  const double e0 = an.energy().total();
  double worst = 0;
  for (int s = 0; s < 1100; ++s) {
    ASSERT_TRUE(solveStep(an)) << "step " << s;
    an.commit();
    worst = std::max(worst, std::abs(an.energy().total() - e0));
  }
  const State& st = an.state();
  const double turns = st.u(2) / (2 * kPi);
  EXPECT_GT(turns, 10.5);
  // Started unstretched, the beam stretches under the centrifugal load (up to
  // 0.2 %), its moment of inertia grows and it turns a little slower than
  // omega0 = 2 pi (the Coriolis forces of the axial vibration bend it slightly,
  // symmetrically: both end rotations stay equal).
  EXPECT_NEAR(turns / 11.0, 1.0, 1e-2);
  const int last = m.numNodes() - 1;
  EXPECT_NEAR(st.u(3 * last + 2), st.u(2), 1e-9);
  EXPECT_LT(worst, 1e-10 * e0);
  const Momentum mm = momentum(m, st);
  EXPECT_LT((mm.mx / mm.mass).norm(), 1e-11);
  EXPECT_LT(mm.p.norm(), 1e-11);
}

// Angular momentum about the origin: x_a x (M v)_a + (M v)_theta,a summed
// over the elements (the mass matrices couple like dofs only; a jointed
// element's slave section turns at the master's rate plus the relative one).
double angularMomentum(const Model& m, const State& s) {
  double j = 0;
  for (int e = 0; e < m.numElements(); ++e) {
    const Element& el = m.element(e);
    const auto nodes = el.nodes();
    ElemVec v;
    for (int a = 0; a < 2; ++a) v.segment<3>(3 * a) = s.v.segment<3>(3 * nodes[a]);
    if (auto* je = dynamic_cast<const JointedElement*>(&el))
      v(3 * je->slaveEnd() + 2) += je->relativeVelocity();  // the slave section's rate
    const ElemVec mv = el.mass() * v;
    for (int a = 0; a < 2; ++a) {
      const Vec2 x = position(m, s, nodes[a]);
      j += x.x() * mv(3 * a + 1) - x.y() * mv(3 * a) + mv(3 * a + 2);
    }
  }
  return j;
}

// A free beam spinning at 0.3 rad per step and vibrating: energy (with alpha > 0:
// never grows), linear and angular momentum are conserved to the
// solver's tolerance, at any step size: the rotations advance by the Cayley rule
// and the Reissner beam's algorithmic forces balance their moments about the
// mid-point configuration (ReissnerFrameMidPoint.InternalForceHasNoResultantAndNoMoment).
// With additive rotations the angular momentum drifted by 3e-3 of J in 10 s.
// (The velocity dissipation beta > 0 of the decaying scheme does not conserve
// angular momentum: dx/h is not the mean velocity.)
TEST(CollapseDynamicsEnergy, FreeSpinningBeamConservesEnergyAndAngularMomentum) {
  const std::pair<MassType, double> cases[] = {
      {MassType::Consistent, 0.0}, {MassType::Lumped, 0.0}, {MassType::Consistent, 0.1}};
  for (auto [mass, alpha] : cases) {
    {
      Model m;
      m.materials()[1] = rodMaterial(1e4, 4e3, 20.0, 1.0, 0.02);
      m.materials()[1].mass = mass;
      const int first = m.addNode(Vec2(-1.0, 0.2));
      addRod(m, first, Vec2(1.0, -0.2), 5);
      Analysis an(m);
      an.setIntegrator(TimeIntegrator::midPoint(alpha, 0));
      setVelocities(m, an.state(), Vec2(0.4, -0.2), 6.0, 0.6);  // 6 rad/s: 0.3 rad per step
      an.setDt(0.05);
      const double e0 = an.energy().total();
      const Vec2 p0 = momentum(m, an.state()).p;
      const double j0 = angularMomentum(m, an.state());
      double worstEnergy = 0, worstJ = 0, ePrev = e0;
      for (int s = 0; s < 200; ++s) {
        ASSERT_TRUE(solveStep(an)) << "step " << s;
        worstJ = std::max(worstJ, std::abs(angularMomentum(m, an.state()) - j0));
        an.commit();
        const double e = an.energy().kinetic + an.energy().strain;
        worstEnergy =
            std::max(worstEnergy, alpha == 0 ? std::abs(e - e0) : e - ePrev);
        ePrev = e;
      }
      EXPECT_LT(worstEnergy, 1e-10 * e0) << "alpha " << alpha;
      EXPECT_LT((momentum(m, an.state()).p - p0).norm(), 1e-10 * p0.norm());
      EXPECT_LT(worstJ, 1e-10 * std::abs(j0)) << "alpha " << alpha;
    }
  }
}

// Three links joined by free joints, the first to a fixed pivot at the origin,
// spinning at 0.1 rad per step without gravity and vibrating: the pivot's
// reaction has no moment about it, so the angular momentum about the origin is
// conserved, with the joints' slave rotations advancing by the Cayley rule too.
TEST(CollapseDynamicsEnergy, SpinningJointedChainConservesAngularMomentum) {
  Model m;
  buildChain(m, rodMaterial(1e5, 5e4, 2e2, 1.0, 1e-3), {kPi / 2, kPi / 3, 2.5}, 0.5, 2);
  m.gravity() = Vec2::Zero();
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setDt(0.01);
  const double w = 10.0;
  State& st = an.state();
  st.resize(m.numNodes());
  for (int n = 1; n < m.numNodes(); ++n) {
    const Vec2 r = m.coord(n);
    st.v.segment<2>(3 * n) = w * Vec2(-r.y(), r.x()) + 0.5 * Vec2(std::sin(n), std::cos(3.0 * n));
    st.v(3 * n + 2) = w;
  }
  st.vn = st.v;
  for (JointedElement* je : jointedElements(m))
    if (je->masterNode() == 0) je->setRelativeState(0, w, 0);  // the pivot does not turn
  const double e0 = an.energy().total(), j0 = angularMomentum(m, st);
  double worstE = 0, worstJ = 0, maxRelative = 0;
  for (int s = 0; s < 600; ++s) {
    ASSERT_TRUE(solveStep(an)) << "step " << s;
    worstJ = std::max(worstJ, std::abs(angularMomentum(m, an.state()) - j0));
    an.commit();
    worstE = std::max(worstE, std::abs(an.energy().total() - e0));
    for (const JointedElement* je : jointedElements(m))
      if (je->masterNode() != 0)
        maxRelative = std::max(maxRelative, std::abs(je->relativeRotation()));
  }
  EXPECT_LT(worstE, 1e-10 * e0);
  EXPECT_LT(worstJ, 1e-10 * std::abs(j0));
  EXPECT_GT(maxRelative, 0.1);  // the links fold at the joints
}

// alpha * sum l dE.C.dE over the elements for the last step (before commit).
double strainDissipation(const Model& m, const State& s, double alpha) {
  double sum = 0;
  for (int e = 0; e < m.numElements(); ++e) {
    const Element& el = m.element(e);
    ElementKinematics kin;
    const auto nodes = el.nodes();
    for (int a = 0; a < 2; ++a) {
      kin.d.segment<3>(3 * a) = s.u.segment<3>(3 * nodes[a]);
      kin.dn.segment<3>(3 * a) = s.un.segment<3>(3 * nodes[a]);
      kin.vn.segment<3>(3 * a) = s.vn.segment<3>(3 * nodes[a]);
      kin.an.segment<3>(3 * a) = s.an.segment<3>(3 * nodes[a]);
    }
    const ReissnerFrame* rf = dynamic_cast<const ReissnerFrame*>(&el);
    if (auto* je = dynamic_cast<const JointedElement*>(&el)) {
      kin = je->innerKinematics(kin, je->relativeRotation());
      rf = dynamic_cast<const ReissnerFrame*>(&je->inner());
    }
    EXPECT_NE(rf, nullptr);
    const Vec3 dE = rf->strains(kin.d) - rf->strains(kin.dn);
    sum += alpha * rf->length() * dE.dot(rf->sectionStiffness().asDiagonal() * dE);
  }
  return sum;
}

// beta * dv.M.dv over the elements for the last step, relative rotations included.
double velocityDissipation(const Model& m, const State& s, double beta) {
  double sum = 0;
  for (int e = 0; e < m.numElements(); ++e) {
    const Element& el = m.element(e);
    const auto nodes = el.nodes();
    ElemVec dv;
    for (int a = 0; a < 2; ++a)
      dv.segment<3>(3 * a) = s.v.segment<3>(3 * nodes[a]) - s.vn.segment<3>(3 * nodes[a]);
    if (auto* je = dynamic_cast<const JointedElement*>(&el))
      dv(3 * je->slaveEnd() + 2) += je->relativeVelocity() - je->committedRelativeVelocity();
    sum += beta * dv.dot(el.mass() * dv);
  }
  return sum;
}

// Three links of two elements each, released from the horizontal.
Model threeLinks() {
  Model m;
  buildChain(m, rodMaterial(1e5, 5e4, 2e2, 1.0, 1e-3), {kPi / 2, kPi / 2, kPi / 2}, 0.5, 2);
  return m;
}

TEST(CollapseDynamicsEnergy, JointedPendulumUnderGravityConservesEnergy) {
  Model m = threeLinks();
  ASSERT_EQ(jointedElements(m).size(), 3u);
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setDt(0.01);
  const double scale = 1.5 * kG * 1.5;  // m g L: the potential energy range
  const double e0 = an.energy().total();
  double worst = 0, maxRelative = 0;
  for (int s = 0; s < 1500; ++s) {
    ASSERT_TRUE(solveStep(an)) << "step " << s;
    an.commit();
    worst = std::max(worst, std::abs(an.energy().total() - e0));
    for (const JointedElement* je : jointedElements(m))
      maxRelative = std::max(maxRelative, std::abs(je->relativeRotation()));
  }
  EXPECT_LT(worst, 1e-10 * scale);
  EXPECT_GT(maxRelative, 1.0);  // the joints really turned
  EXPECT_GT(an.energy().kinetic, 0.1 * scale);
}

TEST(CollapseDynamicsPredictor, DivergingPredictionRestartsFromTheCommittedState) {
  // The jointed pendulum above at dt = 0.012: in its fastest swings the linear extrapolation
  // stretches the links, Newton's method from there diverges, and the step
  // starts again from u_n (IterationInfo::restarted) and converges. Most steps
  // converge from the prediction.
  Model m = threeLinks();
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setDt(0.012);
  const double scale = 1.5 * kG * 1.5;
  const double e0 = an.energy().total();
  int restarts = 0;
  double worst = 0;
  for (int s = 0; s < 1100; ++s) {
    ASSERT_TRUE(an.advance());
    IterationInfo info;
    bool converged = false;
    for (int i = 0; i < 40 && !converged; ++i) {
      ASSERT_TRUE(an.iterate(false, false, info)) << "step " << s;
      if (info.restarted) {
        ++restarts;
        EXPECT_FALSE(info.converged);
        EXPECT_TRUE(an.stepHistory().empty());
      }
      converged = info.converged;
    }
    ASSERT_TRUE(converged) << "step " << s;
    an.commit();
    worst = std::max(worst, std::abs(an.energy().total() - e0));
  }
  EXPECT_GT(restarts, 0);
  EXPECT_LT(restarts, 1100 / 4);
  EXPECT_LT(worst, 1e-10 * scale);
}

TEST(CollapseDynamicsEnergy, DecayingSchemeSatisfiesTheStepIdentityAndNeverGainsEnergy) {
  const double alpha = 0.1, beta = 0.05;
  Model m = threeLinks();
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(alpha, beta));
  an.setDt(0.01);
  const double scale = 1.5 * kG * 1.5;
  double before = an.energy().total(), worstIdentity = 0, totalDissipated = 0;
  for (int s = 0; s < 600; ++s) {
    ASSERT_TRUE(solveStep(an)) << "step " << s;
    const double dissipated =
        strainDissipation(m, an.state(), alpha) + velocityDissipation(m, an.state(), beta);
    an.commit();
    const double after = an.energy().total();
    EXPECT_LE(after, before + 1e-12 * scale) << "step " << s;
    worstIdentity = std::max(worstIdentity, std::abs(after - before + dissipated));
    totalDissipated += dissipated;
    before = after;
  }
  EXPECT_LT(worstIdentity, 1e-11 * scale);
  EXPECT_GT(totalDissipated, 1e-3 * scale);
}

struct Drift {
  double worst = 0;  // largest |E - E0| / (m g L/2)
  bool completed = true;
};

// A rod pendulum released at 1.5 rad from the vertical.
Drift pendulumDrift(const TimeIntegrator& ti, double ea, double dt, int steps) {
  Model m;
  buildChain(m, rodMaterial(ea, ea, 1e-2 * ea, 1.0, 0.0), {1.5}, 1.0, 4);
  Analysis an(m);
  an.setIntegrator(ti);
  an.setDt(dt);
  const double e0 = an.energy().total();
  Drift d;
  for (int s = 0; s < steps && d.completed; ++s) {
    d.completed = solveStep(an, 30, true);
    if (!d.completed) break;
    an.commit();
    d.worst = std::max(d.worst, std::abs(an.energy().total() - e0) / (kG * 0.5));
  }
  return d;
}

TEST(CollapseDynamicsEnergy, NewmarkDriftsWhereTheMidPointSchemeConserves) {
  // Trapezoidal Newmark on the same pendulum deck: a bounded but visible energy
  // error with a flexible rod and a small step ...
  const Drift mid = pendulumDrift(TimeIntegrator::midPoint(0, 0), 1e4, 0.01, 400);
  const Drift newmark = pendulumDrift(TimeIntegrator::newmark(0.25, 0.5), 1e4, 0.01, 400);
  ASSERT_TRUE(mid.completed && newmark.completed);
  EXPECT_LT(mid.worst, 1e-10);
  EXPECT_GT(newmark.worst, 1e-4);
  // ... and with a stiff rod and a large step its energy grows by more than the
  // whole potential energy range (until Newton gives up), while the conserving
  // scheme keeps it to round-off.
  const Drift midStiff = pendulumDrift(TimeIntegrator::midPoint(0, 0), 1e6, 0.04, 200);
  const Drift newmarkStiff = pendulumDrift(TimeIntegrator::newmark(0.25, 0.5), 1e6, 0.04, 200);
  ASSERT_TRUE(midStiff.completed);
  EXPECT_LT(midStiff.worst, 1e-10);
  EXPECT_GT(newmarkStiff.worst, 1.0);
}

// --- ground contact (V6) ----------------------------------------------------

TEST(GroundContact, MidPointForceIsTheDiscreteGradient) {
  Ground g{0.5, 3.0e3, -1};
  StepRule rule;
  rule.scheme = Scheme::MidPoint;
  const double ys[] = {0.7, 0.5, 0.49, 0.3, 0.2999999, 0.51, -0.1};
  for (double y0 : ys)
    for (double y1 : ys) {
      if (y0 == y1) continue;
      const ContactForce c = groundContact(g, 0.0, y0, y1, rule);
      // Work of the upward force over the step = -(U1 - U0).
      const double work = c.force * (y1 - y0);
      EXPECT_NEAR(work, -(contactEnergy(g, 0.0, y1) - contactEnergy(g, 0.0, y0)), 1e-12 * g.k)
          << y0 << " -> " << y1;
      // Tangent: d force / d penetration(y1) = -d force / d y1.
      const double h = 1e-7;
      const double fd =
          -(groundContact(g, 0.0, y0, y1 + h, rule).force - groundContact(g, 0.0, y0, y1 - h, rule).force) /
          (2 * h);
      if (std::abs(y1 - g.y0) > 1e-6) {
        EXPECT_NEAR(c.tangent, fd, 1e-5 * g.k) << y0 << " " << y1;
      }
    }
  // The dashpot: c (<p1> - <p0>) / h on top while in contact (core/contact/ContactDamper.h).
  rule.h = 0.01;
  const GroundDamper d{600.0};
  const ContactForce c0 = groundContact(g, 0.0, 0.45, 0.40, rule),
                     c1 = groundContact(g, 0.0, 0.45, 0.40, rule, d);
  EXPECT_NEAR(c1.force - c0.force, 600.0 * 0.05 / rule.h, 1e-12 * g.k);
  // Entering or leaving, the dashpot's force is continuous where the node
  // passes the ground line (a jump there makes Newton's method cycle), never
  // does work on the node, and its tangent is the derivative of the force.
  for (double yn : {0.7, 0.52, 0.45, 0.3}) {
    const double eps = 1e-9;
    const ContactForce above = groundContact(g, 0.0, yn, g.y0 + eps, rule, d),
                       below = groundContact(g, 0.0, yn, g.y0 - eps, rule, d);
    EXPECT_NEAR(above.force, below.force, 10 * (g.k + d.c / rule.h) * eps) << "from y = " << yn;
    for (double y1 : {0.8, 0.51, 0.49, 0.35}) {
      const double diss =
          groundContact(g, 0.0, yn, y1, rule, d).force - groundContact(g, 0.0, yn, y1, rule).force;
      EXPECT_LE(diss * (y1 - yn), 0.0) << yn << " -> " << y1;
      const double h = 1e-7;
      const double fd = -(groundContact(g, 0.0, yn, y1 + h, rule, d).force -
                          groundContact(g, 0.0, yn, y1 - h, rule, d).force) /
                        (2 * h);
      EXPECT_NEAR(groundContact(g, 0.0, yn, y1, rule, d).tangent, fd, 1e-5 * g.k)
          << yn << " -> " << y1;
    }
  }
}

// A bar of n elements lying flat at height y, stiff and uniform, mass 1.
Model bar(int n, double y, const Ground& ground, double ei = 1e5) {
  Model m;
  m.materials()[1] = rodMaterial(1e3 * ei, 1e3 * ei, ei, 1.0, 1e-4);
  const int first = m.addNode(Vec2(0, y));
  addRod(m, first, Vec2(1.0, y), n);
  m.gravity() = Vec2(0, -kG);
  m.ground() = ground;
  return m;
}

TEST(GroundContact, StaticPenetrationIsWeightOverNodesTimesK) {
  const double k = 2.0e4, weight = 1.0 * kG;
  for (int n : {1, 4}) {
    // Start slightly inside the ground so that the first tangent has contact stiffness.
    // Equal springs but unequal consistent nodal weights: a very stiff bar, so
    // that the rigid-bar answer holds node by node (k l^3/EI = 2e-5).
    Model m = bar(n, 0.0, Ground{1e-5, k, 0}, 1e9);
    m.bound(0)[0] = 1;  // frictionless: fix the horizontal rigid motion
    Analysis an(m);
    an.setDt(1.0);
    ASSERT_TRUE(solveStep(an));
    an.commit();
    double mean = 0;
    const int nodes = n + 1;
    for (int i = 0; i < nodes; ++i)
      mean += penetration(*m.ground(), position(m, an.state(), i).y());
    mean /= nodes;
    EXPECT_NEAR(mean, weight / (nodes * k), 1e-12 * weight / k) << n << " elements";
    for (int i = 0; i < nodes; ++i)
      EXPECT_NEAR(penetration(*m.ground(), position(m, an.state(), i).y()), weight / (nodes * k),
                  1e-5 * weight / (nodes * k));
  }
}

struct DropResult {
  double contactTime = 0, maxPenetration = 0, reboundHeight = 0, startHeight = 0;
  bool energyNeverIncreased = true;
  // Largest change of total + dissipated energy over the commits, and the
  // total dissipated energy (the account's).
  double worstIdentity = 0, dissipated = 0, energyScale = 0;
};

double mass(const Model& m) {
  double total = 0;
  for (int e = 0; e < m.numElements(); ++e) {
    const ElemMat me = m.element(e).mass();
    total += me(0, 0) + me(0, 3) + me(3, 0) + me(3, 3);
  }
  return total;
}

// One element bar (equal nodal masses and loads: a rigid translation) thrown
// down from height y0 with speed v0 onto the ground y = 0 whose dashpot has
// the damping ratio zeta.
DropResult drop(double zeta, double k, double y0, double v0, double dt) {
  Model m = bar(1, y0, Ground{0.0, k, zeta});
  Analysis an(m);
  an.setIntegrator(TimeIntegrator::midPoint(0, 0));
  an.setDt(dt);
  State& s = an.state();
  s.resize(m.numNodes());
  s.v(1) = s.v(4) = -v0;
  s.vn = s.v;
  DropResult out;
  out.startHeight = y0 + v0 * v0 / (2 * kG);
  std::vector<double> t{0}, p{-y0};
  out.energyScale = mass(m) * kG * out.startHeight;
  double before = an.energy().total();
  // Every commit (the steps through the impact are shortened: solvers/ImpactSteps.h);
  // the account starts at the first.
  bool first = true;
  double balance0 = 0, dissipated0 = 0;
  an.onCommit = [&] {
    const Energy e = an.energy();
    if (first) {
      balance0 = e.balance();
      dissipated0 = e.dissipated;
      first = false;
    }
    if (e.total() > before + 1e-12 * out.energyScale) out.energyNeverIncreased = false;
    out.worstIdentity = std::max(out.worstIdentity, std::abs(e.balance() - balance0));
    out.dissipated = e.dissipated - dissipated0;
    before = e.total();
    t.push_back(s.tn);
    p.push_back(-(m.coord(0).y() + s.un(1)));
    EXPECT_NEAR(s.un(4), s.un(1), 1e-12);
  };
  bool left = false;
  for (int i = 0; i < 20000 && !left; ++i) {
    EXPECT_TRUE(solveStep(an)) << "step " << i;
    an.commit();
    // Out of contact and rising for a few steps: done.
    left = p.size() > 5 && p.back() < 0 && p[p.size() - 2] < 0 && p[p.size() - 4] > 0;
  }
  EXPECT_TRUE(left);
  // Contact from the first to the second crossing of penetration zero.
  const auto c = zeroCrossings(t, p);
  EXPECT_EQ(c.size(), 2u);
  if (c.size() >= 2) out.contactTime = c[1] - c[0];
  // Maximum penetration from a parabola through the largest sample and its neighbours.
  const size_t i = std::max_element(p.begin(), p.end()) - p.begin();
  const double a = p[i - 1], b = p[i], cc = p[i + 1];
  out.maxPenetration = b + (a - cc) * (a - cc) / (8 * (2 * b - a - cc));
  // Free flight after the impact is exact for the mid-point rule: y + v^2/(2g).
  const double y = position(m, s, 0).y(), v = s.v(1);
  out.reboundHeight = y + v * v / (2 * kG);
  return out;
}

TEST(GroundContact, DroppedBarMatchesTheRigidDropFormulas) {
  const double mass = 1.0, k = 5.0e3, y0 = 0.01, vStart = 2.0;
  const double kTotal = 2 * k;                                 // two nodes
  const double v0 = std::sqrt(vStart * vStart + 2 * kG * y0);  // at first contact
  const double omega = std::sqrt(kTotal / mass);
  const double tc = (kPi + 2 * std::atan(kG / (omega * v0))) / omega;
  const double dt = tc / 500;
  const DropResult r = drop(0, k, y0, vStart, dt);
  const double st = mass * kG / kTotal;
  const double pMax = st + std::sqrt(st * st + mass * v0 * v0 / kTotal);
  EXPECT_NEAR(r.contactTime / tc, 1.0, 2e-5) << r.contactTime << " vs " << tc;
  EXPECT_NEAR(r.maxPenetration / pMax, 1.0, 1e-6) << r.maxPenetration << " vs " << pMax;
  EXPECT_NEAR(r.reboundHeight / r.startHeight, 1.0, 1e-10);
  EXPECT_TRUE(r.energyNeverIncreased);
  EXPECT_LT(r.worstIdentity, 1e-12 * r.energyScale);
}

TEST(GroundContact, ContactDampingLowersTheReboundTheSameAtEveryStep) {
  // The dashpot c = 2 zeta sqrt(k m) of each node's mass m takes
  // c (<p_n+1> - <p_n>)(p_n+1 - p_n) / h per step and node: the same damper at
  // every step, so the rebound converges as the step shrinks (the former
  // alpha k (<p_n+1> - <p_n>) was a damper alpha k h that vanished with it).
  const double k = 5.0e3, y0 = 0.01, vStart = 2.0, zeta = 0.1;
  double rebound[2] = {0, 0};
  int i = 0;
  for (double dt : {3.3e-2 / 300, 3.3e-2 / 20}) {
    const DropResult elastic = drop(0, k, y0, vStart, dt);
    const DropResult damped = drop(zeta, k, y0, vStart, dt);
    EXPECT_NEAR(elastic.reboundHeight / elastic.startHeight, 1.0, 1e-10);
    EXPECT_TRUE(damped.energyNeverIncreased);
    EXPECT_LT(damped.worstIdentity, 1e-12 * damped.energyScale);
    // The rebound height is lowered by exactly the dissipated energy.
    EXPECT_NEAR(damped.startHeight - damped.reboundHeight, damped.dissipated / kG,
                1e-10 * damped.startHeight);
    EXPECT_GT(damped.dissipated, 1e-2 * damped.energyScale) << "dt " << dt;
    rebound[i++] = damped.reboundHeight;
  }
  EXPECT_NEAR(rebound[1] / rebound[0], 1.0, 0.02);
}

TEST(GroundContact, AssembledTangentWithContactMatchesFiniteDifferences) {
  // A jointed two-link frame partly pressed into the ground.
  Model m;
  m.materials()[1] = rodMaterial(2e3, 1e3, 30.0, 1.0, 0.01);
  const int a = m.addNode(Vec2(0, 0.02));
  const int b = addRod(m, a, Vec2(1.0, -0.03), 2);
  const Vec2 xb = m.coord(b);
  const int c = m.addNode(xb);
  addRod(m, c, Vec2(1.8, 0.4), 2);
  m.joints().push_back({b, c, JointForm::Condensed});
  installJoints(m);
  m.ground() = Ground{0.0, 4.0e3, 0};
  m.gravity() = Vec2(0, -kG);
  for (const TimeIntegrator& ti :
       {TimeIntegrator::statics(), TimeIntegrator::newmark(0.25, 0.5),
        TimeIntegrator::midPoint(0.1, 0.05), TimeIntegrator::midPoint(0, 0)}) {
    Assembler as(m);
    as.refresh();
    State s;
    s.resize(m.numNodes());
    test::scatteredState(s, 0.01, 0.02);
    const StepRule rule = ti.rule(0.05);
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(s.u.size());
    ASSERT_TRUE(as.assemble(s, rule, ones, true).ok);
    const Eigen::MatrixXd k = Eigen::MatrixXd(as.tangent());
    const DofMap& dofs = as.dofs();
    const int neq = dofs.numEquations();
    Eigen::VectorXd r0;
    as.toEquations(as.nodalResidual(), r0);
    // Penetrating nodes exist and none sits on the ground line.
    int inContact = 0;
    for (int n = 0; n < m.numNodes(); ++n) {
      if (!dofs.used(n)) continue;
      const double p = -(m.coord(n).y() + s.u(3 * n + 1));
      ASSERT_GT(std::abs(p), 1e-4);
      inContact += p > 0;
    }
    EXPECT_GE(inContact, 2);
    Eigen::MatrixXd fd(neq, neq);
    const double h = 1e-7;
    for (int n = 0; n < m.numNodes(); ++n)
      for (int d = 0; d < 3; ++d) {
        const int eq = dofs.eq(n, d);
        if (eq < 0) continue;
        Eigen::VectorXd rp, rm;
        s.u(3 * n + d) += h;
        ASSERT_TRUE(as.assemble(s, rule, ones, false).ok);
        as.toEquations(as.nodalResidual(), rp);
        s.u(3 * n + d) -= 2 * h;
        ASSERT_TRUE(as.assemble(s, rule, ones, false).ok);
        as.toEquations(as.nodalResidual(), rm);
        s.u(3 * n + d) += h;
        fd.col(eq) = (rp - rm) / (2 * h);
      }
    EXPECT_LT((fd - k).cwiseAbs().maxCoeff(), 1e-6 * k.cwiseAbs().maxCoeff()) << ti.describe();
  }
}

}  // namespace
}  // namespace c2d
