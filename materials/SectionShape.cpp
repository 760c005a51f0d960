#include "materials/SectionShape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace c2d {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Sorts the first n of at most four cuts (insertion sort).
void sortCuts(double* cuts, int n) {
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
}

// Antiderivatives of cos^k(phi) sin^2(phi), k = 0..3, at phi.
void trigPrimitives(double phi, double f[4]) {
  const double s = std::sin(phi), s3 = s * s * s;
  f[0] = phi / 2 - std::sin(2 * phi) / 4;
  f[1] = s3 / 3;
  f[2] = phi / 8 - std::sin(4 * phi) / 32;
  f[3] = s3 / 3 - s3 * s * s / 5;
}

}  // namespace

SectionShape::SectionShape(const RcSectionData& d) : kind_(d.shape), h_(d.h) {
  auto bad = [](const char* what) { throw std::invalid_argument(what); };
  switch (kind_) {
    case SectionShapeKind::Rectangle:
      if (!(d.b > 0) || !(d.h > 0)) bad("section width b and depth h must be positive");
      web_ = d.b;
      strips_ = {{0, d.h, d.b}};
      break;
    case SectionShapeKind::Tee:
      if (!(d.b > 0) || !(d.h > 0))
        bad("the T-section's web width bw and depth h must be positive");
      if (!(d.flangeWidth >= d.b)) bad("the T-section's flange width beff must not be below bw");
      if (!(d.flangeDepth > 0 && d.flangeDepth < d.h))
        bad("the T-section's flange thickness hf must lie in (0, h)");
      web_ = d.b;
      strips_ = {{0, d.flangeDepth, d.flangeWidth}, {d.flangeDepth, d.h, d.b}};
      break;
    case SectionShapeKind::Circle:
      if (!(d.h > 0)) bad("the circle's diameter D must be positive");
      web_ = d.h;
      disks_ = {{d.h / 2, d.h / 2, 1}};
      break;
    case SectionShapeKind::Annulus:
      if (!(d.h > 0)) bad("the annulus' diameter D must be positive");
      if (!(d.wall > 0 && d.wall < d.h / 2))
        bad("the annulus' wall thickness t must lie in (0, D/2)");
      wall_ = d.wall;
      web_ = 2 * d.wall;
      disks_ = {{d.h / 2, d.h / 2, 1}, {d.h / 2, d.h / 2 - d.wall, -1}};
      break;
  }
  double s1 = 0;
  for (const Strip& p : strips_) {
    area_ += p.w * (p.z1 - p.z0);
    s1 += p.w * (p.z1 - p.z0) * 0.5 * (p.z0 + p.z1);
  }
  for (const Disk& p : disks_) {
    area_ += p.s * kPi * p.r * p.r;
    s1 += p.s * kPi * p.r * p.r * p.zc;
  }
  // Symmetric shapes: mid-depth exactly (the rectangles' numbers as before).
  zg_ = kind_ == SectionShapeKind::Tee ? s1 / area_ : h_ / 2;
  for (const Strip& p : strips_) {
    const double t = p.z1 - p.z0, a = p.w * t, e = 0.5 * (p.z0 + p.z1) - zg_;
    i_ += p.w * t * t * t / 12 + a * e * e;
  }
  for (const Disk& p : disks_) {
    const double r2 = p.r * p.r, e = p.zc - zg_;
    i_ += p.s * kPi * r2 * (r2 / 4 + e * e);
  }
}

double SectionShape::width(double z, int sign) const {
  const double zz = sign > 0 ? z : h_ - z;
  double w = 0;
  for (const Strip& p : strips_)
    if (zz >= p.z0 && zz < p.z1) w += p.w;
  for (const Disk& p : disks_)
    if (const double y = zz - p.zc; std::abs(y) < p.r) w += p.s * 2 * std::sqrt(p.r * p.r - y * y);
  return w;
}

double SectionShape::webWidth() const { return web_; }

double SectionShape::effectiveDepth(double farthestBars) const {
  const bool round = kind_ == SectionShapeKind::Circle || kind_ == SectionShapeKind::Annulus;
  return round ? 0.8 * h_ : farthestBars;
}

double SectionShape::shearFactor(double nu) const {
  if (kind_ == SectionShapeKind::Rectangle || kind_ == SectionShapeKind::Tee) return 5.0 / 6.0;
  const double m = kind_ == SectionShapeKind::Annulus ? 1 - 2 * wall_ / h_ : 0.0;
  const double q = (1 + m * m) * (1 + m * m);
  return 6 * (1 + nu) * q / ((7 + 6 * nu) * q + (20 + 12 * nu) * m * m);
}

