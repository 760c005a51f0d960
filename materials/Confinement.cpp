#include "materials/Confinement.h"

#include <algorithm>
#include <cmath>

namespace c2d {

std::optional<Confinement> confinementOf(const RcSectionData& d) {
  if (!d.stirrups || d.bars.empty()) return std::nullopt;
  double top = d.h, bottom = 0;
  for (const RebarLayer& l : d.bars) {
    top = std::min(top, l.depth);
    bottom = std::max(bottom, l.depth);
  }
  const double cover = std::min(top, d.h - bottom);
  Confinement c;
  c.b0 = d.b / d.kept - 2 * cover;  // the original member's core (WEAKen)
  c.h0 = bottom - top;
  if (!(c.b0 > 0) || !(c.h0 > 0)) return std::nullopt;  // one layer: no core
  const Stirrups& st = *d.stirrups;
  c.alphaS = std::max(0.0, 1 - st.spacing / (2 * c.b0)) * std::max(0.0, 1 - st.spacing / (2 * c.h0));
  c.alphaN = std::max(0.0, 1 - (2 * c.b0 * c.b0 + 2 * c.h0 * c.h0) / (6 * c.b0 * c.h0));
  c.alpha = c.alphaS * c.alphaN;
  c.rhoSx = st.area / (d.b * st.spacing);
  const double index = c.alpha * c.rhoSx * st.fy / d.fc;
  c.fcc = d.fc * (1 + 3.7 * std::pow(index, 0.86));
  c.epsCu = 0.004 + 0.5 * c.alpha * c.rhoSx * st.fy / c.fcc;
  return c;
}

std::optional<double> stressUnitInMPa(double fc) {
  if (fc >= 5 && fc <= 150) return 1.0;
  if (fc >= 5e3 && fc <= 1.5e5) return 1e-3;
  if (fc >= 5e6 && fc <= 1.5e8) return 1e-6;
  return std::nullopt;
}

std::optional<double> chordRotationFactor(const RcSectionData& d, double N, int sign) {
  const auto mpa = stressUnitInMPa(d.fc);
  if (!mpa) return std::nullopt;
  // Depths in the sign's frame: the compressed face at 0.
  double tension = 0, compression = 0, depth = 0;
  for (const RebarLayer& l : d.bars) {
    const double z = sign > 0 ? l.depth : d.h - l.depth;
    (z > 0.5 * d.h ? tension : compression) += l.area;
    if (z > 0.5 * d.h) depth = std::max(depth, z);
  }
  if (!(depth > 0)) depth = 0.9 * d.h;
  const double w = tension * d.fy / (d.b * depth * d.fc);
  const double wc = compression * d.fy / (d.b * depth * d.fc);
  const double nu = std::max(0.0, -N / (d.b * d.h * d.fc));
  double confinement = 0;
  if (const auto c = confinementOf(d)) confinement = c->alpha * c->rhoSx * d.stirrups->fy / d.fc;
  return 0.016 * std::pow(0.3, nu) *
         std::pow(std::max(0.01, wc) / std::max(0.01, w) * d.fc * *mpa, 0.225) *
         std::pow(25.0, confinement);
}

}  // namespace c2d
