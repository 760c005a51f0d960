// The members' structural damping (DAMPing, materials/SectionDamping): the
// bending moment's work and slope, the elements' tangents against finite
// differences under Newmark and the mid-point scheme (elastic, hardening and
// softening sections), the mid-point work identity with alpha + a1/h, and the
// free vibration of a damped cantilever against the closed form: the log
// decrement 2 pi zeta / sqrt(1 - zeta^2) of its first mode, zeta = a1 w / 2,
// at two time steps (the damping does not scale with the step).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "core/Model.h"
#include "elements/ElementFactory.h"
#include "elements/InelasticFrame.h"
#include "elements/LinearFrame.h"
#include "elements/ReissnerFrame.h"
#include "materials/RcSection.h"
#include "materials/SectionDamping.h"
#include "materials/SectionLaws.h"
#include "solvers/Analysis.h"
#include "solvers/TimeIntegrator.h"
#include "tests/unit/ElementTestSupport.h"
#include "tests/unit/RcTestSupport.h"
#include "tests/unit/V2Material.h"

namespace c2d {
namespace {

using test::kinAt;
using test::tangentError;
using test::turned;

constexpr double kPi = std::numbers::pi;

// The dashpot's bending moment m(K1) for dM = M0 + kt (K1 - K0) - M0: its work
// m dK is never negative, it is the Kelvin-Voigt moment f EI dK in an elastic
// step and nothing while the moment falls, and its slope is the given tangent.
TEST(SectionDampingBending, WorkIsNeverNegativeAndTheSlopeIsExact) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const double f = 0.3, EI = 100;
  for (int i = 0; i < 2000; ++i) {
    const double dK = 0.01 * u(gen), kt = EI * 1.5 * u(gen), dM = kt * dK + 0.2 * u(gen);
    const auto b = SectionDamping::bending(f, EI, dM, dK, kt);
    EXPECT_GE(b.m * dK, 0.0) << "dM " << dM << " dK " << dK;
    EXPECT_LE(std::abs(b.m), f * EI * std::abs(dK) * (1 + 1e-14));
  }
  const auto elastic = SectionDamping::bending(f, EI, EI * 0.02, 0.02, EI);
  EXPECT_DOUBLE_EQ(elastic.m, f * EI * 0.02);
  EXPECT_DOUBLE_EQ(elastic.tangent, f * EI);
  EXPECT_EQ(SectionDamping::bending(f, EI, -3, 0.02, -50).m, 0.0);  // a softening hinge
  // Slope along K1 with dM = kt dK + c: hardening steps (0 < r < 1).
  for (double kt : {30.0, 60.0, -20.0}) {
    const double c = 0.05, dK = 0.01, h = 1e-7;
    auto m = [&](double k) { return SectionDamping::bending(f, EI, kt * k + c, k, kt).m; };
    const auto b = SectionDamping::bending(f, EI, kt * dK + c, dK, kt);
    EXPECT_NEAR(b.tangent, (m(dK + h) - m(dK - h)) / (2 * h), 1e-6 * (std::abs(b.tangent) + 1))
        << "kt " << kt;
  }
}

// Step rules with the step length the dashpot needs.
StepRule midPoint(double alpha, double dt) {
  StepRule r = TimeIntegrator::midPoint(alpha, 0).rule(dt);
  return r;
}
StepRule newmark(double dt) { return TimeIntegrator::newmark(0.25, 0.5).rule(dt); }

// Every element type with the V2 laws and a dashpot (a1 = 2e-3 s, f = a1/h =
// 0.2 at h = 0.01): elastic, hardening and softening steps, each scheme.
TEST(SectionDampingTangent, MatchesFiniteDifferencesOnEveryBranch) {
  const double l = 0.5, phi = 0.7, dt = 0.01;
  const Vec2 x1(0, 0), x2 = l * Vec2(std::cos(phi), std::sin(phi));
  for (Kinematics kin : {Kinematics::Small, Kinematics::Finite}) {
    MaterialSet mat = test::v2::material(1, 1.25e6, kin);
    mat.dampingA1 = 2e-3;
    const double rho = kin == Kinematics::Finite ? 1.3 : 0.0;  // a large rigid rotation
    for (const StepRule& rule : {newmark(dt), midPoint(0, dt), midPoint(0.1, dt)}) {
      for (double M : {20.0, 150.0, 271.0, -200.0}) {  // elastic, both hardening branches
        const double kappa = test::v2::kappaOf(std::abs(M)) * (M > 0 ? 1 : -1);
        auto e = makeElement(mat, {0, 1}, x1, x2);
        const ElemVec dn = turned(l, phi, rho - 0.05, 1e-4, -1e-4, 0.5 * kappa);
        ElemVec r;
        ElemMat k;
        ASSERT_TRUE(e->evaluate(kinAt(dn, dn), StepRule{}, false, r, k).ok);
        e->commit();
        const ElemVec d = turned(l, phi, rho, 2e-4, 1e-4, kappa);
        EXPECT_LT(tangentError(*e, kinAt(d, dn), rule), 1e-6)
            << "M " << M << " scheme " << int(rule.scheme) << " finite " << int(kin);
      }
      // A hinge opened at Mu, then softening.
      auto e = makeElement(mat, {0, 1}, x1, x2);
      auto& hinge = dynamic_cast<HingeCarrier&>(*e);
      const double kU = test::v2::kappaOf(test::v2::kMu);
      const ElemVec dU = turned(l, phi, rho, 0, 0, kU);
      ElemVec r;
      ElemMat k;
      ASSERT_TRUE(e->evaluate(kinAt(dU, dU), StepRule{}, false, r, k).ok);
      e->commit();
      hinge.activateHinge();
      const ElemVec d = turned(l, phi, rho + 0.01, 1e-4, -1e-4, kU + 0.004);
      EXPECT_LT(tangentError(*e, kinAt(d, dU), rule), 1e-6) << "hinge, finite " << int(kin);
      EXPECT_TRUE(hinge.hinge().active);
    }
  }
  // The elastic elements, Timoshenko and Euler-Bernoulli.
  for (bool shear : {true, false}) {
    MaterialSet mat = test::resultantMaterial(Kinematics::Small, shear);
    mat.dampingA1 = 2e-3;
    LinearFrame e(mat, {0, 1}, x1, x2);
    std::mt19937 gen(3);
    for (const StepRule& rule : {newmark(dt), midPoint(0.1, dt)})
      EXPECT_LT(
          tangentError(e, kinAt(test::randomVec(gen, 0.01), test::randomVec(gen, 0.01)), rule),
          1e-6);
  }
}

// Under the mid-point scheme the dashpot weighs the strains' change like the
// scheme's alpha: r(d - dn).f_int = W(d) - W(dn) + (alpha + a1/h) l dE.C.dE.
TEST(SectionDampingMidPoint, WorkIdentityWithAlphaPlusA1OverH) {
  std::mt19937 gen(99);
  const Vec2 x1(0.0, 0.0), x2(0.8, 1.5);
  MaterialSet mat = test::resultantMaterial(Kinematics::Finite);
  mat.dampingA1 = 3e-3;
  ReissnerFrame e(mat, {0, 1}, x1, x2);
  const Vec3 c(mat.EA(), mat.GA(), mat.EI());
  for (double dt : {0.01, 1e-4}) {
    StepRule rule = midPoint(0.1, dt);
    rule.ca = rule.av = rule.aa = 0;  // internal force only
    for (double w : {0.3, 4.0}) {
      ElemVec dn = test::randomVec(gen, 0.05), d = dn + test::randomVec(gen, 0.05);
      dn(2) += w;
      dn(5) += w;
      d(2) += w + 0.4;
      d(5) += w + 0.4;
      ElemVec r;
      ElemMat k;
      ASSERT_TRUE(e.evaluate({d, dn, ElemVec::Zero(), ElemVec::Zero()}, rule, false, r, k).ok);
      const double wd = e.energy(d), wn = e.energy(dn);
      const Vec3 de = e.strains(d) - e.strains(dn);
      const double damped = (0.1 + mat.dampingA1 / dt) * e.length() * de.dot(c.cwiseProduct(de));
      EXPECT_NEAR(rule.rate(d - dn).dot(r), wd - wn + damped, 1e-11 * (wd + wn + damped))
          << "dt " << dt << " w " << w;
    }
  }
}

// ---------------------------------------------------------------------------
// Free vibration of a damped cantilever (L = 3 m, the paper's member: EI =
// 48000 kN m^2, 0.3 t/m): started in its first discrete mode, it decays with
// the log decrement 2 pi zeta / sqrt(1 - zeta^2), zeta = a1 w1 / 2, because
// stiffness-proportional damping keeps the modes apart (C = a1 K). w1 is the
// mesh's first frequency, within 2 % of the Euler-Bernoulli beam's 3.516
// sqrt(EI / (m L^4)) (shear deformation and rotary inertia lower it by 1.2 %).

constexpr double kLength = 3.0;
constexpr int kElements = 8;

MaterialSet cantileverMaterial(Kinematics kin, bool laws, double a1) {
  MaterialSet m = test::resultantFrame(kin, 3.6e6, 1.2e6, 48000, 2.5, 0.12, 1.6e-3);
  if (laws) {  // the paper's beams: elastic up to Mc = 30 kN m
    m.hardening = HardeningData{30, 150, 11190, 137};
    m.softening = SofteningData{170, -393, std::nullopt};
  }
  m.dampingA1 = a1;
  return m;
}

Model cantilever(const MaterialSet& mat) {
  Model m;
  m.materials()[1] = mat;
  m.resizeNodes(kElements + 1);
  for (int i = 0; i <= kElements; ++i) m.setCoord(i, Vec2(kLength * i / kElements, 0));
  for (int i = 0; i < kElements; ++i)
    m.setElement(i, makeElement(m.materials().at(1), {i, i + 1}, m.coord(i), m.coord(i + 1)));
  m.bound(0) = {1, 1, 1};
  return m;
}

// The first mode of the clamped mesh (free dofs: nodes 1..n): circular
// frequency and shape (all dofs, the tip's vertical displacement 1).
struct Mode {
  double omega = 0;
  Eigen::VectorXd shape;
};

Mode firstMode(const MaterialSet& mat = cantileverMaterial(Kinematics::Small, false, 0)) {
  const int n = 3 * (kElements + 1);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), M = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < kElements; ++i) {
    LinearFrame e(mat, {i, i + 1}, Vec2(kLength * i / kElements, 0),
                  Vec2(kLength * (i + 1) / kElements, 0));
    K.block<6, 6>(3 * i, 3 * i) += e.stiffness();
    M.block<6, 6>(3 * i, 3 * i) += e.mass();
  }
  const int nf = n - 3;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K.bottomRightCorner(nf, nf),
                                                                M.bottomRightCorner(nf, nf));
  Mode mode;
  mode.omega = std::sqrt(eig.eigenvalues()(0));
  mode.shape = Eigen::VectorXd::Zero(n);
  mode.shape.tail(nf) = eig.eigenvectors().col(0);
  mode.shape /= mode.shape(n - 2);
  return mode;
}