double SectionShape::shearWidth() const {
  const bool round = kind_ == SectionShapeKind::Circle || kind_ == SectionShapeKind::Annulus;
  return round ? area_ / h_ : web_;
}

double SectionShape::parabolaRectangle(double e, double fc, double epsC2) {
  if (e >= 0) return 0.0;
  if (e <= -epsC2) return -fc;
  const double x = e / epsC2;
  return fc * (2 * x + x * x);
}

SectionShape::Resultant SectionShape::strip(const Strip& p, double e0, double kappa, double zg,
                                            double fc, double epsC2) const {
  double cuts[4] = {p.z0, p.z1, 0, 0};
  int nc = 2;
  if (kappa != 0)
    for (double e : {0.0, -epsC2}) {
      const double z = (e - e0) / kappa;
      if (z > p.z0 && z < p.z1) cuts[nc++] = z;
    }
  sortCuts(cuts, nc);
  Resultant f;
  const double g = 1 / std::sqrt(3.0);
  for (int i = 0; i + 1 < nc; ++i) {
    const double zm = 0.5 * (cuts[i] + cuts[i + 1]), hw = 0.5 * (cuts[i + 1] - cuts[i]);
    for (double z : {zm - g * hw, zm + g * hw}) {
      const double sg = parabolaRectangle(e0 + kappa * z, fc, epsC2);
      f.N += p.w * hw * sg;
      f.M += p.w * hw * sg * (z - zg);
    }
  }
  return f;
}

SectionShape::Resultant SectionShape::disk(const Disk& p, double e0, double kappa, double zg,
                                           double fc, double epsC2) const {
  // z = zc - r cos(phi), phi in [0, pi]; the kinks' depths as angles.
  double cuts[4] = {0, kPi, 0, 0};
  int nc = 2;
  if (kappa != 0)
    for (double e : {0.0, -epsC2}) {
      const double c = (p.zc - (e - e0) / kappa) / p.r;
      if (c > -1 && c < 1) cuts[nc++] = std::acos(c);
    }
  sortCuts(cuts, nc);
  // On a piece, sigma = s0 + s1 c + s2 c^2 (c = cos phi) and the arm z - zg =
  // pa + qa c; N = 2 r^2 int sigma sin^2, M = 2 r^2 int sigma (pa + qa c) sin^2.
  const double pa = p.zc - zg, qa = -p.r;
  const double a = (e0 + kappa * p.zc) / epsC2, b = -kappa * p.r / epsC2;
  Resultant f;
  double lo[4], hi[4];
  trigPrimitives(cuts[0], lo);
  for (int i = 0; i + 1 < nc; ++i) {
    trigPrimitives(cuts[i + 1], hi);
    const double mid = 0.5 * (cuts[i] + cuts[i + 1]);
    const double e = e0 + kappa * (p.zc - p.r * std::cos(mid));
    double s[3] = {0, 0, 0};
    if (e <= -epsC2)
      s[0] = -fc;
    else if (e < 0) {
      s[0] = fc * (2 * a + a * a);
      s[1] = fc * (2 * b + 2 * a * b);
      s[2] = fc * b * b;
    }
    double j[4];
    for (int k = 0; k < 4; ++k) j[k] = hi[k] - lo[k];
    for (int k = 0; k < 3; ++k) {
      f.N += s[k] * j[k];
      f.M += s[k] * (pa * j[k] + qa * j[k + 1]);
    }
    std::copy(hi, hi + 4, lo);
  }
  const double scale = 2 * p.s * p.r * p.r;
  f.N *= scale;
  f.M *= scale;
  return f;
}

SectionShape::Resultant SectionShape::concrete(double e0, double kappa, int sign, double fc,
                                               double epsC2) const {
  const double zg = centroidDepth(sign);
  Resultant f;
  for (Strip p : strips_) {
    if (sign < 0) p = {h_ - p.z1, h_ - p.z0, p.w};
    const Resultant r = strip(p, e0, kappa, zg, fc, epsC2);
    f.N += r.N;
    f.M += r.M;
  }
  for (Disk p : disks_) {
    if (sign < 0) p.zc = h_ - p.zc;
    const Resultant r = disk(p, e0, kappa, zg, fc, epsC2);
    f.N += r.N;
    f.M += r.M;
  }
  return f;
}

}  // namespace c2d
