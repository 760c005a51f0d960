#include "materials/RcSection.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "materials/Confinement.h"
#include "materials/HingeLength.h"

namespace c2d {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kTableNodes = 81;

// Root of an increasing function on [lo, hi] with f(lo) <= 0 <= f(hi): regula
// falsi (Illinois), a bisection whenever a step does not shrink the bracket
// enough; ends at |f| <= ftol or at a bracket of round-off width.
double increasingRoot(const std::function<double(double)>& f, double lo, double hi, double flo,
                      double fhi, double ftol) {
  int side = 0;
  double x = lo;
  for (int it = 0; it < 200; ++it) {
    const double width = hi - lo;
    if (!(width > 4 * std::numeric_limits<double>::epsilon() * (std::abs(lo) + std::abs(hi))))
      break;
    x = fhi != flo ? lo - flo * width / (fhi - flo) : 0.5 * (lo + hi);
    if (!(x > lo && x < hi) || it % 4 == 3) x = 0.5 * (lo + hi);
    const double fx = f(x);
    if (std::abs(fx) <= ftol) return x;
    if (fx < 0) {
      lo = x;
      flo = fx;
      if (side == -1) fhi *= 0.5;
      side = -1;
    } else {
      hi = x;
      fhi = fx;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
  }
  return x;
}

}  // namespace

RcSection::RcSection(const RcSectionData& data) : d_(data), shape_(data) {
  auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!(d_.fc > 0)) bad("concrete strength fc must be positive");
  if (!(d_.fy > 0)) bad("bar yield stress fy must be positive");
  if (!(d_.Es > 0)) bad("bar modulus Es must be positive");
  if (!(d_.fu >= d_.fy)) bad("bar ultimate stress fu must not be below fy");
  if (!(d_.eu > d_.fy / d_.Es)) bad("bar fracture strain eu must exceed the yield strain fy/Es");
  if (d_.bars.empty()) bad("the section has no bars (REBAr)");
  for (const RebarLayer& r : d_.bars) {
    if (!(r.depth > 0 && r.depth < d_.h))
      bad("a bar layer lies outside the section (0 < depth < h)");
    if (!(r.area > 0)) bad("a bar layer's area must be positive");
  }
  if (const auto& st = d_.stirrups; st && !(st->area > 0 && st->spacing > 0 && st->fy > 0))
    bad("the stirrups' area, spacing and yield stress must be positive");
  shear_.emplace(ShearResistance::webs(shape_, d_.bars), shape_.area(), d_.fc, d_.stirrups);
  fcc_ = d_.fc;
  if (const auto c = confinementOf(d_)) {
    epsCuc_ = std::max(kEpsCu2, c->epsCu);
    fcc_ = c->fcc;
    epsC2c_ = kEpsC2 * (fcc_ / d_.fc) * (fcc_ / d_.fc);  // EC2 (3.26)
  }
  for (int k = 0; k < 2; ++k) lplBase_[k] = c2d::hingeLengthBase(d_, shape_, k == 0 ? 1 : -1);
  bars_[0] = d_.bars;
  bars_[1] = d_.bars;
  for (RebarLayer& r : bars_[1]) r.depth = d_.h - r.depth;
  ec_ = 2 * d_.fc / kEpsC2;
  const double n1 = d_.Es / ec_ - 1;
  double s = 0, s2 = 0;
  for (const RebarLayer& r : d_.bars) {
    as_ += r.area;
    s += r.area * r.depth;
    s2 += r.area * r.depth * r.depth;
  }
  const double ac = shape_.area(), zg = shape_.centroidDepth(1);
  atr_ = ac + n1 * as_;
  ztr_ = (ac * zg + n1 * s) / atr_;
  itr_ = shape_.secondMoment() + ac * (zg - ztr_) * (zg - ztr_) +
         n1 * (s2 - 2 * ztr_ * s + ztr_ * ztr_ * as_);

