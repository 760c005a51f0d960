#include "materials/ShearResistance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/MaterialSet.h"
#include "materials/SectionShape.h"

namespace c2d {

namespace {

// alpha_cw of EC2 6.2.3(3) Note 3 at the compression sigma (positive), fc the strength.
double strutFactor(double sigma, double fc) {
  if (sigma <= 0) return 1.0;
  if (sigma <= 0.25 * fc) return 1.0 + sigma / fc;
  if (sigma <= 0.5 * fc) return 1.25;
  return std::max(0.0, 2.5 * (1.0 - sigma / fc));
}

}  // namespace

ShearResistance::ShearResistance(const std::array<Web, 2>& webs, double area, double fc,
                                 const std::optional<Stirrups>& stirrups)
    : area_(area), fc_(fc) {
  if (!(fc >= kMinFc && fc <= kMaxFc))
    throw std::invalid_argument(
        "fc = " + std::to_string(fc) +
        " is not a concrete strength in kN/m^2 (the shear rule, EC2 6.2.2, reads it as " +
        std::to_string(fc * kMPaPerStress) + " MPa; 30 MPa is 30e3 kN/m^2)");
  if (!(area > 0)) throw std::invalid_argument("the section's area must be positive");
  const double fcMPa = fc * kMPaPerStress;
  nu_ = 0.6 * (1 - fcMPa / 250);  // 6.6N
  for (int k = 0; k < 2; ++k) {
    const Web& w = webs[k];
    if (!(w.bw > 0) || !(w.d > 0))
      throw std::invalid_argument("the shear rule needs a web width and an effective depth");
    const double kd = std::min(2.0, 1 + std::sqrt(200 / (w.d * kMmPerLength)));
    const double rho = std::min(kRhoMax, w.asl / (w.bw * w.d));
    const double v = kCRdc * kd * std::cbrt(100 * rho * fcMPa);
    const double vmin = 0.035 * std::pow(kd, 1.5) * std::sqrt(fcMPa);
    s_[k] = {w, std::max(v, vmin) / kMPaPerStress, 0.5 * nu_ * fc * w.bw * w.d};
  }
  if (stirrups) omega_ = stirrups->area * stirrups->fy / stirrups->spacing;
  floor_ = 1e-9 * capacity(0.0);
}

std::array<ShearResistance::Web, 2> ShearResistance::webs(const SectionShape& shape,
                                                          const std::vector<RebarLayer>& bars) {
  const double h = shape.depth();
  std::array<Web, 2> w;
  for (int k = 0; k < 2; ++k) {
    w[k].bw = shape.webWidth();
    double farthest = 0;
    for (const RebarLayer& l : bars) {
      const double depth = k == 0 ? l.depth : h - l.depth;  // from the compressed face
      farthest = std::max(farthest, depth);
      if (depth > 0.5 * h) w[k].asl += l.area;
    }
    w[k].d = shape.effectiveDepth(farthest);
  }
  return w;
}

ShearResistance::Parts ShearResistance::parts(double N, int sign) const {
  const Sign& s = s_[sign > 0 ? 0 : 1];
  const double sigma = -N / area_;  // compression positive
  Parts p;
  const double vc = s.vc + kK1 * std::min(sigma, 0.2 * fc_);
  p.concrete = std::clamp(vc * s.web.bw * s.web.d, 0.0, s.vcap);
  if (omega_ > 0) {
    // The most the truss carries: VRd,s = omega z c rises with c = cot(theta),
    // VRd,max = a z c / (1 + c^2) falls for c > 1; they meet at c^2 = a/omega - 1.
    const double a = strutFactor(sigma, fc_) * s.web.bw * nu_ * fc_, z = kZ * s.web.d;
    p.cot = std::clamp(std::sqrt(std::max(0.0, a / omega_ - 1)), kCotMin, kCotMax);
    p.stirrups = std::min(omega_ * z * p.cot, a * z * p.cot / (1 + p.cot * p.cot));
  }
  p.vu = std::max(p.concrete, p.stirrups);
  return p;
}

double ShearResistance::capacity(double N) const {
  return std::min(capacity(N, 1), capacity(N, -1));
}

double ShearResistance::demand(double V, double N) const {
  return std::abs(V) / std::max(capacity(N), floor_);
}

}  // namespace c2d
