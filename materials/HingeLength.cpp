#include "materials/HingeLength.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "materials/Confinement.h"

namespace c2d {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kBarSpacing = 0.15;  // m: restrained bars' spacing, EN 1998-1 5.4.3.2.2(11)

}  // namespace

double tensionBarDiameter(const RcSectionData& d, const SectionShape& shape, int sign) {
  if (d.bars.empty()) return 0;
  const bool round = d.shape == SectionShapeKind::Circle || d.shape == SectionShapeKind::Annulus;
  if (round) {  // the layer nearest the top face is one bar of a ring
    const RebarLayer* top = &d.bars.front();
    for (const RebarLayer& l : d.bars)
      if (l.depth < top->depth) top = &l;
    return std::sqrt(4 * top->area / d.kept / kPi);
  }
  // The layer farthest from the compressed face (depth in the sign's frame).
  const RebarLayer* far = &d.bars.front();
  for (const RebarLayer& l : d.bars)
    if ((sign > 0 ? l.depth : d.h - l.depth) > (sign > 0 ? far->depth : d.h - far->depth)) far = &l;
  const double cover = std::min(far->depth, d.h - far->depth);
  // The original member's width and bars (WEAKen scales both by kept).
  const double clear = std::max(0.0, shape.width(far->depth, 1) / d.kept - 2 * cover);
  const double n = std::max(2.0, 1 + std::ceil(clear / kBarSpacing - 1e-9));
  return std::sqrt(4 * far->area / d.kept / (n * kPi));
}

std::optional<double> strainPenetration(const RcSectionData& d, const SectionShape& shape,
                                        int sign) {
  const auto mpa = stressUnitInMPa(d.fc);
  if (!mpa) return std::nullopt;
  return 0.11 * tensionBarDiameter(d, shape, sign) * d.fy * *mpa / std::sqrt(d.fc * *mpa);
}

double hingeLengthBase(const RcSectionData& d, const SectionShape& shape, int sign) {
  return 0.2 * d.h + strainPenetration(d, shape, sign).value_or(0.0);
}

double plasticHingeLength(double base, double Lv) { return Lv / 30 + base; }

double rotationLength(double base, double Lv) {
  const double lpl = std::min(plasticHingeLength(base, Lv), Lv);
  return lpl * (1 - 0.5 * lpl / Lv);
}

double shearSpan(double L, double Ma, double Mb) {
  const double dm = std::abs(Ma - Mb);
  return dm > 0 ? std::abs(Ma) * L / dm : std::numeric_limits<double>::infinity();
}

double boundedShearSpan(double Lv, double h) {
  return std::clamp(Lv, kShearSpanMin * h, kShearSpanMax * h);
}

}  // namespace c2d