  for (int k = 0; k < 2; ++k) zero_[k] = rawPoints(0.0, k == 0 ? 1 : -1);
  // Nodes on [-Nc, 0] and [0, Nt] (N = 0 one of them: the laws echoed and
  // used at N = 0 are the section's), about as far apart on both sides.
  const double nLo = -squashLoad(), nHi = tensionYield();
  const int below = std::clamp(
      static_cast<int>(std::lround((kTableNodes - 1) * -nLo / (nHi - nLo))), 4, kTableNodes - 5);
  std::vector<double> ns;
  for (int i = 0; i <= below; ++i) ns.push_back(nLo * (1 - static_cast<double>(i) / below));
  for (int i = 1; i < kTableNodes - below; ++i) ns.push_back(nHi * i / (kTableNodes - 1 - below));
  ns[below] = 0.0;
  for (int k = 0; k < 2; ++k) {
    std::array<std::vector<double>, 6> v;
    for (double n : ns) {
      const Points p = floored(rawPoints(n, k == 0 ? 1 : -1), k == 0 ? 1 : -1);
      const double vals[6] = {p.Mc, p.My, p.Mu, p.xiY, p.xiU, p.xiF};
      for (int j = 0; j < 6; ++j) v[j].push_back(vals[j]);
    }
    for (int j = 0; j < 6; ++j) table_[k][j] = MonotoneCubic(ns, v[j]);
  }
}

double RcSection::GA() const {
  return shape_.shearFactor(kConcretePoisson) * ec_ / (2 * (1 + kConcretePoisson)) *
         shape_.shearWidth() * d_.h;
}

double RcSection::squashLoad() const {
  return d_.fc * shape_.area() + as_ * std::min(d_.fy, d_.Es * kEpsC2);
}

RcSection::Forces RcSection::forces(double e0, double kappa, int sign, bool confined) const {
  const SectionShape::Resultant c = confined ? shape_.concrete(e0, kappa, sign, fcc_, epsC2c_)
                                             : shape_.concrete(e0, kappa, sign, d_.fc, kEpsC2);
  Forces f{c.N, c.M};
  const double zg = shape_.centroidDepth(sign);
  for (const RebarLayer& r : bars_[sign > 0 ? 0 : 1]) {
    const double sg = std::clamp(d_.Es * (e0 + kappa * r.depth), -d_.fy, d_.fy);
    f.N += r.area * sg;
    f.M += r.area * sg * (r.depth - zg);
  }
  return f;
}

std::optional<double> RcSection::topStrain(double N, double kappa, int sign, bool confined) const {
  const double ey = d_.fy / d_.Es, kh = kappa * d_.h;
  const double lo = -std::max(confined ? epsC2c_ : kEpsC2, ey) - std::max(0.0, kh) - 1e-6;
  const double hi = ey - std::min(0.0, kh) + 1e-6;
  const double nlo = forces(lo, kappa, sign, confined).N, nhi = forces(hi, kappa, sign, confined).N;
  const double scale = std::abs(nlo) + std::abs(nhi);
  if (N < nlo - 1e-12 * scale || N > nhi + 1e-12 * scale) return std::nullopt;
  return increasingRoot([&](double e) { return forces(e, kappa, sign, confined).N - N; }, lo, hi,
                        nlo - N, nhi - N, 1e-13 * scale);
}

namespace {

// The state where g(kappa, e0) reaches 1 at constant N, g increasing in kappa.
RcSection::State stateAt(const RcSection& s, double N, int sign,
                         const std::function<double(double, double)>& g, bool confined = false) {
  RcSection::State out;
  const auto e00 = s.topStrain(N, 0.0, sign, confined);
  if (!e00 || !(g(0.0, *e00) < 1)) return out;
  const double h = s.data().h;
  auto eval = [&](double kappa) {
    const auto e = s.topStrain(N, kappa, sign, confined);
    return e ? g(kappa, *e) - 1 : kInf;
  };
  double lo = 0, flo = g(0.0, *e00) - 1;
  double hi = s.data().fy / s.data().Es / h, fhi = eval(hi);
  for (int i = 0; i < 80 && fhi < 0; ++i) {
    lo = hi;
    flo = fhi;
    hi *= 2;
    fhi = eval(hi);
  }
  if (fhi < 0) return out;
  if (!std::isfinite(fhi)) fhi = 1;
  const double kappa = increasingRoot(eval, lo, hi, flo, fhi, 1e-13);
  const auto e0 = s.topStrain(N, kappa, sign, confined);
  if (!e0) return out;
  out.exists = true;
  out.kappa = kappa;
  out.e0 = *e0;
  out.M = s.forces(*e0, kappa, sign, confined).M;
  out.depth = kappa > 0 ? -*e0 / kappa : kInf;
  return out;
}

}  // namespace

