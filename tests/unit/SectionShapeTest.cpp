// The shapes of SECTion (materials/SectionShape through materials/RcSection)
// against calculations written here independently of the program's
// integration: the ultimate moment Mu at N = 0 and at a compression N of a
// T-beam (the neutral axis in the flange: the parabola-rectangle block of
// width beff, its force alpha fc beff x at beta x from the face), of a
// circular and of an annular section (the EC2 stress times the chord width
// summed over the depth by the midpoint rule on 200000 strips, against the
// program's closed form in the angle); the uncracked stiffnesses against the
// closed forms (pi D^4/64, the annulus' pi (D^4 - d^4)/64, the T's parallel
// axes), and the shear's web width and depth. Units kN, m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "materials/RcSection.h"
#include "tests/unit/RcTestSupport.h"

namespace c2d {
namespace {

using test::c30b500;

constexpr double kC2 = 0.002, kCu = 0.0035;
const double kPi = std::acos(-1.0);

// The ultimate plane of a neutral axis depth x: the face at eps_cu2 or the
// farthest bar at eu, whichever comes first; curvature kappa = e_face / x.
double ultimateKappa(double x, double dmax, double eu) {
  return std::min(kCu / x, eu / (dmax - x));
}

double barStress(const RcSectionData& d, double strain) {
  return std::clamp(d.Es * strain, -d.fy, d.fy);
}

struct Hand {
  double x = 0, M = 0;
};

// x by bisection so that the section's force is N (compression grows with x);
// forces(x, M) returns N and sets M.
Hand solveDepth(double lo, double hi, double N, const std::function<double(double, double&)>& f) {
  double m = 0;
  for (int i = 0; i < 200; ++i) {
    const double x = 0.5 * (lo + hi);
    (f(x, m) > N ? lo : hi) = x;
  }
  Hand h;
  h.x = 0.5 * (lo + hi);
  f(h.x, h.M);
  return h;
}

// ---------------------------------------------------------------------------
// T-beam (decks/rc/tee_beam.inp): test::teeBeam().
using test::teeBeam;

// The block of a face strain e (17/21 and 99/238 at eps_cu2).
void block(double e, double& alpha, double& beta) {
  const double r = e / kC2;
  if (r <= 1) {
    alpha = r * (1 - r / 3);
    beta = (4 - r) / (12 - 4 * r);
    return;
  }
  const double q = 1 / r;
  alpha = 1 - q / 3;
  beta = 1 - (0.5 - q * q / 12) / alpha;
}

// The T's ultimate state with the compressed block of width `width` (beff for
// sagging, bw for hogging: the block must stay in the flange or the web),
// moments about the gross centroid zg (measured from the compressed face).
Hand teeUltimate(const RcSectionData& d, int sign, double N, double width, double zg) {
  std::vector<RebarLayer> bars = d.bars;
  if (sign < 0)
    for (RebarLayer& b : bars) b.depth = d.h - b.depth;
  double dmax = 0;
  for (const RebarLayer& b : bars) dmax = std::max(dmax, b.depth);
  return solveDepth(1e-6, dmax - 1e-6, N, [&](double x, double& m) {
    const double kappa = ultimateKappa(x, dmax, d.eu);
    double alpha, beta;
    block(kappa * x, alpha, beta);
    const double c = alpha * d.fc * width * x;
    double n = -c;
    m = c * (zg - beta * x);
    for (const RebarLayer& b : bars) {
      const double s = barStress(d, kappa * (b.depth - x));
      n += b.area * s;
      m += b.area * s * (b.depth - zg);
    }
    return n;
  });
}

TEST(RcShape, TeeBeamUltimateMomentsAgainstTheBlockOfTheFlangeAndOfTheWeb) {
  const RcSectionData d = teeBeam();
  const RcSection s(d);
  const double af = 1.2 * 0.15, aw = 0.3 * 0.45, a = af + aw;
  const double zg = (af * 0.075 + aw * 0.375) / a;  // 0.20357 m from the top
  EXPECT_NEAR(s.shape().area(), a, 1e-14);
  EXPECT_NEAR(s.shape().centroidDepth(1), zg, 1e-14);
  const double ig = 1.2 * std::pow(0.15, 3) / 12 + af * std::pow(0.075 - zg, 2) +
                    0.3 * std::pow(0.45, 3) / 12 + aw * std::pow(0.375 - zg, 2);
  EXPECT_NEAR(s.shape().secondMoment(), ig, 1e-14);
  for (double n : {0.0, -1500.0}) {
    SCOPED_TRACE("N = " + std::to_string(n));
    // Sagging: the flange compressed, the block of width beff within hf.
    const Hand sag = teeUltimate(d, 1, n, 1.2, zg);
    ASSERT_LT(sag.x, 0.15);
    const RcSection::State u = s.ultimate(n, 1);
    ASSERT_TRUE(u.exists);
    EXPECT_NEAR(u.depth, sag.x, 1e-8);
    EXPECT_NEAR(u.M, sag.M, 1e-7 * sag.M);
    // Hogging: the web's bottom compressed (width bw, within h - hf).
    const Hand hog = teeUltimate(d, -1, n, 0.3, 0.6 - zg);
    ASSERT_LT(hog.x, 0.45);
    const RcSection::State v = s.ultimate(n, -1);
    ASSERT_TRUE(v.exists);
    EXPECT_NEAR(v.depth, hog.x, 1e-8);
    EXPECT_NEAR(v.M, hog.M, 1e-7 * hog.M);
    // At N = 0 the flange's side (with the main bars) is the strong one; under
    // compression the web's compressed bottom, far from the centroid near the
    // flange, gains more (1322 against 1013 kN m at -1500 kN).
    if (n == 0) {
      EXPECT_GT(u.M, 1.3 * v.M);
    }
  }
  // By hand at N = 0 (the slab bars next to the neutral axis carry little):
  // T = 6 A25 fy = 1472.6 kN, x ~ T/(17/21 fc beff) = 0.0505 m, Mu ~ T (0.55 -
  // 99/238 x) = 779 kN m.
  EXPECT_NEAR(s.ultimate(0, 1).M, 1472.6 * (0.55 - 99.0 / 238 * 0.0505), 8.0);
  // Shear: the web's bw and the bars' depth.
  EXPECT_EQ(s.shape().webWidth(), 0.3);
  EXPECT_NEAR(s.shape().shearArea(0.2), 5.0 / 6 * 0.3 * 0.6, 1e-15);
}

// ---------------------------------------------------------------------------
// Circles: the stress times the chord width, the midpoint rule over the depth.
struct Round {
  double D = 0, t = 0;  // t = 0: solid
};

double chord(const Round& c, double z) {
  const double r = c.D / 2, y = z - r;
  double w = 2 * std::sqrt(std::max(0.0, r * r - y * y));
  if (c.t > 0) {
    const double ri = r - c.t;
    if (std::abs(y) < ri) w -= 2 * std::sqrt(ri * ri - y * y);
  }
  return w;
}

double concreteStress(double e, double fc) {
  if (e >= 0) return 0;
  if (e <= -kC2) return -fc;
  const double r = -e / kC2;
  return -fc * (2 * r - r * r);
}

// n bars of area a on the circle at cover c, the first at the top.
std::vector<RebarLayer> ring(double D, int n, double a, double c) {
  std::vector<RebarLayer> bars;
  for (int i = 0; i < n; ++i) bars.push_back({D / 2 - (D / 2 - c) * std::cos(2 * kPi * i / n), a});
  return bars;
}

Hand roundUltimate(const RcSectionData& d, const Round& c, double N) {
  constexpr int kStrips = 200000;
  double dmax = 0;
  for (const RebarLayer& b : d.bars) dmax = std::max(dmax, b.depth);
  const double dz = c.D / kStrips, zg = c.D / 2;
  return solveDepth(1e-6, dmax - 1e-6, N, [&](double x, double& m) {
    const double kappa = ultimateKappa(x, dmax, d.eu);
    double n = 0;
    m = 0;
    for (int i = 0; i < kStrips; ++i) {
      const double z = (i + 0.5) * dz;
      const double f = concreteStress(kappa * (z - x), d.fc) * chord(c, z) * dz;
      n += f;
      m += f * (z - zg);
    }
    for (const RebarLayer& b : d.bars) {
      const double s = barStress(d, kappa * (b.depth - x));
      n += b.area * s;
      m += b.area * s * (b.depth - zg);
    }
    return n;
  });
}

void expectRoundUltimate(const RcSectionData& d, const Round& c, double N) {
  SCOPED_TRACE("N = " + std::to_string(N));
  const RcSection s(d);
  const Hand h = roundUltimate(d, c, N);
  for (int sign : {1, -1}) {  // the bars' ring is symmetric about mid-depth
    const RcSection::State u = s.ultimate(N, sign);
    ASSERT_TRUE(u.exists);
    EXPECT_NEAR(u.depth, h.x, 1e-5 * c.D);
    EXPECT_NEAR(u.M, h.M, 1e-4 * h.M);
  }
}

TEST(RcShape, CircularColumnUltimateMomentsAgainstTheChordWidthsSummed) {
  // D 0.6 m, 12 bars of 20 mm at the cover 0.06 m.
  RcSectionData d = c30b500();
  d.shape = SectionShapeKind::Circle;
  d.b = d.h = 0.6;
  d.bars = ring(0.6, 12, kPi * 1e-4, 0.06);
  expectRoundUltimate(d, {0.6, 0}, 0.0);
  expectRoundUltimate(d, {0.6, 0}, -2000.0);  // about 0.24 fc A
  // By hand at N = 0 (rough): the bars alone 12 A fy = 1885 kN would balance
  // a segment of depth ~0.15 m; Mu between 0.3 and 0.45 of 1885 x 0.6.
  const double mu = RcSection(d).ultimate(0, 1).M;
  EXPECT_GT(mu, 0.3 * 1885 * 0.6);
  EXPECT_LT(mu, 0.45 * 1885 * 0.6);
}

TEST(RcShape, AnnularChimneyUltimateMomentsAgainstTheChordWidthsSummed) {
  // A chimney's shaft: D 4 m, wall 0.25 m, 60 bars of 20 mm at cover 0.06 m.
  RcSectionData d = c30b500();
  d.shape = SectionShapeKind::Annulus;
  d.b = d.h = 4.0;
  d.wall = 0.25;
  d.bars = ring(4.0, 60, kPi * 1e-4, 0.06);
  expectRoundUltimate(d, {4.0, 0.25}, 0.0);
  expectRoundUltimate(d, {4.0, 0.25}, -8000.0);  // about its own weight of 50 m
}

TEST(RcShape, UncrackedStiffnessesOfTheRoundShapesAgainstClosedForms) {
  RcSectionData d = c30b500();
  d.shape = SectionShapeKind::Circle;
  d.b = d.h = 0.6;
  const int nb = 12;
  const double ab = kPi * 1e-4, rho = 0.3 - 0.06, n1 = 200.0 / 30 - 1;
  d.bars = ring(0.6, nb, ab, 0.06);
  {
    const RcSection s(d);
    const double a = kPi * 0.36 / 4, i = kPi * std::pow(0.6, 4) / 64;
    EXPECT_NEAR(s.shape().area(), a, 1e-15);
    EXPECT_NEAR(s.shape().secondMoment(), i, 1e-15);
    EXPECT_NEAR(s.EA(), 30e6 * (a + n1 * nb * ab), 1e-6 * s.EA());
    // The ring's bars: sum A (rho cos)^2 = n A rho^2 / 2.
    EXPECT_NEAR(s.EI(), 30e6 * (i + n1 * nb * ab * rho * rho / 2), 1e-9 * s.EI());
    EXPECT_NEAR(s.centroidDepth(), 0.3, 1e-12);
    // Cowper's shear factor of a solid circle, 6 (1 + nu)/(7 + 6 nu) = 0.8780.
    EXPECT_NEAR(s.GA(), 30e6 / 2.4 * 7.2 / 8.2 * a, 1e-6 * s.GA());
    EXPECT_NEAR(s.squashLoad(), 30e3 * a + nb * ab * 400e3, 1e-9);
    EXPECT_EQ(s.shape().webWidth(), 0.6);
    EXPECT_NEAR(s.shape().effectiveDepth(0.54), 0.48, 1e-15);  // 0.8 D (ACI 318-19 22.5.2.2)
  }
  d.shape = SectionShapeKind::Annulus;
  d.wall = 0.1;
  {
    const RcSection s(d);
    const double a = kPi * (0.36 - 0.16) / 4, i = kPi * (std::pow(0.6, 4) - std::pow(0.4, 4)) / 64;
    EXPECT_NEAR(s.shape().area(), a, 1e-15);
    EXPECT_NEAR(s.shape().secondMoment(), i, 1e-15);
    EXPECT_NEAR(s.EI(), 30e6 * (i + n1 * nb * ab * rho * rho / 2), 1e-9 * s.EI());
    EXPECT_EQ(s.shape().webWidth(), 0.2);  // the two walls
    // Widths: the two walls' at mid-depth, the chord at the top.
    EXPECT_NEAR(s.shape().width(0.3, 1), 0.2, 1e-15);
    EXPECT_NEAR(s.shape().width(0.05, -1), 2 * std::sqrt(0.09 - 0.0625), 1e-14);
  }
  // Sizes that make no shape.
  d.wall = 0.3;
  EXPECT_THROW(RcSection{d}, std::invalid_argument);
  RcSectionData t = teeBeam();
  t.flangeWidth = 0.2;
  EXPECT_THROW(RcSection{t}, std::invalid_argument);
  t = teeBeam();
  t.flangeDepth = 0.6;
  EXPECT_THROW(RcSection{t}, std::invalid_argument);
}

// The closed form of the disk's pieces equals the midpoint sums for planes
// cutting it anywhere (either kink inside, outside, both), both signs.
TEST(RcShape, DiskResultantsOfArbitraryPlanes) {
  RcSectionData d = c30b500();
  d.shape = SectionShapeKind::Annulus;
  d.b = d.h = 1.0;
  d.wall = 0.2;
  d.bars = {{0.5, 1e-4}};
  const SectionShape shape(d);
  const Round c{1.0, 0.2};
  for (double e0 : {-0.004, -0.0015, 0.0005})
    for (double kappa : {-0.003, 0.0, 0.002, 0.01}) {
      constexpr int k = 100000;
      double n = 0, m = 0;
      for (int i = 0; i < k; ++i) {
        const double z = (i + 0.5) / k;
        const double f = concreteStress(e0 + kappa * z, 30e3) * chord(c, z) / k;
        n += f;
        m += f * (z - 0.5);
      }
      const SectionShape::Resultant r = shape.concrete(e0, kappa, 1, 30e3, kC2);
      const double scale = 30e3 * shape.area();
      EXPECT_NEAR(r.N, n, 1e-6 * scale) << e0 << " " << kappa;
      EXPECT_NEAR(r.M, m, 1e-6 * scale) << e0 << " " << kappa;
    }
}

}  // namespace
}  // namespace c2d
