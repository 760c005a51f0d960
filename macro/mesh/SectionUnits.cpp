#include "macro/mesh/SectionUnits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "macro/mesh/SubRecordFields.h"

namespace c2d {

namespace {

// The deck's units: kN/m^2, m, m^2.
struct Unit {
  const char* name;
  double inDeck;  // one of it in the deck's unit
};
constexpr Unit kStress[] = {{"MPa", 1e3}, {"Pa", 1e-3}, {"ksi", 6894.757}, {"psi", 6.894757}};
constexpr Unit kLength[] = {{"mm", 1e-3}, {"cm", 1e-2}};
constexpr Unit kArea[] = {{"cm^2", 1e-4}, {"mm^2", 1e-6}};
struct Band {
  double lo, hi;
};
constexpr Band kFc{5e3, 1.5e5}, kBarStress{1e5, 2.5e6}, kModulus{1e8, 3e8};
constexpr double kMaxSize = 30;        // m: no section is so deep
constexpr double kMaxLayer = 0.05;     // m^2: 40 bars of 40 mm
constexpr double kMaxRingBar = 5e-3;   // m^2: one bar of 80 mm
constexpr double kMaxLinkRatio = 0.1;  // Asw/(b s)
constexpr double kInLine = 0.99;       // cosine: elements continuing one member

// 30000 as 30e3, 2e8 as 200e6, 3.14e-4 as 314e-6, 0.005 as 5e-3; others as %g.
std::string num(double v) {
  char buf[48];
  const double a = std::abs(v);
  if (std::isfinite(a) && (a >= 1e4 || (a > 0 && a < 1e-2))) {
    const int e = static_cast<int>(std::floor(std::log10(a) / 3)) * 3;
    std::snprintf(buf, sizeof buf, "%.4ge%d", v / std::pow(10.0, e), e);
  } else {
    std::snprintf(buf, sizeof buf, "%.4g", v);
  }
  return buf;
}

// "MPa? 500 MPa is 500e3 kN/m^2": the first unit that brings v into band.
template <std::size_t N>
std::string guess(double v, const Band& band, const Unit (&units)[N], const char* deckUnit) {
  for (const Unit& u : units)
    if (const double d = v * u.inDeck; d >= band.lo && d <= band.hi)
      return std::string(": ") + u.name + "? " + num(v) + " " + u.name + " is " + num(d) + " " +
             deckUnit;
  return {};
}

void warn(const MeshContext& ctx, const Record& r, std::size_t field, const std::string& msg) {
  if (ctx.warnings)
    ctx.warnings->add(r.fieldLoc(field), msg, r.excerpt(r.fieldLoc(field)), /*unit=*/true);
}

bool given(const Record& r, std::size_t field) {
  return r.size() > field && !r.text(field).empty();
}

// A stress of the record outside its band, at its field.
void checkStress(const MeshContext& ctx, const Record& r, std::size_t field, const char* name,
                 double v, const Band& band, const char* what) {
  if (v >= band.lo && v <= band.hi) return;
  warn(ctx, r, field,
       std::string(name) + " = " + num(v) + " is not " + what + " in the deck's kN/m^2 (" +
           num(band.lo) + "-" + num(band.hi) + ", i.e. " + num(band.lo * 1e-3) + "-" +
           num(band.hi * 1e-3) + " MPa)" + guess(v, band, kStress, "kN/m^2"));
}

// The shape's sizes as its record gives them (fields 2, 3, ...).
std::vector<double> shapeSizes(const RcSectionData& d) {
  switch (d.shape) {
    case SectionShapeKind::Rectangle:
      return {d.b, d.h};
    case SectionShapeKind::Tee:
      return {d.b, d.h, d.flangeWidth, d.flangeDepth};
    case SectionShapeKind::Circle:
      return {d.h};
    case SectionShapeKind::Annulus:
      return {d.h, d.wall};
  }
  return {};
}

void checkSection(const MeshContext& ctx, const Record& r, const RcSectionData& d) {
  const std::vector<double> sizes = shapeSizes(d);
  const std::size_t nd = sizes.size();
  for (std::size_t i = 0; i < nd; ++i)
    if (sizes[i] > kMaxSize)
      warn(ctx, r, 2 + i,
           "the section's size " + num(sizes[i]) + " is not in the deck's m (no section is " +
               num(kMaxSize) + " m deep)" + guess(sizes[i], {0.05, kMaxSize}, kLength, "m"));
  checkStress(ctx, r, 2 + nd, "fc", d.fc, kFc, "a concrete strength");
  checkStress(ctx, r, 3 + nd, "fy", d.fy, kBarStress, "a bar's yield stress");
  if (given(r, 4 + nd)) checkStress(ctx, r, 4 + nd, "Es", d.Es, kModulus, "a bar's modulus");
  if (given(r, 5 + nd)) checkStress(ctx, r, 5 + nd, "fu", d.fu, kBarStress, "a bar's strength");
}

// The REBAr layers are the section's first bars, in the order of their records.
void checkBars(const MeshContext& ctx, const LawRecords& seen, const RcSectionData& d) {
  const std::string hint = " (a 20 mm bar is 314e-6 m^2)";
  std::size_t k = 0;
  for (const Record* r : seen.rebar) {
    const std::size_t first = subrecord::firstNumber(*r);
    for (std::size_t i = first + 1; i < r->size() && k < d.bars.size(); i += 2, ++k)
      if (const double a = d.bars[k].area; a > kMaxLayer)
        warn(ctx, *r, i,
             "a bar layer of " + num(a) + " m^2 is more than " + num(kMaxLayer) +
                 " m^2 (40 bars of 40 mm)" + guess(a, {1e-5, kMaxLayer}, kArea, "m^2") + hint);
  }
  for (const RingRecord& ring : seen.rings)
    if (ring.area > kMaxRingBar)
      warn(ctx, *ring.record, 3,
           "a bar of " + num(ring.area) + " m^2 is more than " + num(kMaxRingBar) +
               " m^2 (a bar of 80 mm)" + guess(ring.area, {1e-5, kMaxRingBar}, kArea, "m^2") +
               hint);
}

void checkStirrups(const MeshContext& ctx, const Record& r, const RcSectionData& d) {
  const std::size_t first = subrecord::firstNumber(r);
  const Stirrups& st = *d.stirrups;
  if (const double ratio = st.area / (d.b * st.spacing); ratio > kMaxLinkRatio)
    warn(ctx, r, first,
         "links of Asw/(b s) = " + num(ratio) + " are more than " + num(kMaxLinkRatio) +
             " of the section (a member has a few per mille)" +
             guess(st.area, {2e-5, kMaxLinkRatio * d.b * st.spacing}, kArea, "m^2"));
  if (st.spacing > d.h)
    warn(ctx, r, first + 1,
         "links at s = " + num(st.spacing) +
             " are farther apart than the section is deep (h = " + num(d.h) +
             "): a 45-degree crack may cross none (EC2 9.2.2(6): s <= 0.75 d in beams; 9.5.3: "
             "20 bar diameters, the smaller side, 0.4 m in columns)" +
             guess(st.spacing, {1e-2, d.h}, kLength, "m"));
  if (given(r, first + 2))
    checkStress(ctx, r, first + 2, "fyw", st.fy, kBarStress, "a link's yield stress");
}

// Union-find root with path halving.
int root(std::vector<int>& parent, int e) {
  while (parent[e] != e) e = parent[e] = parent[parent[e]];
  return e;
}

void warnLonger(const MeshContext& ctx, const Record& r, std::size_t field, const char* name,
                double v, int set, double longest) {
  if (r.blank() || !(v > longest)) return;
  warn(ctx, r, field,
       std::string(name) + " = " + num(v) + " is longer than the longest member of material set " +
           std::to_string(set) + " (" + num(longest) + " m, its elements in line)" +
           guess(v, {0.05, longest}, kLength, "m"));
}

}  // namespace

void warnSectionUnits(MeshContext& ctx, const LawRecords& seen, const MaterialSet& mat) {
  const Record* lb = seen.softening && given(*seen.softening, 6) ? seen.softening : nullptr;
  if (seen.section && mat.section) {
    checkSection(ctx, *seen.section, *mat.section);
    checkBars(ctx, seen, *mat.section);
    if (seen.stirrups && mat.section->stirrups) checkStirrups(ctx, *seen.stirrups, *mat.section);
  } else if (!lb) {
    ctx.lawOrigins.erase(mat.number);  // a set given again without them
    return;
  }
  MeshContext::LawOrigin& o = ctx.lawOrigins[mat.number];
  o.section = seen.section ? *seen.section : Record{};
  o.stirrups = seen.stirrups ? *seen.stirrups : Record{};
  o.softening = lb ? *lb : Record{};
  ctx.meshChecks = warnMemberLengths;
}

std::map<int, double> longestMembers(const Model& model) {
  const auto& elements = model.elements();
  const int ne = static_cast<int>(elements.size());
  std::vector<int> parent(static_cast<std::size_t>(ne));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<double> length(static_cast<std::size_t>(ne), 0.0);
  std::vector<Vec2> axis(static_cast<std::size_t>(ne), Vec2::Zero());
  std::vector<std::vector<int>> atNode(static_cast<std::size_t>(model.numNodes()));
  for (int e = 0; e < ne; ++e) {
    if (!elements[e]) continue;
    const auto n = elements[e]->nodes();
    const Vec2 d = model.coord(n[1]) - model.coord(n[0]);
    length[e] = d.norm();
    if (length[e] > 0) axis[e] = d / length[e];
    for (int k : n) atNode[static_cast<std::size_t>(k)].push_back(e);
  }
  for (const std::vector<int>& es : atNode)
    for (std::size_t i = 0; i < es.size(); ++i)
      for (std::size_t j = i + 1; j < es.size(); ++j) {
        const int a = es[i], b = es[j];
        if (elements[a]->materialNumber() == elements[b]->materialNumber() &&
            std::abs(axis[a].dot(axis[b])) >= kInLine)
          parent[root(parent, a)] = root(parent, b);
      }
  std::vector<double> member(static_cast<std::size_t>(ne), 0.0);
  for (int e = 0; e < ne; ++e)
    if (elements[e]) member[root(parent, e)] += length[e];
  std::map<int, double> longest;
  for (int e = 0; e < ne; ++e)
    if (elements[e]) {
      double& l = longest[elements[e]->materialNumber()];
      l = std::max(l, member[root(parent, e)]);
    }
  return longest;
}

void warnMemberLengths(const MeshContext& ctx) {
  if (!ctx.warnings) return;
  const std::map<int, double> longest = longestMembers(ctx.model);
  for (const auto& [set, origin] : ctx.lawOrigins) {
    const auto it = longest.find(set);
    const MaterialSet* mat = ctx.model.material(set);
    if (it == longest.end() || !mat) continue;  // a set no element uses
    if (const auto& d = mat->section) {
      // The depth: h of RECTangular and TEE (field 3), D of the circles (field 2).
      const bool round =
          d->shape == SectionShapeKind::Circle || d->shape == SectionShapeKind::Annulus;
      warnLonger(ctx, origin.section, round ? 2 : 3, "the section's depth", d->h, set, it->second);
      if (d->stirrups) {
        const Record& r = origin.stirrups;
        const std::size_t first = subrecord::firstNumber(r);
        warnLonger(ctx, r, first + 1, "the link spacing s", d->stirrups->spacing, set, it->second);
      }
    }
    if (!origin.softening.blank())
      if (const auto& soft = mat->softening)
        warnLonger(ctx, origin.softening, 6, "the shortest piece Lb", soft->pieceLength, set,
                   it->second);
  }
}

}  // namespace c2d