// Tip deflection's successive maxima (a parabola through the three samples
// around each); the log decrement over the first `cycles` of them.
struct Decay {
  double decrement = 0;
  double balanceError = 0;  // largest |balance - initial| over the run, per initial energy
  double dissipated = 0;    // from the first step to the end, per energy then
  double span = 0;          // the time from the first step to the end
};

Decay freeVibration(const MaterialSet& mat, const TimeIntegrator& ti, const Mode& mode, double dt,
                    int cycles, double tip = 1e-3) {
  Model m = cantilever(mat);
  // The tip `tip` up (1 mm: elastic, root moment 16 kN m), at rest: the
  // elements committed there.
  const Eigen::VectorXd u0 = tip * mode.shape;
  for (int i = 0; i < kElements; ++i) {
    const ElemVec d = u0.segment<6>(3 * i);
    ElemVec r;
    ElemMat k;
    EXPECT_TRUE(m.element(i)
                    .evaluate({d, d, ElemVec::Zero(), ElemVec::Zero()}, StepRule{}, false, r, k)
                    .ok);
    m.element(i).commit();
  }
  Analysis an(m);
  an.setIntegrator(ti);
  an.setDt(dt);
  an.state().resize(m.numNodes());
  an.state().u = an.state().un = u0;
  std::vector<double> y{u0(3 * kElements + 1)}, peaks;
  Decay out;
  Energy e0;
  double stored0 = 0;
  const double period = 2 * kPi / mode.omega;
  const int steps = static_cast<int>(std::ceil((cycles + 0.7) * period / dt));
  for (int s = 0; s < steps; ++s) {
    EXPECT_TRUE(an.advance().ok);
    IterationInfo info;
    for (int i = 0; i < 20 && !info.converged; ++i) EXPECT_TRUE(an.iterate(false, false, info).ok);
    EXPECT_TRUE(info.converged);
    an.commit();
    const Energy e = an.energy();
    if (s == 0) {  // the account from the first step on
      e0 = e;
      stored0 = e.kinetic + e.strain;
    }
    out.balanceError = std::max(out.balanceError, std::abs(e.balance() - e0.balance()) / stored0);
    out.dissipated = (e.dissipated - e0.dissipated) / stored0;
    y.push_back(an.state().u(3 * kElements + 1));
    const std::size_t k = y.size() - 2;
    if (k >= 1 && y[k] >= y[k - 1] && y[k] > y[k + 1] && y[k] > 0) {
      const double a = 0.5 * (y[k - 1] + y[k + 1]) - y[k], b = 0.5 * (y[k + 1] - y[k - 1]);
      peaks.push_back(y[k] - b * b / (4 * a));
    }
  }
  if (peaks.size() < static_cast<std::size_t>(cycles)) {
    ADD_FAILURE() << "only " << peaks.size() << " maxima";
    return out;
  }
  out.decrement = std::log(tip / peaks[cycles - 1]) / cycles;
  out.span = (steps - 1) * dt;
  return out;
}

