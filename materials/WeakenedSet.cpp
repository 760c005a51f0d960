#include "materials/WeakenedSet.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "materials/SectionLaws.h"

namespace c2d {

namespace {

void scaleHandGivenLaws(MaterialSet& m, double f) {
  m.E *= f;
  for (std::optional<double>* r : {&m.resEA, &m.resGA, &m.resEI})
    if (*r) **r *= f;
  if (m.hardening) {
    auto scale = [f](HardeningValues& h) {
      h.Mc *= f;
      h.My *= f;
      h.Kh1 *= f;
      h.Kh2 *= f;
    };
    scale(*m.hardening);
    if (m.hardening->negative) scale(*m.hardening->negative);
  }
  if (m.softening) {
    m.softening->Mu *= f;
    m.softening->Ks *= f;
    m.softening->Mr *= f;
    if (auto& n = m.softening->negative) {
      n->first *= f;
      n->second *= f;
    }
  }
  for (auto& [N, Mu] : m.interaction) {
    N *= f;
    Mu *= f;
  }
}

}  // namespace

MaterialSet weakenedSet(const MaterialSet& mat, double f, int number) {
  if (!(f > 0) || f > 1 || !std::isfinite(f))
    throw std::invalid_argument("the share kept must lie in (0, 1]");
  MaterialSet m = mat;
  m.number = number;
  std::ostringstream label;
  label << mat.label << (mat.label.empty() ? "" : ", ") << "set " << mat.number << " weakened to "
        << f;
  m.label = label.str();
  if (m.section) {
    // Every width of the concrete and every bar area times f scales each
    // resultant of a strain plane by f: the section's laws scale exactly. A
    // circle has no width of its own to scale.
    RcSectionData& s = *m.section;
    if (s.shape == SectionShapeKind::Circle || s.shape == SectionShapeKind::Annulus)
      throw std::invalid_argument(
          "a CIRCular or ANNUlar section has no width to scale: give the weakened member a "
          "material set of its own (fewer bars, a thinner wall)");
    s.b *= f;
    s.flangeWidth *= f;
    for (RebarLayer& l : s.bars) l.area *= f;
    if (s.stirrups) s.stirrups->area *= f;
    s.kept *= f;
    m.density /= f;
  } else {
    scaleHandGivenLaws(m, f);
  }
  deriveSectionLaws(m);
  return m;
}

}  // namespace c2d
