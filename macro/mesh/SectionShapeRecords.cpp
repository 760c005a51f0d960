#include "macro/mesh/SectionShapeRecords.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "macro/mesh/SubRecordFields.h"
#include "materials/SectionShape.h"

namespace c2d {

using meshspec::failAt;

namespace {

// Defaults of SECTion: Es in kN/m^2 (the decks' system); fu and eu of
// Eurocode 2's class B bars (Annex C: ft/fy >= 1.08, eps_uk >= 5 %).
constexpr double kDefaultEs = 200e6, kDefaultHardeningRatio = 1.08, kDefaultFractureStrain = 0.05;
constexpr double kPi = 3.14159265358979323846;

std::string str(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

struct ShapeForm {
  SectionShapeKind kind;
  const char* keyword;
  std::size_t dims;
  const char* names[4];
};
constexpr ShapeForm kForms[] = {
    {SectionShapeKind::Rectangle, "RECTangular", 2, {"width b", "depth h", "", ""}},
    {SectionShapeKind::Tee,
     "TEE",
     4,
     {"web width bw", "depth h", "flange width beff", "flange thickness hf"}},
    {SectionShapeKind::Circle, "CIRCular", 1, {"diameter D", "", "", ""}},
    {SectionShapeKind::Annulus, "ANNUlar", 2, {"diameter D", "wall thickness t", "", ""}},
};

// The shape's sizes (fields 2 .. 1 + dims) into d, checked at their fields.
void bindSizes(const Record& r, const ShapeForm& form, const std::vector<double>& v,
               RcSectionData& d) {
  for (std::size_t i = 0; i < form.dims; ++i)
    if (!(v[i] > 0))
      failAt(r, 2 + i, std::string("the section's ") + form.names[i] + " must be positive");
  d.shape = form.kind;
  switch (form.kind) {
    case SectionShapeKind::Rectangle:
      d.b = v[0];
      d.h = v[1];
      break;
    case SectionShapeKind::Tee:
      d.b = v[0];
      d.h = v[1];
      d.flangeWidth = v[2];
      d.flangeDepth = v[3];
      if (!(d.flangeWidth >= d.b))
        failAt(r, 4,
               "the flange width beff = " + str(d.flangeWidth) +
                   " is below the web's bw = " + str(d.b));
      if (!(d.flangeDepth < d.h))
        failAt(r, 5,
               "the flange thickness hf = " + str(d.flangeDepth) +
                   " is not below the depth h = " + str(d.h));
      break;
    case SectionShapeKind::Circle:
      d.b = d.h = v[0];
      break;
    case SectionShapeKind::Annulus:
      d.b = d.h = v[0];
      d.wall = v[1];
      if (!(d.wall < d.h / 2))
        failAt(r, 3,
               "the wall thickness t = " + str(d.wall) + " is not below D/2 = " + str(d.h / 2),
               "for a solid section write SECTion CIRCular D fc fy");
      break;
  }
}

const char* sectionShapeSyntax(SectionShapeKind k) {
  switch (k) {
    case SectionShapeKind::Rectangle:
      return "SECTion RECTangular b h fc fy [Es [fu eu]]";
    case SectionShapeKind::Tee:
      return "SECTion TEE bw h beff hf fc fy [Es [fu eu]]";
    case SectionShapeKind::Circle:
      return "SECTion CIRCular D fc fy [Es [fu eu]]";
    case SectionShapeKind::Annulus:
      return "SECTion ANNUlar D t fc fy [Es [fu eu]]";
  }
  return "";
}

}  // namespace

void bindSectionShape(MeshContext& ctx, const Record& r, const CommandSpec& s, MaterialSet& mat,
                      LawRecords& seen) {
  const std::string any = "SECTion RECTangular/TEE/CIRCular/ANNUlar sizes fc fy [Es [fu eu]]";
  subrecord::requireText(r, s.name, any);
  const ShapeForm* form = nullptr;
  for (const ShapeForm& f : kForms)
    if (keywordMatches(r.text(1), f.keyword)) form = &f;
  if (!form)
    failAt(r, 1, "unknown shape '" + r.text(1) + "': RECTangular, TEE, CIRCular or ANNUlar",
           "write " + any);
  if (seen.section) failAt(r, 0, "SECTion given twice in one MATErial set");
  const std::string syntax = sectionShapeSyntax(form->kind);
  const std::size_t nd = form->dims;
  const auto v = subrecord::values(ctx, r, s.name, nd + 5, nd + 2, syntax);
  RcSectionData d;
  bindSizes(r, *form, v, d);
  d.fc = v[nd];
  d.fy = v[nd + 1];
  if (!(d.fc > 0)) failAt(r, 2 + nd, "the section's concrete strength fc must be positive");
  if (!(d.fy > 0)) failAt(r, 3 + nd, "the section's bar yield stress fy must be positive");
  auto given = [&](std::size_t field) { return r.size() > field && !r.text(field).empty(); };
  d.Es = given(4 + nd) ? v[nd + 2] : kDefaultEs;
  if (!(d.Es > 0)) failAt(r, 4 + nd, "the bar modulus Es must be positive");
  const bool ultimate = given(5 + nd);
  if (ultimate != given(6 + nd))
    failAt(r, ultimate ? r.size() : 5 + nd, "give both fu and eu (or neither)", "write " + syntax);
  d.fu = ultimate ? v[nd + 3] : kDefaultHardeningRatio * d.fy;
  d.eu = ultimate ? v[nd + 4] : kDefaultFractureStrain;
  if (!(d.fu >= d.fy))
    failAt(r, 5 + nd, "the bars' ultimate stress fu must not be below fy = " + str(d.fy));
  // The bars harden from fy at fy/Es to fu at eu: eu beyond fu/Es, the strain
  // of fu on the elastic line (materials/AxialCapacity), leaves the hardening room.
  if (!(d.eu > d.fu / d.Es))
    failAt(r, ultimate ? 6 + nd : 4 + nd,
           "the bars' fracture strain eu = " + str(d.eu) + " must exceed fu/Es = " +
               str(d.fu / d.Es) + " (the bars harden from fy to fu before they fracture)");
  d.bars = mat.section ? mat.section->bars : std::vector<RebarLayer>{};
  d.stirrups = mat.section ? mat.section->stirrups : std::nullopt;
  mat.section = d;
  seen.section = &r;
}

bool bindRebarRing(MeshContext& ctx, const Record& r, LawRecords& seen) {
  if (!(r.size() > 1 && keywordMatches(r.text(1), "RING"))) return false;
  const std::string syntax = "REBAr RING n A c";
  if (r.size() < 5) failAt(r, r.size(), "REBAr RING needs n, A and c", "write " + syntax);
  if (r.size() > 5) failAt(r, 5, "too many values: the record is '" + syntax + "'");
  const double n = ctx.number(r, 2), area = ctx.number(r, 3), cover = ctx.number(r, 4);
  if (!(n >= 2 && n <= 1000 && n == std::floor(n)))
    failAt(r, 2, "the number of bars n must be a whole number from 2 to 1000");
  if (!(area > 0)) failAt(r, 3, "a bar's area A must be positive");
  if (!(cover > 0)) failAt(r, 4, "the cover c to the bars' centres must be positive");
  seen.rings.push_back({&r, static_cast<int>(n), area, cover});
  return true;
}

void placeSectionBars(const LawRecords& seen, RcSectionData& d) {
  const bool round = d.shape == SectionShapeKind::Circle || d.shape == SectionShapeKind::Annulus;
  for (const RingRecord& ring : seen.rings) {
    const Record& r = *ring.record;
    if (!round)
      failAt(r, 1, "REBAr RING places bars on a circle: it needs SECTion CIRCular or ANNUlar",
             "give the layers: REBAr d1 A1 [d2 A2 ...]");
    const double limit = d.shape == SectionShapeKind::Annulus ? d.wall : d.h / 2;
    if (!(ring.cover < limit))
      failAt(r, 4,
             "the bars' centres at cover " + str(ring.cover) + " lie outside the concrete (" +
                 (d.shape == SectionShapeKind::Annulus ? "wall t = " : "radius D/2 = ") +
                 str(limit) + ")");
    // Bars at angles 2 pi i/n from the top; i and n - i share a depth.
    const double rho = d.h / 2 - ring.cover;
    for (int i = 0; 2 * i <= ring.n; ++i) {
      const int count = i == 0 || 2 * i == ring.n ? 1 : 2;
      d.bars.push_back({d.h / 2 - rho * std::cos(2 * kPi * i / ring.n), count * ring.area});
    }
  }
}

}  // namespace c2d