RcSection::State RcSection::firstYield(double N, int sign) const {
  const double ey = d_.fy / d_.Es;
  const auto& bars = bars_[sign > 0 ? 0 : 1];
  return stateAt(*this, N, sign, [&](double kappa, double e0) {
    double g = -e0 / kEpsC2;
    for (const RebarLayer& r : bars) g = std::max(g, (e0 + kappa * r.depth) / ey);
    return g;
  });
}

namespace {

// The compressed face at epsCu, or epsC2 at (1 - epsC2/epsCu) h from it when
// the whole section is compressed, or a bar at eu (EC2 6.1(5), Fig. 6.1).
RcSection::State ultimateAt(const RcSection& s, const std::vector<RebarLayer>& bars, double N,
                            int sign, double epsCu, double epsC2, bool confined) {
  const RcSectionData& d = s.data();
  const double zc = (1 - epsC2 / epsCu) * d.h;
  return stateAt(
      s, N, sign,
      [&](double kappa, double e0) {
        double g = std::max(-e0 / epsCu, -(e0 + kappa * zc) / epsC2);
        for (const RebarLayer& r : bars) g = std::max(g, (e0 + kappa * r.depth) / d.eu);
        return g;
      },
      confined);
}

}  // namespace

RcSection::State RcSection::ultimate(double N, int sign) const {
  return ultimateAt(*this, bars_[sign > 0 ? 0 : 1], N, sign, kEpsCu2, kEpsC2, false);
}

RcSection::State RcSection::ultimateConfined(double N, int sign) const {
  if (epsCuc_ == kEpsCu2 && fcc_ == d_.fc) return ultimate(N, sign);
  return ultimateAt(*this, bars_[sign > 0 ? 0 : 1], N, sign, epsCuc_, epsC2c_, true);
}

RcSection::State RcSection::cracking(double N, int sign) const {
  State out;
  const double zs = sign > 0 ? ztr_ : d_.h - ztr_;  // centroid depth in the sign's frame
  const double mCent = (fct() - N / atr_) * itr_ / (d_.h - zs);
  if (!(mCent > 0)) return out;
  out.exists = true;
  out.kappa = mCent / (ec_ * itr_);
  out.e0 = N / (ec_ * atr_) - out.kappa * zs;
  out.M = mCent + N * (zs - shape_.centroidDepth(sign));
  out.depth = out.kappa > 0 ? -out.e0 / out.kappa : kInf;
  return out;
}

RcSection::State RcSection::balance(int sign) const {
  double dt = 0;
  for (const RebarLayer& r : bars_[sign > 0 ? 0 : 1]) dt = std::max(dt, r.depth);
  State out;
  out.exists = true;
  out.kappa = (kEpsCu2 + d_.fy / d_.Es) / dt;
  out.e0 = -kEpsCu2;
  out.M = forces(out.e0, out.kappa, sign).M;
  out.depth = kEpsCu2 / out.kappa;
  return out;
}

double RcSection::rotationLength(int sign, double Lv) const {
  return c2d::rotationLength(lplBase_[sign > 0 ? 0 : 1], Lv);
}

double RcSection::plasticRotation(double N, int sign, double Lv) const {
  const State y = firstYield(N, sign), u = ultimateConfined(N, sign);
  if (!y.exists || !u.exists) return 0;
  return std::max(0.0, (u.kappa - y.kappa) * rotationLength(sign, boundedShearSpan(Lv, d_.h)));
}