TEST(SectionDampingCantilever, FirstModeDecaysWithTheLogDecrementOfItsRatio) {
  const Mode mode = firstMode();
  const double w1 = 3.516015 * std::sqrt(48000 / (0.3 * std::pow(kLength, 4)));
  EXPECT_NEAR(mode.omega, w1, 0.02 * w1);
  const double zeta = 0.05, a1 = 2 * zeta / mode.omega;
  const double exact = 2 * kPi * zeta / std::sqrt(1 - zeta * zeta);
  const double period = 2 * kPi / mode.omega;
  const int cycles = 4;
  struct Case {
    Kinematics kin;
    bool laws;
  };
  for (const Case& c : {Case{Kinematics::Small, false}, Case{Kinematics::Small, true},
                        Case{Kinematics::Finite, false}, Case{Kinematics::Finite, true}}) {
    const MaterialSet mat = cantileverMaterial(c.kin, c.laws, a1);
    // The conserving mid-point scheme: the dashpot is the only dissipation,
    // and the account books it exactly.
    const TimeIntegrator mid = TimeIntegrator::midPoint(0, 0);
    const Decay coarse = freeVibration(mat, mid, mode, period / 40, cycles);
    const Decay fine = freeVibration(mat, mid, mode, period / 160, cycles);
    SCOPED_TRACE(::testing::Message() << "finite " << int(c.kin) << " laws " << c.laws);
    // Second order in h: 0.4 % at 40 steps a period, 0.03 % at 160.
    EXPECT_NEAR(coarse.decrement, exact, 0.01 * exact);
    EXPECT_NEAR(fine.decrement, exact, 0.001 * exact);
    EXPECT_GT(std::abs(coarse.decrement - exact), 8 * std::abs(fine.decrement - exact));
    EXPECT_LT(coarse.balanceError, 1e-9);
    EXPECT_LT(fine.balanceError, 1e-9);
    // The mode's energy decays as exp(-2 zeta w t) (to its swing within a cycle).
    EXPECT_NEAR(fine.dissipated, 1 - std::exp(-2 * zeta * mode.omega * fine.span), 0.01);
  }
  // Without the dashpot the mode keeps its amplitude: the test sees the damping.
  const Decay none = freeVibration(cantileverMaterial(Kinematics::Finite, false, 0),
                                   TimeIntegrator::midPoint(0, 0), mode, period / 40, cycles);
  EXPECT_LT(std::abs(none.decrement), 1e-3 * exact);
  // Newmark (trapezoidal): the dashpot's force at t_n+1 from the step's mean
  // rate lags by h/2, which shifts the frequency rather than the decay: the
  // decrement is as close (0.4 % and 0.05 %).
  const MaterialSet mat = cantileverMaterial(Kinematics::Small, false, a1);
  const TimeIntegrator nm = TimeIntegrator::newmark(0.25, 0.5);
  const Decay coarse = freeVibration(mat, nm, mode, period / 40, cycles);
  const Decay fine = freeVibration(mat, nm, mode, period / 160, cycles);
  EXPECT_NEAR(coarse.decrement, exact, 0.01 * exact);
  EXPECT_NEAR(fine.decrement, exact, 0.002 * exact);
}

