// The RC section of SECTion/REBAr (materials/RcSection) against hand
// calculations: the neutral axis, My and Mu at N = 0, under compression and
// under tension, both signs, for two sections, and the interaction diagram's
// balance point (verification.md V20).
//
// The hand calculation is the textbook one, written here independently of the
// program's integration: the parabola-rectangle block of a compressed depth x
// with the face strain e has the force alpha fc b x at beta x from the face,
//   e <= eps_c2: r = e/eps_c2, alpha = r (1 - r/3), beta = (4 - r)/(12 - 4 r),
//   e >  eps_c2: q = eps_c2/e, alpha = 1 - q/3, beta = 1 - (1/2 - q^2/12)/alpha
// (17/21 and 99/238 at eps_cu2 = 0.0035), the bars at clamp(Es e_i, -fy, fy),
// and x found by bisection so that the forces sum to N. Ultimate: the face at
// eps_cu2. First yield: the extreme tension bar at fy/Es or the face at eps_c2,
// whichever first. Units kN, m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "materials/RcSection.h"
#include "tests/unit/RcTestSupport.h"

namespace c2d {
namespace {

using test::v20;

constexpr double kC2 = 0.002, kCu = 0.0035;

struct Hand {
  double x = 0, M = 0, kappa = 0;
};

struct Block {
  double alpha, beta;
};
Block block(double e) {
  const double r = e / kC2;
  if (r <= 1) return {r * (1 - r / 3), (4 - r) / (12 - 4 * r)};
  const double q = 1 / r, a = 1 - q / 3;
  return {a, 1 - (0.5 - q * q / 12) / a};
}

// The state of the section (sign -1: turned upside down) whose plane is given
// by its neutral axis depth x: face strain and curvature from `plane`.
template <class Plane>
Hand handState(const RcSectionData& d, int sign, double N, Plane plane) {
  std::vector<RebarLayer> bars = d.bars;
  if (sign < 0)
    for (RebarLayer& b : bars) b.depth = d.h - b.depth;
  double dt = 0;
  for (const RebarLayer& b : bars) dt = std::max(dt, b.depth);
  auto forces = [&](double x, double& m, double& kappa) {
    kappa = plane(x, dt);
    const Block bl = block(kappa * x);
    double n = -bl.alpha * d.fc * d.b * x;
    m = bl.alpha * d.fc * d.b * x * (d.h / 2 - bl.beta * x);
    for (const RebarLayer& b : bars) {
      const double s = std::clamp(d.Es * kappa * (b.depth - x), -d.fy, d.fy);
      n += b.area * s;
      m += b.area * s * (b.depth - d.h / 2);
    }
    return n;
  };
  double lo = 1e-9, hi = std::min(d.h, dt - 1e-9), m = 0, kappa = 0;
  for (int i = 0; i < 200; ++i) {
    const double x = 0.5 * (lo + hi);
    (forces(x, m, kappa) > N ? lo : hi) = x;
  }
  Hand h;
  h.x = 0.5 * (lo + hi);
  forces(h.x, h.M, h.kappa);
  return h;
}

Hand handUltimate(const RcSectionData& d, int sign, double N) {
  return handState(d, sign, N, [](double x, double) { return kCu / x; });
}

Hand handYield(const RcSectionData& d, int sign, double N) {
  const double ey = d.fy / d.Es;
  return handState(d, sign, N,
                   [ey](double x, double dt) { return std::min(ey / (dt - x), kC2 / x); });
}

const double kA20 = M_PI * 0.01 * 0.01, kA16 = M_PI * 0.008 * 0.008;

// An unsymmetric beam: 0.3 x 0.5 m, 2 bars of 16 mm at 0.04 m from the top,
// 3 of 20 mm at 0.45 m.
RcSectionData beam() {
  RcSectionData d = v20();
  d.b = 0.3;
  d.bars = {{0.04, 2 * kA16}, {0.45, 3 * kA20}};
  return d;
}

void expectHand(const RcSection& s, int sign, double N, double xu, double Mu, double xy,
                double My) {
  SCOPED_TRACE("sign " + std::to_string(sign) + ", N = " + std::to_string(N));
  const RcSectionData& d = s.data();
  const RcSection::State u = s.ultimate(N, sign), y = s.firstYield(N, sign);
  const Hand hu = handUltimate(d, sign, N), hy = handYield(d, sign, N);
  ASSERT_TRUE(u.exists && y.exists);
  // The program's integration against the block formulas.
  EXPECT_NEAR(u.depth, hu.x, 1e-9);
  EXPECT_NEAR(u.M, hu.M, 1e-7 * hu.M);
  EXPECT_NEAR(u.kappa, hu.kappa, 1e-7 * hu.kappa);
  EXPECT_NEAR(y.depth, hy.x, 1e-8);
  EXPECT_NEAR(y.M, hy.M, 1e-7 * hy.M);
  EXPECT_NEAR(y.kappa, hy.kappa, 1e-7 * hy.kappa);
  // And against the figures worked out by hand (rounded).
  EXPECT_NEAR(u.depth, xu, 1e-5);
  EXPECT_NEAR(u.M, Mu, 1e-3);
  EXPECT_NEAR(y.depth, xy, 1e-5);
  EXPECT_NEAR(y.M, My, 1e-3);
}

TEST(RcSection, ColumnOfV20AgainstHandCalculations) {
  const RcSection s(v20());
  for (int sign : {1, -1}) {  // symmetric: both signs alike
    expectHand(s, sign, 0, 0.05072, 269.128, 0.10539, 258.492);
    expectHand(s, sign, -3000, 0.24706, 693.023, 0.28703, 548.725);
    expectHand(s, sign, 500, 0.03673, 166.814, 0.05273, 155.316);
  }
  // N = 0: the compression bars at 0.05 m sit next to the neutral axis, so
  // Mu is about T (d - d') + C (h/2 - beta x) with T = 4 A fy = 628.3 kN.
  EXPECT_NEAR(s.ultimate(0, 1).M,
              628.3 * 0.2 + 0.8095 * 30e3 * 0.5 * 0.05072 * (0.25 - 0.416 * 0.05072), 3.0);
}

TEST(RcSection, UnsymmetricBeamAgainstHandCalculationsBothSigns) {
  const RcSection s(beam());
  expectHand(s, 1, 0, 0.05443, 200.092, 0.12073, 192.339);
  expectHand(s, 1, -800, 0.14689, 338.627, 0.19547, 323.513);
  expectHand(s, 1, 100, 0.04595, 179.200, 0.10773, 173.114);
  expectHand(s, -1, 0, 0.04281, 92.476, 0.07845, 86.291);
  expectHand(s, -1, -800, 0.09467, 249.760, 0.16671, 234.397);
  expectHand(s, -1, 100, 0.03910, 72.046, 0.05873, 65.169);
}

TEST(RcSection, BalancePointOfTheInteractionDiagram) {
  // x_b = eps_cu2 / (eps_cu2 + fy/Es) d = 0.0035/0.006 0.45 = 0.2625 m; both
  // bar layers yield (the compressed one at 0.0035 (0.2625 - 0.05)/0.2625 =
  // 0.00283 > 0.0025) and cancel: N_b = -17/21 fc b x_b = -3187.5 kN,
  // M_b = 3187.5 (0.25 - 99/238 x_b) + 2 (628.32)(0.2) = 700.16 kN m.
  const RcSection s(v20());
  const RcSection::State b = s.balance(1);
  const double xb = 0.2625, nb = -17.0 / 21 * 30e3 * 0.5 * xb;
  EXPECT_NEAR(b.depth, xb, 1e-12);
  EXPECT_NEAR(s.forces(b.e0, b.kappa, 1).N, nb, 1e-8);
  EXPECT_NEAR(nb, -3187.5, 1e-9);
  const double mb = -nb * (0.25 - 99.0 / 238 * xb) + 2 * 4 * kA20 * 500e3 * 0.2;
  EXPECT_NEAR(b.M, mb, 1e-8);
  EXPECT_NEAR(b.M, 700.16, 0.01);
  // The ultimate state at N_b is the balance state, and the diagram's largest
  // moment lies there: compression raises Mu up to it and lowers it beyond;
  // tension lowers it.
  EXPECT_NEAR(s.ultimate(nb, 1).M, mb, 1e-6);
  double best = 0, at = 0;
  for (double n = -8000; n <= 1200; n += 10)
    if (const double m = s.ultimate(n, 1).M; m > best) {
      best = m;
      at = n;
    }
  EXPECT_NEAR(at, nb, 60);
  EXPECT_LT(best, mb * 1.002);
  EXPECT_LT(s.ultimate(-1000, 1).M, s.ultimate(-2000, 1).M);
  EXPECT_LT(s.ultimate(0, 1).M, s.ultimate(-1000, 1).M);
  EXPECT_LT(s.ultimate(500, 1).M, s.ultimate(0, 1).M);
  EXPECT_LT(s.ultimate(-6000, 1).M, s.ultimate(nb, 1).M);
  // The tabulated law passes through the direct values at its nodes and
  // follows them between within the interpolation's error.
  for (double n : {-6000.0, -3000.0, -1000.0, 0.0, 300.0, 900.0}) {
    const MomentLaw l = s.at(1, n);
    EXPECT_NEAR(l.Mu, s.ultimate(n, 1).M, 5e-3 * l.Mu) << n;
    EXPECT_NEAR(l.My, s.firstYield(n, 1).M, 5e-3 * l.My) << n;
  }
}

TEST(RcSection, StiffnessesAxialCapacitiesAndHinge) {
  const RcSection s(v20());
  // Ec = 2 fc/eps_c2 = 30 GPa; transformed: n - 1 = 200/30 - 1, As = 8 A20.
  const double as = 8 * kA20, n1 = 200.0 / 30 - 1;
  EXPECT_NEAR(s.Ec(), 30e6, 1e-6);
  EXPECT_NEAR(s.EA(), 30e6 * (0.25 + n1 * as), 1e-3);
  EXPECT_NEAR(s.EI(), 30e6 * (0.5 * 0.125 / 12 + n1 * as * 0.2 * 0.2), 1e-6);
  EXPECT_NEAR(s.GA(), 5.0 / 6 * 30e6 / 2.4 * 0.25, 1e-6);
  EXPECT_NEAR(s.tensionYield(), as * 500e3, 1e-9);
  EXPECT_NEAR(s.tensionUltimate(), as * 540e3, 1e-9);
  EXPECT_NEAR(s.squashLoad(), 30e3 * 0.25 + as * 400e3, 1e-9);  // bars at eps_c2 Es = 400 MPa
  // Cracking at N = 0: fct I_tr / (h/2) with fct = 3 MPa.
  EXPECT_NEAR(s.cracking(0, 1).M, 3e3 * s.EI() / 30e6 / 0.25, 1e-9);
  // The hinge, EN 1998-3 (A.9), (A.10): dbL estimated from the layer of 4 A20
  // (b - 2c = 0.4 m: 1 + ceil(0.4/0.15) = 4 bars) = 20 mm; Lpl = L_V/30 + 0.2 h
  // + 0.11 x 0.02 x 500/sqrt(30) = L_V/30 + 0.300832 m; at the reference L_V =
  // 4h = 2 m: Lpl = 0.367499, Lpl (1 - 0.5 Lpl/L_V) = 0.333735 m; theta_pl =
  // (kappa_u - kappa_y) that (no links: kappa_u at eps_cu2), failure jump 5
  // theta_pl; at L_V = 10 h = 5 m (thetaR's): 0.4675 x (1 - 0.04675) = 0.445644 m.
  EXPECT_NEAR(s.hingeLengthBase(1), 0.300832, 1e-6);
  EXPECT_NEAR(s.rotationLength(1, 2.0), 0.333735, 1e-6);
  const double dk = s.ultimate(0, 1).kappa - s.firstYield(0, 1).kappa, th = dk * 0.333735;
  EXPECT_NEAR(s.plasticRotation(0, 1, 2.0), th, 5e-6 * th);
  EXPECT_NEAR(s.at(1, 0).xiF, 5 * th, 1e-5 * th);
  EXPECT_NEAR(s.failureJump(1, 0, 5.0), 5 * dk * 0.445644, 5e-6 * 5 * dk * 0.445644);
  EXPECT_NEAR(s.failureJump(1, 0, 50.0), s.failureJump(1, 0, 5.0), 1e-12);  // L_V <= 10 h
  // L_V >= h: Lpl = 0.5/30 + 0.300832 = 0.317499, times 1 - 0.317499 = 0.216693.
  EXPECT_NEAR(s.failureJump(1, 0, 0.1), 5 * dk * 0.216693, 1e-5 * th);
  EXPECT_NEAR(s.ruptureRotation(), 5 * dk * 0.445644 + std::acos(1 / 1.05), 1e-5);
  // The law's points: (Mc/EI, Mc), (kappa_y, My), (kappa_u, Mu) with the plastic
  // curvatures kappa - M/EI at My and Mu.
  const MomentLaw l = s.at(1, 0);
  const double kpy = s.firstYield(0, 1).kappa - l.My / s.EI();
  EXPECT_NEAR(l.Kh1, (l.My - l.Mc) / kpy, 1e-6 * l.Kh1);
  const double kpu = s.ultimate(0, 1).kappa - l.Mu / s.EI();
  EXPECT_NEAR(l.Kh2, (l.Mu - l.My) / (kpu - kpy), 1e-6 * l.Kh2);
}

// Shear (materials/ShearResistance; its own tests hold the rule): without
// links the concrete's VRd,c at N = 0, 111.637 kN (+: d = 0.45 m, 3 x 20 mm)
// and 84.911 kN (-: d = 0.46 m, 2 x 16 mm); two legs of 8 mm at 0.2 m, fyw =
// 500 MPa: omega = 251.33 kN/m, cot theta = 2.5, VRd,s+ = 251.33 x 0.405 x 2.5
// = 254.469 kN, VRd,s- = 260.124 kN. Lb = max(Mu+/Vu+, Mu-/Vu-) with Mu+ =
// 200.092, Mu- = 92.476 kN m.
TEST(RcSection, ShearCapacityAndShortestPieceAgainstHandCalculations) {
  RcSectionData d = beam();
  EXPECT_NEAR(RcSection(d).shearCapacity(0.0, 1), 111.637, 1e-3);
  EXPECT_NEAR(RcSection(d).shearCapacity(0.0, -1), 84.911, 1e-3);
  EXPECT_NEAR(RcSection(d).shortestPiece(), std::max(200.092 / 111.637, 92.476 / 84.911), 1e-4);
  const double asw = 2 * M_PI * 0.004 * 0.004;
  d.stirrups = Stirrups{asw, 0.2, 500e3};
  const RcSection s(d);
  EXPECT_NEAR(s.shearCapacity(0.0, 1), 254.469, 1e-3);
  EXPECT_NEAR(s.shearCapacity(0.0, -1), 260.124, 1e-3);
  EXPECT_NEAR(s.shortestPiece(), 200.092 / 254.469, 1e-4);
  // Heavy links: the struts crush first at cot theta = 1, a z / 2 with a =
  // bw nu fc = 0.3 x 0.528 x 30e3: 4752 x 0.405 / 2 = 962.28 kN.
  d.stirrups = Stirrups{2e-3, 0.1, 500e3};
  EXPECT_NEAR(RcSection(d).shearCapacity(0.0, 1), 962.28, 1e-9);
  d.stirrups = Stirrups{asw, 0.0, 500e3};
  EXPECT_THROW(RcSection{d}, std::invalid_argument);
}

TEST(RcSection, LawDerivativesWithRespectToN) {
  const RcSection s(beam());
  for (int sign : {1, -1})
    for (double n : {-1500.0, -400.0, 0.0, 200.0}) {
      const double h = 1e-3;
      const MomentLaw l = s.at(sign, n), p = s.at(sign, n + h), m = s.at(sign, n - h);
      EXPECT_NEAR(l.dMu, (p.Mu - m.Mu) / (2 * h), 1e-6 * std::max(1.0, std::abs(l.dMu)));
      EXPECT_NEAR(l.dMy, (p.My - m.My) / (2 * h), 1e-6 * std::max(1.0, std::abs(l.dMy)));
      EXPECT_NEAR(l.dMc, (p.Mc - m.Mc) / (2 * h), 1e-6 * std::max(1.0, std::abs(l.dMc)));
      EXPECT_NEAR(l.dKh1, (p.Kh1 - m.Kh1) / (2 * h), 1e-5 * std::max(1.0, std::abs(l.Kh1)));
      EXPECT_NEAR(l.dKh2, (p.Kh2 - m.Kh2) / (2 * h), 1e-5 * std::max(1.0, std::abs(l.Kh2)));
    }
}

}  // namespace
}  // namespace c2d