double RcSection::failureJump(int sign, double N, double Lv) const {
  return at(sign, N).xiF * rotationLength(sign, boundedShearSpan(Lv, d_.h)) /
         rotationLength(sign, referenceSpan());
}

double RcSection::ruptureRotation() const {
  double xiF = 0;
  for (int k = 0; k < 2; ++k) {
    const int sign = k == 0 ? 1 : -1;
    xiF = std::max(xiF, zero_[k].xiF * rotationLength(sign, kShearSpanMax * d_.h) /
                            rotationLength(sign, referenceSpan()));
  }
  return xiF + std::acos(1 / (1 + d_.eu));
}

double RcSection::shortestPiece() const {
  double lb = 0;
  for (int sign : {1, -1})
    lb = std::max(lb, zero_[sign > 0 ? 0 : 1].Mu / shearCapacity(0.0, sign));
  return lb;
}

RcSection::Points RcSection::rawPoints(double N, int sign) const {
  Points p;
  const State c = cracking(N, sign), y = firstYield(N, sign), u = ultimate(N, sign);
  const double ei = EI();
  if (c.exists) p.Mc = c.M;
  if (y.exists) {
    p.My = y.M;
    p.xiY = y.kappa - y.M / ei;
  }
  if (u.exists) {
    p.Mu = u.M;
    p.xiU = u.kappa - u.M / ei;
  }
  if (y.exists && u.exists) p.xiF = plasticRotation(N, sign, referenceSpan()) / kUltimateDrop;
  return p;
}

RcSection::Points RcSection::floored(const Points& p, int sign) const {
  const Points& z = zero_[sign > 0 ? 0 : 1];
  const double m0 = 0.01 * z.Mu;
  Points f;
  f.Mu = std::max(p.Mu, m0);
  f.My = std::min(std::max(p.My, 0.5 * m0), f.Mu);
  f.Mc = std::min(std::max(p.Mc, 0.25 * m0), f.My);
  f.xiY = std::max(p.xiY, 0.05 * z.xiY);
  f.xiU = std::max(p.xiU, f.xiY + 0.05 * (z.xiU - z.xiY));
  f.xiF = std::max(p.xiF, 0.25 * z.xiF);
  return f;
}

MomentLaw RcSection::at(int sign, double N) const {
  const auto& t = table_[sign > 0 ? 0 : 1];
  const MonotoneCubic::Value mc = t[0].at(N), my = t[1].at(N), mu = t[2].at(N), xy = t[3].at(N),
                             xu = t[4].at(N), xf = t[5].at(N);
  MomentLaw l;
  // The interpolants of the points keep their order at the nodes; between
  // them the order is enforced (the derivative of the one taken).
  l.Mu = mu.y;
  l.dMu = mu.dy;
  l.My = my.y;
  l.dMy = my.dy;
  if (l.My > l.Mu) {
    l.My = l.Mu;
    l.dMy = l.dMu;
  }
  l.Mc = mc.y;
  l.dMc = mc.dy;
  if (l.Mc > l.My) {
    l.Mc = l.My;
    l.dMc = l.dMy;
  }
  double xiY = xy.y, dxiY = xy.dy, xiU = xu.y, dxiU = xu.dy;
  if (xiU < xiY * (1 + 1e-9)) {
    xiU = xiY * (1 + 1e-9);
    dxiU = dxiY * (1 + 1e-9);
  }
  l.Kh1 = (l.My - l.Mc) / xiY;
  l.dKh1 = ((l.dMy - l.dMc) - l.Kh1 * dxiY) / xiY;
  l.Kh2 = (l.Mu - l.My) / (xiU - xiY);
  l.dKh2 = ((l.dMu - l.dMy) - l.Kh2 * (dxiU - dxiY)) / (xiU - xiY);
  l.xiF = xf.y;
  return l;
}

}  // namespace c2d