// Members whose laws follow the axial force, in their elastic range: an RC
// member (SECTion: 0.3 x 0.5 m, C30, 3 bars of 20 mm at each face; its axial
// force bounded; the tip 0.5 mm up, the root moment below 0.6 Mc) and the
// paper's member with an interaction curve (INTEraction, the tip 1 mm up).
// The dashpot acts on the elastic strains as for laws that do not follow N,
// so the first mode decays with the same log decrement, and the account
// closes, in both kinematics. (Undamped, Newmark's rule makes the finite RC
// member's swing about N = 0 grow, EnergyWatchTest; damped, the dashpot on
// the committed branch's stiffness keeps it.)
MaterialSet rcCantileverMaterial(Kinematics kin) {
  const double a20 = 3 * kPi * 0.01 * 0.01;
  return test::rcSectionMaterial(kin, {{0.05, a20}, {0.45, a20}});
}

TEST(SectionDampingCantilever, LawsFollowingTheAxialForceDecayAlike) {
  struct Case {
    Kinematics kin;
    bool section;
  };
  for (const Case& c : {Case{Kinematics::Small, true}, Case{Kinematics::Small, false},
                        Case{Kinematics::Finite, false}, Case{Kinematics::Finite, true}}) {
    MaterialSet mat = cantileverMaterial(c.kin, true, 0);
    double tip = 1e-3;
    if (c.section) {
      mat = rcCantileverMaterial(c.kin);
      tip = 5e-4;
      // Root moment of the static deflection shape: 3 EI tip / L^2.
      EXPECT_LT(3 * *mat.resEI * tip / (kLength * kLength), 0.6 * mat.capacity->at(1, 0.0).Mc);
    } else {
      mat.interaction = {{-2000, 200}, {0, 170}, {500, 100}};
      deriveSectionLaws(mat);
    }
    ASSERT_TRUE(mat.capacity);
    const Mode mode = firstMode(mat);
    const double zeta = 0.03, a1 = 2 * zeta / mode.omega;
    const double exact = 2 * kPi * zeta / std::sqrt(1 - zeta * zeta);
    const double period = 2 * kPi / mode.omega;
    mat.dampingA1 = a1;
    SCOPED_TRACE(::testing::Message() << "finite " << int(c.kin) << " section " << c.section);
    const TimeIntegrator mid = TimeIntegrator::midPoint(0, 0);
    const Decay coarse = freeVibration(mat, mid, mode, period / 40, 4, tip);
    const Decay fine = freeVibration(mat, mid, mode, period / 160, 4, tip);
    EXPECT_NEAR(coarse.decrement, exact, 0.01 * exact);
    EXPECT_NEAR(fine.decrement, exact, 0.001 * exact);
    EXPECT_LT(coarse.balanceError, 1e-9);
    EXPECT_LT(fine.balanceError, 1e-9);
    EXPECT_NEAR(fine.dissipated, 1 - std::exp(-2 * zeta * mode.omega * fine.span), 0.01);
    const Decay nm =
        freeVibration(mat, TimeIntegrator::newmark(0.25, 0.5), mode, period / 160, 4, tip);
    EXPECT_NEAR(nm.decrement, exact, 0.002 * exact);
  }
}

}  // namespace
}  // namespace c2d
