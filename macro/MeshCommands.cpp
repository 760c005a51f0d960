#include "macro/MeshCommands.h"

#include "macro/SectionRecords.h"
#include "macro/SubRecordFields.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <ostream>
#include <set>
#include <sstream>

#include "elements/ElementFactory.h"
#include "elements/Joints.h"
#include "elements/MaterialUpdate.h"
#include "macro/Expression.h"
#include "macro/Limits.h"
#include "macro/BlastCommand.h"
#include "macro/LoadCommands.h"
#include "macro/NumberRanges.h"
#include "macro/MaterialRecords.h"

namespace c2d {

using namespace meshspec;

// ---------------------------------------------------------------------------
// MeshContext helpers

double MeshContext::number(const Record& r, std::size_t i) const {
  if (i >= r.size()) return 0.0;
  return Expression::parse(r[i]).eval(params);
}

int MeshContext::integer(const Record& r, std::size_t i, std::string_view what) const {
  if (i >= r.size()) return 0;
  return Expression::parse(r[i]).evalInt(params, what);
}

void MeshContext::ensureNode(long long n, const Record& r, std::size_t i) {
  if (n < 1)
    throw DeckError(r.fieldLoc(i),
                    "node " + std::to_string(n) + " does not exist (nodes start at 1)",
                    r.excerpt(r.fieldLoc(i)));
  if (maxNodes > 0 && n > maxNodes)
    throw DeckError(r.fieldLoc(i),
                    "node " + std::to_string(n) + " is beyond numnp = " + std::to_string(maxNodes) +
                        " of the control record",
                    r.excerpt(r.fieldLoc(i)), "raise numnp, or set it to 0 to have nodes counted");
  checkNumber(r, i, n, DeckLimits::maxNodes(), "node");
  if (n > model.numNodes()) model.resizeNodes(static_cast<int>(n));
}

int MeshContext::node(const Record& r, std::size_t i, std::string_view what) {
  const int n = integer(r, i, what);
  if (n < 1)
    throw DeckError(r.fieldLoc(i),
                    std::string(what) + " must be positive, got " + std::to_string(n),
                    r.excerpt(r.fieldLoc(i)));
  ensureNode(n, r, i);
  return n;
}

int MeshContext::elementNumber(const Record& r, std::size_t i) {
  const int e = integer(r, i, "element number");
  if (e < 1)
    throw DeckError(r.fieldLoc(i), "element number must be positive, got " + std::to_string(e),
                    r.excerpt(r.fieldLoc(i)));
  if (maxElements > 0 && e > maxElements)
    throw DeckError(
        r.fieldLoc(i),
        "element " + std::to_string(e) + " is beyond numel = " + std::to_string(maxElements) +
            " of the control record",
        r.excerpt(r.fieldLoc(i)), "raise numel, or set it to 0 to have elements counted");
  checkNumber(r, i, e, DeckLimits::maxElements(), "element");
  return e;
}

int MeshContext::materialNumber(const Record& r, std::size_t i) {
  const int m = integer(r, i, "material number");
  if (m < 1)
    throw DeckError(r.fieldLoc(i), "material number must be positive, got " + std::to_string(m),
                    r.excerpt(r.fieldLoc(i)));
  if (maxMaterials > 0 && m > maxMaterials)
    throw DeckError(r.fieldLoc(i),
                    "material " + std::to_string(m) + " is beyond nummat = " +
                        std::to_string(maxMaterials) + " of the control record",
                    r.excerpt(r.fieldLoc(i)), "raise nummat, or set it to 0 to have them counted");
  checkNumber(r, i, m, DeckLimits::kMaxMaterials, "material set");
  return m;
}

void MeshContext::setCoordOrigin(int n, const Record& r) {
  if (static_cast<int>(coordOrigin.size()) < n) coordOrigin.resize(n, nullptr);
  coordOrigin[n - 1] = &r;
}

void MeshContext::maxFields(const Record& r, std::size_t max, std::string_view syntax) const {
  if (r.size() > max)
    throw DeckError(r[max].loc, "too many fields: the record is '" + std::string(syntax) + "'",
                    r.excerpt(r[max].loc));
}

namespace {

// ---------------------------------------------------------------------------
// small helpers

using subrecord::looksNumeric;

std::string restOfLine(const Record& r, std::size_t field) {
  if (field >= r.size() || !r.line) return {};
  const auto p = static_cast<std::size_t>(r[field].loc.col - 1);
  return p < r.line->size() ? r.line->substr(p) : std::string();
}

// Echo tables in FEAP's style: a spaced-out title, then aligned columns.
void title(std::ostream& os, const std::string& t) { os << "\n   " << t << "\n\n"; }

std::ostream& num(std::ostream& os, double v) {
  return os << std::setw(13) << std::scientific << std::setprecision(4) << v;
}

constexpr const char* kDofName[kNodeDofs] = {"u", "v", "theta"};

// Edge and coordinate commands: ADD (add values / set nonzero codes) or SET (replace).
enum class Mode { Add, Set };

Mode readMode(const Record& head, Mode dflt) {
  if (head.size() < 2 || head[1].text.empty()) return dflt;
  if (keywordMatches(head[1].text, "ADD")) return Mode::Add;
  if (keywordMatches(head[1].text, "SET")) return Mode::Set;
  failAt(head, 1, "unknown option '" + head[1].text + "'", "the options are ADD and SET");
}

// ---------------------------------------------------------------------------
// COORdinates: node ng x y. ng on the earlier of two records generates the nodes
// between them (n1, n1+ng, ...) by linear interpolation (FEAP genvec).

void applyCoordinates(MeshContext& ctx, const MeshCommand& cmd) {
  std::set<int> touched;
  int l = 0, lg = 0;
  const Record* prevRec = nullptr;
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 4, "node ng x y");
    const int n = ctx.node(r, 0);
    const int ng = ctx.integer(r, 1, "generation increment");
    const Vec2 x(ctx.number(r, 2), ctx.number(r, 3));
    if (n == l) failAt(r, 0, "node " + std::to_string(n) + " is given on two records in a row");
    const Vec2 xl = l > 0 ? ctx.model.coord(l - 1) : Vec2::Zero();
    ctx.model.setCoord(n - 1, x);
    ctx.setCoordOrigin(n, r);
    touched.insert(n);
    generateBetween(l, lg, n, xl, x, [&](int k, const Vec2& v) {
      ctx.model.setCoord(k - 1, v);
      ctx.setCoordOrigin(k, *prevRec);
      touched.insert(k);
    });
    prevRec = &r;
    ctx.highestNode = std::max({ctx.highestNode, n, l});
    l = n;
    lg = ng;
  }
  ctx.topologyChanged = true;
  if (auto* os = ctx.out()) {
    title(*os, "N o d a l   C o o r d i n a t e s");
    *os << "      node      1 Coord      2 Coord\n";
    for (int k : touched) {
      *os << std::setw(10) << k;
      num(*os, ctx.model.coord(k - 1).x());
      num(*os, ctx.model.coord(k - 1).y()) << "\n";
    }
  }
}

// ---------------------------------------------------------------------------
// ELEMents: elem ng mat n1 n2, in increasing element order. A gap to the next
// record is filled by copying the previous element with its nodes advanced by
// ng (0 counts as 1); the last record generates nothing (FEAP pelmin).

void applyElements(MeshContext& ctx, const MeshCommand& cmd) {
  int lp = 0, lg = 1;
  const Record* prevRec = nullptr;
  MeshContext::PendingElement prev;
  std::vector<int> given;
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 5, "elem ng mat n1 n2");
    const int e = ctx.elementNumber(r, 0);
    const int ng = ctx.integer(r, 1, "generation increment");
    const int mat = ctx.materialNumber(r, 2);
    const int n1 = ctx.node(r, 3), n2 = ctx.node(r, 4);
    if (lp != 0 && e <= lp)
      failAt(r, 0, "element " + std::to_string(e) + " comes after element " + std::to_string(lp),
             "the records of an ELEMents data set go in increasing element order");
    for (int k = lp + 1; lp != 0 && k < e; ++k) {
      MeshContext::PendingElement g = prev;
      for (int a = 0; a < 2; ++a) {
        const long long n = prev.nodes[a] + static_cast<long long>(k - lp) * lg;
        ctx.ensureNode(n, *prevRec, 3 + a);
        g.nodes[a] = static_cast<int>(n);
      }
      g.generated = true;
      ctx.elements[k] = g;
      given.push_back(k);
    }
    prev = {mat, {n1, n2}, &r, false};
    prevRec = &r;
    ctx.elements[e] = prev;
    given.push_back(e);
    lp = e;
    lg = ng == 0 ? 1 : ng;
    ctx.highestElement = std::max(ctx.highestElement, e);
  }
  ctx.topologyChanged = true;
  if (auto* os = ctx.out()) {
    title(*os, "E l e m e n t s");
    *os << "      Elmt  Mat   1 Node   2 Node\n";
    for (int k : given) {
      const auto& p = ctx.elements.at(k);
      *os << std::setw(10) << k << std::setw(5) << p.material << std::setw(9) << p.nodes[0]
          << std::setw(9) << p.nodes[1] << "\n";
    }
  }
}

// ---------------------------------------------------------------------------
// MATErial,m [label]: type record FRAMe, then sub-records until the blank.
// Sub-records take two text fields, then numbers.

void echoMaterial(std::ostream& os, const MaterialSet& m) {
  title(os, "M a t e r i a l   S e t   " + std::to_string(m.number) +
                (m.label.empty() ? "" : "   (" + m.label + ")"));
  os << "      Element type       " << m.elementType << "\n";
  os << "      Kinematics         " << (m.kinematics == Kinematics::Small ? "small" : "finite")
     << "\n";
  os << "      Shear deformation  " << (m.shear ? "on (Timoshenko)" : "off (Euler-Bernoulli)")
     << "\n";
  auto line = [&](const char* name, double v) {
    os << "      " << std::left << std::setw(19) << name << std::right;
    num(os, v) << "\n";
  };
  if (m.resEI) {
    line("EA (resultant)", *m.resEA);
    line("GA (resultant)", *m.resGA);
    line("EI (resultant)", *m.resEI);
  } else {
    line("Modulus E", m.E);
    line("Poisson ratio", m.nu);
  }
  if (m.A > 0 || !m.resEI) {
    line("Area A", m.A);
    line("Inertia I", m.I);
    line("Shear factor", m.kappa);
  }
  line("Density", m.density);
  os << "      Mass               " << (m.mass == MassType::Lumped ? "lumped" : "consistent")
     << "\n";
  if (m.dampingA1 > 0) line("Damping a1 (s)", m.dampingA1);
  echoLaws(os, m);
}

void applyMaterial(MeshContext& ctx, const MeshCommand& cmd) {
  const Record& h = cmd.head;
  const int m = ctx.materialNumber(h, 1);
  MaterialSet mat;
  mat.number = m;
  mat.label = restOfLine(h, 2);

  CommandRegistry subs;
  registerMaterialSubRecords(subs);

  if (cmd.data.empty())
    failAt(h, 0, "MATErial," + std::to_string(m) + " has no element type record",
           "the record after MATErial is the element type, FRAMe");
  const Record& type = cmd.data[0];
  if (!type.is("FRAMe")) {
    const CommandSpec* s = subs.find(type[0].text);
    if (s) failAt(type, 0, "the element type record (FRAMe) must come first in MATErial data");
    std::string hint = subs.suggest(type[0].text);
    failAt(type, 0, "unknown element type '" + type[0].text + "'",
           hint.empty() ? "the element type is FRAMe" : hint);
  }
  ctx.maxFields(type, 1, "FRAMe");
  mat.elementType = "FRAMe";

  const Record *elasticRec = nullptr, *sectionRec = nullptr, *resultantRec = nullptr;
  LawRecords laws;
  const Record* densityRec = nullptr;
  const Record* dampingRec = nullptr;
  const Record* kinematicsRec = nullptr;
  for (std::size_t k = 1; k < cmd.data.size(); ++k) {
    const Record& r = cmd.data[k];
    const CommandSpec* s = subs.find(r[0].text);
    if (!s || s->key() == "fram") {
      if (s) failAt(r, 0, "element type given twice in one MATErial set");
      std::string hint = subs.suggest(r[0].text);
      failAt(r, 0, "unknown material record '" + r[0].text + "'",
             hint.empty() ? "see collapse2d --help for the material records" : hint);
    }
    const std::string key = s->key();
    const std::string text2 = r.text(1);
    auto numericText = [&](const std::string& syntax) { subrecord::requireText(r, s->name, syntax); };
    auto values = [&](std::size_t maxCount, std::size_t required, const std::string& syntax) {
      return subrecord::values(ctx, r, s->name, maxCount, required, syntax);
    };
    auto option = [&](const std::string& syntax, std::initializer_list<const char*> allowed) {
      ctx.maxFields(r, 2, syntax);
      for (const char* a : allowed)
        if (keywordMatches(text2, a)) return std::string(a);
      failAt(r, 1, "unknown option '" + text2 + "' of " + s->name, "write " + syntax);
    };

    if (key == "elas") {
      const std::string syntax = "ELAStic ISOTropic E nu";
      numericText(syntax);
      if (!text2.empty() && !keywordMatches(text2, "ISOTropic"))
        failAt(r, 1, "only isotropic elasticity is available for frames", "write " + syntax);
      const auto v = values(2, 1, syntax);
      if (v[0] <= 0) failAt(r, 2, "modulus E must be positive");
      if (v[1] <= -1 || v[1] >= 0.5) failAt(r, 3, "Poisson ratio must lie in (-1, 0.5)");
      mat.E = v[0];
      mat.nu = v[1];
      elasticRec = &r;
    } else if (key == "cros") {
      // FEAPpv's frame record: A Ixx Iyy Ixy J kappa_1 kappa_2. A plane frame bends
      // about one axis: it uses A, I = Ixx and the shear factor kappa_1 (0: 5/6).
      const std::string syntax = "CROSs SECTion A I [Iyy Ixy J kappa kappa2]";
      numericText("CROSs SECTion A I (or CROSs,,A,I)");
      const auto v = values(7, 2, syntax);
      if (v[0] <= 0) failAt(r, 2, "section area A must be positive");
      if (v[1] <= 0) failAt(r, 3, "section inertia I must be positive");
      if (v[5] < 0) failAt(r, 7, "shear factor must be positive");
      mat.A = v[0];
      mat.I = v[1];
      mat.kappa = v[5] != 0 ? v[5] : 5.0 / 6.0;
      sectionRec = &r;
    } else if (key == "shea") {
      if (text2.empty()) {
        mat.shear = true;
      } else {
        mat.shear = option("SHEAr ON / SHEAr OFF", {"ON", "OFF"}) == "ON";
      }
    } else if (key == "smal" || key == "fini") {
      ctx.maxFields(r, 1, s->name);
      mat.kinematics = key == "smal" ? Kinematics::Small : Kinematics::Finite;
      kinematicsRec = &r;
    } else if (key == "dens") {
      const std::string syntax = "DENSity,,rho";
      numericText(syntax);
      if (!text2.empty()) failAt(r, 1, "DENSity takes no option", "write " + syntax);
      const auto v = values(2, 1, syntax);
      if (v[0] < 0) failAt(r, 2, "density must not be negative");
      if (v[1] != 0 && v[1] != 1)
        failAt(r, 3, "a rotary inertia factor other than 1 is not available");
      mat.density = v[0];
      densityRec = &r;
    } else if (key == "damp") {
      mat.dampingA1 = readDamping(ctx, r);
      dampingRec = &r;
    } else if (key == "mass") {
      mat.mass = option("MASS LUMPed / MASS CONSistent", {"LUMPed", "CONSistent"}) == "LUMPed"
                     ? MassType::Lumped
                     : MassType::Consistent;
    } else if (key == "resu") {
      const std::string syntax = "RESUltant STIFfness EA GA EI";
      numericText(syntax);
      if (!keywordMatches(text2, "STIFfness"))
        failAt(r, 1, "expected STIFfness", "write " + syntax);
      const auto v = values(3, 3, syntax);
      if (v[0] <= 0) failAt(r, 2, "EA must be positive");
      if (v[1] < 0) failAt(r, 3, "GA must not be negative");
      if (v[2] <= 0) failAt(r, 4, "EI must be positive");
      mat.resEA = v[0];
      mat.resGA = v[1];
      mat.resEI = v[2];
      resultantRec = &r;
    } else {
      bindLawRecord(ctx, r, *s, mat, laws);
    }
  }

  finishLawRecords(h, laws, mat, elasticRec, sectionRec, resultantRec);
  if (dampingRec && mat.dampingA1 > 0 && mat.capacity)
    failAt(*dampingRec, 0,
           "DAMPing is not available for members whose laws follow the axial force (SECTion, "
           "INTEraction)",
           "leave DAMPing out of this material");
  if (!mat.resEI) {
    if (!elasticRec)
      failAt(h, 0, "material " + std::to_string(m) + " has no ELAStic record",
             "give ELAStic ISOTropic E nu and CROSs SECTion A I, or RESUltant STIFfness EA GA EI");
    if (!sectionRec)
      failAt(h, 0, "material " + std::to_string(m) + " has no CROSs record",
             "give CROSs SECTion A I");
  } else if (mat.shear && *mat.resGA <= 0) {
    failAt(h, 0, "material " + std::to_string(m) + " has GA = 0 with shear deformation on",
           "give GA, or SHEAr OFF for Euler-Bernoulli");
  }
  if (densityRec && mat.density > 0 && mat.A <= 0)
    failAt(*densityRec, 2, "DENSity needs the section area: give CROSs SECTion A I too");

  if (auto* os = ctx.out()) echoMaterial(*os, mat);
  if (const MaterialSet* before = ctx.model.material(m)) {
    if (before->section || mat.section)
      failAt(h, 0, "material " + std::to_string(m) + " has or gets a SECTion: it cannot be given again",
             "an RC member's history belongs to its section");
    auto [it, added] = ctx.changedMaterials.try_emplace(m);
    if (added) it->second.before = before->kinematics;  // as the existing elements have it
    it->second.head = h;
    it->second.kinematics = kinematicsRec ? *kinematicsRec : Record{};
  }
  ctx.model.materials()[m] = mat;
}

// ---------------------------------------------------------------------------
// BOUNdary: node ng c1 c2 c3 (nonzero: restrained). FEAP pbouin: a record's codes
// replace the node's; a negative code propagates: to the nodes generated from
// the earlier record (increment ng) and to a zero code of the next record's node.

void applyBoundary(MeshContext& ctx, const MeshCommand& cmd) {
  std::set<int> touched;
  int l = 0, lg = 0;
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 2 + kNodeDofs, "node ng c1 c2 c3");
    const int n = ctx.node(r, 0);
    const int ng = ctx.integer(r, 1, "generation increment");
    std::array<int, kNodeDofs> c{};
    for (int i = 0; i < kNodeDofs; ++i) c[i] = ctx.integer(r, 2 + i, "boundary code");
    if (l != 0)
      for (int i = 0; i < kNodeDofs; ++i)
        if (c[i] == 0 && ctx.model.bound(l - 1)[i] < 0) c[i] = -1;
    ctx.model.bound(n - 1) = c;
    touched.insert(n);
    int prev = l;
    for (int k : generatedBetween(l, n, lg)) {
      for (int i = 0; i < kNodeDofs; ++i)
        if (ctx.model.bound(prev - 1)[i] < 0) ctx.model.bound(k - 1)[i] = -1;
      touched.insert(k);
      prev = k;
    }
    ctx.referencedNodes.emplace(n, r);
    l = n;
    lg = ng;
  }
  ctx.topologyChanged = true;
  if (auto* os = ctx.out()) {
    title(*os, "N o d a l   B. C.");
    *os << "      Node  1-b.c.  2-b.c.  3-b.c.\n";
    for (int k : touched) {
      *os << std::setw(10) << k;
      for (int i = 0; i < kNodeDofs; ++i) *os << std::setw(8) << ctx.model.bound(k - 1)[i];
      *os << "\n";
    }
  }
}

// FPROportional: node ng p1 p2 p3, the proportional load table of each dof's
// FORCe/DISPlacement value (FEAP; 0 or absent: table 1). Generation copies the
// earlier record's numbers to the nodes between (increment ng).

void applyLoadTables(MeshContext& ctx, const MeshCommand& cmd) {
  int l = 0, lg = 0;
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 2 + kNodeDofs, "node ng p1 p2 p3");
    const int n = ctx.node(r, 0);
    const int ng = ctx.integer(r, 1, "generation increment");
    std::array<int, kNodeDofs> p{};
    for (int i = 0; i < kNodeDofs; ++i) {
      p[i] = ctx.integer(r, 2 + i, "proportional load table");
      if (p[i] < 0) failAt(r, 2 + i, "a proportional load table number is 0 or positive");
      if (p[i] > 0)
        checkNumber(r, 2 + i, p[i], DeckLimits::kMaxLoadTables, "proportional load table");
      if (p[i] > 1) ctx.tableRefs.emplace(p[i], std::make_pair(r, 2 + i));
    }
    for (int k : generatedBetween(l, n, lg))
      ctx.model.loadTable(k - 1) = ctx.model.loadTable(l - 1);
    ctx.model.loadTable(n - 1) = p;
    ctx.referencedNodes.emplace(n, r);
    l = n;
    lg = ng;
  }
}

// ---------------------------------------------------------------------------
// FORCe / DISPlacement: node ng v1 v2 v3, generation by linear interpolation
// between records (FEAP genvec, as for coordinates).

using NodalArray = std::array<double, kNodeDofs>& (Model::*)(int);

void applyNodalValues(MeshContext& ctx, const MeshCommand& cmd, NodalArray array,
                      const char* what) {
  using V3 = Eigen::Matrix<double, kNodeDofs, 1>;
  std::set<int> touched;
  int l = 0, lg = 0;
  auto get = [&](int n) -> std::array<double, kNodeDofs>& { return (ctx.model.*array)(n - 1); };
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 2 + kNodeDofs, "node ng v1 v2 v3");
    const int n = ctx.node(r, 0);
    const int ng = ctx.integer(r, 1, "generation increment");
    V3 v;
    for (int i = 0; i < kNodeDofs; ++i) v[i] = ctx.number(r, 2 + i);
    if (n == l) failAt(r, 0, "node " + std::to_string(n) + " is given on two records in a row");
    V3 vl = V3::Zero();
    if (l > 0)
      for (int i = 0; i < kNodeDofs; ++i) vl[i] = get(l)[i];
    for (int i = 0; i < kNodeDofs; ++i) get(n)[i] = v[i];
    touched.insert(n);
    generateBetween(l, lg, n, vl, v, [&](int k, const V3& x) {
      for (int i = 0; i < kNodeDofs; ++i) get(k)[i] = x[i];
      touched.insert(k);
    });
    ctx.referencedNodes.emplace(n, r);
    l = n;
    lg = ng;
  }
  if (auto* os = ctx.out()) {
    title(*os, std::string("N o d a l   ") + what);
    *os << "      Node";
    for (const char* d : kDofName) *os << std::setw(13) << d;
    *os << "\n";
    for (int k : touched) {
      *os << std::setw(10) << k;
      for (int i = 0; i < kNodeDofs; ++i) num(*os, get(k)[i]);
      *os << "\n";
    }
  }
}

void applyForces(MeshContext& ctx, const MeshCommand& cmd) {
  applyNodalValues(ctx, cmd, static_cast<NodalArray>(&Model::force), "F o r c e s");
}

void applyDisplacements(MeshContext& ctx, const MeshCommand& cmd) {
  applyNodalValues(ctx, cmd, static_cast<NodalArray>(&Model::disp), "D i s p l a c e m e n t s");
}

// ---------------------------------------------------------------------------
// Edge (E...) and coordinate (C...) commands: evaluated now, applied once the
// mesh is complete (as FEAP does), in deck order.

enum class Target { Bound, Force, Disp };

void applyValues(MeshContext& ctx, int node, Target t, Mode mode, const std::array<double, 3>& v) {
  if (t == Target::Bound) {
    auto& b = ctx.model.bound(node);
    for (int i = 0; i < kNodeDofs; ++i) {
      const int c = static_cast<int>(v[i]);
      if (mode == Mode::Set || c != 0) b[i] = c;
    }
    ctx.topologyChanged = true;
  } else {
    auto& a = t == Target::Force ? ctx.model.force(node) : ctx.model.disp(node);
    for (int i = 0; i < kNodeDofs; ++i) a[i] = mode == Mode::Set ? v[i] : a[i] + v[i];
  }
}

std::array<double, 3> readValues(MeshContext& ctx, const Record& r, std::size_t first, Target t) {
  std::array<double, 3> v{};
  for (int i = 0; i < kNodeDofs; ++i)
    v[i] =
        t == Target::Bound ? ctx.integer(r, first + i, "boundary code") : ctx.number(r, first + i);
  return v;
}

// One line per node set by an edge or coordinate command: the values it now has.
void echoNode(MeshContext& ctx, const std::string& cmd, Target t, int node) {
  if (auto* os = ctx.out()) {
    *os << "      " << std::left << std::setw(14) << cmd << std::right << std::setw(8) << node + 1;
    if (t == Target::Bound) {
      for (int i = 0; i < kNodeDofs; ++i) *os << std::setw(8) << ctx.model.bound(node)[i];
    } else {
      const auto& a = t == Target::Force ? ctx.model.force(node) : ctx.model.disp(node);
      for (int i = 0; i < kNodeDofs; ++i) num(*os, a[i]);
    }
    *os << "\n";
  }
}

void edgeCommand(MeshContext& ctx, const MeshCommand& cmd, Target t) {
  const Mode mode = readMode(cmd.head, Mode::Add);
  const std::string name = cmd.head[0].text;
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 2 + kNodeDofs, "idir x v1 v2 v3");
    const int dir = std::abs(ctx.integer(r, 0, "direction"));
    if (dir < 1 || dir > 2) failAt(r, 0, "direction must be 1 (x) or 2 (y)");
    const double x0 = ctx.number(r, 1);
    const auto v = readValues(ctx, r, 2, t);
    ctx.deferred.push_back([=](MeshContext& c) {
      const double tol = 1e-3 * c.model.characteristicLength();
      int found = 0;
      for (int k = 0; k < c.model.numNodes(); ++k) {
        if (!c.model.hasCoord(k) || std::fabs(c.model.coord(k)[dir - 1] - x0) > tol) continue;
        applyValues(c, k, t, mode, v);
        echoNode(c, name, t, k);
        ++found;
      }
      if (found == 0) {
        std::ostringstream s;
        s << "no node has coordinate " << dir << " equal to " << x0 << " (tolerance " << tol << ")";
        failAt(r, 1, s.str());
      }
    });
  }
}

void pointCommand(MeshContext& ctx, const MeshCommand& cmd, Target t) {
  const Mode mode = readMode(cmd.head, Mode::Set);
  const std::string name = cmd.head[0].text;
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 3 + kNodeDofs, "NODE x y v1 v2 v3");
    if (!r.is("NODE"))
      failAt(r, 0, "expected NODE", "the record is 'NODE x y v1 v2 v3': the node nearest (x, y)");
    const Vec2 p(ctx.number(r, 1), ctx.number(r, 2));
    const auto v = readValues(ctx, r, 3, t);
    ctx.deferred.push_back([=](MeshContext& c) {
      int best = -1;
      double bestDist = std::numeric_limits<double>::infinity();
      for (int k = 0; k < c.model.numNodes(); ++k) {
        if (!c.model.hasCoord(k)) continue;
        const double d = (c.model.coord(k) - p).norm();
        if (d < bestDist) {
          bestDist = d;
          best = k;
        }
      }
      if (best < 0) failAt(r, 0, "no node has coordinates yet");
      applyValues(c, best, t, mode, v);
      echoNode(c, name, t, best);
    });
  }
}

void applyEbou(MeshContext& c, const MeshCommand& m) { edgeCommand(c, m, Target::Bound); }
void applyEfor(MeshContext& c, const MeshCommand& m) { edgeCommand(c, m, Target::Force); }
void applyEdis(MeshContext& c, const MeshCommand& m) { edgeCommand(c, m, Target::Disp); }
void applyCbou(MeshContext& c, const MeshCommand& m) { pointCommand(c, m, Target::Bound); }
void applyCfor(MeshContext& c, const MeshCommand& m) { pointCommand(c, m, Target::Force); }
void applyCdis(MeshContext& c, const MeshCommand& m) { pointCommand(c, m, Target::Disp); }

// ---------------------------------------------------------------------------
// BLOCk: CARTesian nr ns ni ne ma [nodinc ntyp], then the two master nodes
// "1 x1 y1" and "2 x2 y2": nr two-node elements on the straight line, nodes
// ni..ni+nr, elements ne..ne+nr-1 of material ma. As in FEAP, ni = 0 continues
// after the highest node given so far, ne = 0 after the highest element, ma = 0
// repeats the previous block's material.

void applyBlock(MeshContext& ctx, const MeshCommand& cmd) {
  if (cmd.data.empty())
    failAt(cmd.head, 0, "BLOCk has no data",
           "the records are 'CARTesian n 0 node1 elem1 mat', then '1 x y', '2 x y'");
  const Record& t = cmd.data[0];
  if (!t.is("CARTesian")) {
    if (looksNumeric(t.text(0)))
      failAt(t, 0, "the first BLOCk record is 'CARTesian n 0 node1 elem1 mat'");
    failAt(t, 0, "only CARTesian blocks are available, not '" + t.text(0) + "'");
  }
  ctx.maxFields(t, 8, "CARTesian nr ns ni ne ma nodinc ntyp");
  const int nr = ctx.integer(t, 1, "number of elements");
  if (nr < 1) failAt(t, 1, "a block needs at least one element, got " + std::to_string(nr));
  const int ns = ctx.integer(t, 2, "second direction count");
  int ni = ctx.integer(t, 3, "first node number");
  int ne = ctx.integer(t, 4, "first element number");
  int ma = ctx.integer(t, 5, "material number");
  const int ntyp = ctx.integer(t, 7, "block type");
  if (ns > 1) failAt(t, 2, "only a line of two-node elements is available (ns = 0)");
  if (ntyp != 0) failAt(t, 7, "only block type 0 is available");
  if (ni < 0 || ne < 0 || ma < 0)
    failAt(t, ni < 0 ? 3 : ne < 0 ? 4 : 5, "numbers must not be negative");
  if (ni == 0) ni = ctx.highestNode + 1;
  if (ne == 0) ne = ctx.highestElement + 1;
  // In 64 bits: the block's last node and element must be numbers this program takes.
  checkNumber(t, 1, static_cast<long long>(ni) + nr, DeckLimits::maxNodes(),
              "the block's last node", "first node + number of elements");
  checkNumber(t, 1, static_cast<long long>(ne) + nr - 1, DeckLimits::maxElements(),
              "the block's last element", "first element + number of elements - 1");
  checkNumber(t, 5, std::max(ma, 1), DeckLimits::kMaxMaterials, "material set");
  if (ma == 0) ma = std::max(1, ctx.lastBlockMaterial);
  if (ctx.maxMaterials > 0 && ma > ctx.maxMaterials)
    failAt(t, 5,
           "material " + std::to_string(ma) +
               " is beyond nummat = " + std::to_string(ctx.maxMaterials));

  std::array<Vec2, 2> master;
  std::array<bool, 2> given{false, false};
  for (std::size_t k = 1; k < cmd.data.size(); ++k) {
    const Record& r = cmd.data[k];
    ctx.maxFields(r, 3, "i x y");
    const int i = ctx.integer(r, 0, "master node number");
    if (i < 1 || i > 2) failAt(r, 0, "a line block has master nodes 1 and 2 only");
    if (given[i - 1]) failAt(r, 0, "master node " + std::to_string(i) + " given twice");
    master[i - 1] = Vec2(ctx.number(r, 1), ctx.number(r, 2));
    given[i - 1] = true;
  }
  if (!given[0] || !given[1]) failAt(cmd.data.back(), 0, "BLOCk needs master nodes 1 and 2");

  const int lastNode = ni + nr, lastElem = ne + nr - 1;
  if (ctx.maxNodes > 0 && lastNode > ctx.maxNodes)
    failAt(t, 3,
           "the block's last node " + std::to_string(lastNode) +
               " is beyond numnp = " + std::to_string(ctx.maxNodes));
  if (ctx.maxElements > 0 && lastElem > ctx.maxElements)
    failAt(t, 4,
           "the block's last element " + std::to_string(lastElem) +
               " is beyond numel = " + std::to_string(ctx.maxElements));
  ctx.ensureNode(lastNode, t, 3);
  for (int i = 0; i <= nr; ++i) {
    ctx.model.setCoord(ni + i - 1,
                       master[0] + (master[1] - master[0]) * (static_cast<double>(i) / nr));
    ctx.setCoordOrigin(ni + i, t);
  }
  for (int e = 0; e < nr; ++e) ctx.elements[ne + e] = {ma, {ni + e, ni + e + 1}, &t, true};

  ctx.highestNode = std::max(ctx.highestNode, lastNode);
  ctx.highestElement = std::max(ctx.highestElement, lastElem);
  ctx.lastBlockMaterial = ma;
  ctx.topologyChanged = true;
  if (auto* os = ctx.out()) {
    title(*os, "B l o c k");
    *os << "      Nodes " << ni << " to " << lastNode << ", elements " << ne << " to " << lastElem
        << ", material " << ma << "\n";
    for (int i = 0; i <= nr; ++i) {
      *os << std::setw(10) << ni + i;
      num(*os, ctx.model.coord(ni + i - 1).x());
      num(*os, ctx.model.coord(ni + i - 1).y()) << "\n";
    }
  }
}

// ---------------------------------------------------------------------------
// JOINt, CONTact, GRAVity, PRINt, NOPRint

void applyJoints(MeshContext& ctx, const MeshCommand& cmd) {
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 2, "master slave");
    const int m = ctx.node(r, 0, "master node");
    const int s = ctx.node(r, 1, "slave node");
    if (m == s) failAt(r, 1, "a joint needs two different nodes");
    ctx.joints.push_back({m, s, r});
  }
  ctx.topologyChanged = true;
}

void applyContact(MeshContext& ctx, const MeshCommand& cmd) {
  const Record* previous = nullptr;
  const Record* previousMembers = nullptr;
  // An optional non-negative number at field i (absent or empty: dflt).
  auto optional = [&](const Record& r, std::size_t i, double dflt, const char* what,
                      const char* hint) {
    if (r.size() <= i || r[i].text.empty()) return dflt;
    const double v = ctx.number(r, i);
    if (v < 0) failAt(r, i, std::string(what) + " must not be negative", hint);
    return v;
  };
  // The restitution e at field i: in (0, 1], absent or empty 1.
  auto restitution = [&](const Record& r, std::size_t i) {
    const double e = r.size() > i && !r[i].text.empty() ? ctx.number(r, i) : 1.0;
    if (!(e > 0 && e <= 1))
      failAt(r, i, "the restitution e must lie in (0, 1]", "1 or absent: an elastic impact");
    return e;
  };
  for (const Record& r : cmd.data) {
    if (r.is("MEMBers")) {
      if (previousMembers)
        failAt(r, 0,
               "a second MEMBers record (the first is on line " +
                   std::to_string(previousMembers->loc.line) + ")");
      ctx.maxFields(r, 7, "MEMBers,,k[,zeta[,r[,mu[,e]]]]");
      if (!r.text(1).empty())
        failAt(r, 1, "MEMBers takes no option word (its second field is empty)",
               "write MEMBers,,k[,zeta[,r[,mu[,e]]]]");
      MemberContactData c;
      c.k = ctx.number(r, 2);
      if (c.k < 0) failAt(r, 2, "penalty stiffness k must not be negative", "0: no member contact");
      c.zeta = optional(r, 3, 0.0, "the damping ratio zeta", "0 or absent: no dashpot");
      c.radius = optional(r, 4, -1.0, "the contact radius r", "leave it out for the default");
      c.mu = optional(r, 5, 0.0, "the friction coefficient mu", "0 or absent: frictionless");
      c.restitution = restitution(r, 6);
      previousMembers = &r;
      ctx.membersOrigin = r;
      ctx.topologyChanged = true;  // contact pairs enter or leave the sparsity pattern
      if (c.k == 0) {  // a study's switch: no member contact
        ctx.model.memberContact().reset();
        if (auto* os = ctx.out()) {
          title(*os, "M e m b e r   C o n t a c t");
          *os << "      off (k = 0"
              << (r.size() > 3 ? ": the record's other values are not used" : "") << ")\n";
        }
        continue;
      }
      ctx.model.memberContact() = c;
      if (auto* os = ctx.out()) {
        title(*os, "M e m b e r   C o n t a c t");
        *os << "      k ";
        num(*os, c.k);
        if (c.zeta > 0) num(*os << "   zeta ", c.zeta);
        *os << "   r ";
        if (c.radius < 0)
          *os << "(sections; 1e-3 of the shortest element without)";
        else
          num(*os, c.radius);
        if (c.mu > 0) num(*os << "   mu ", c.mu);
        if (c.restitution < 1) num(*os << "   e ", c.restitution);
        *os << "\n";
      }
      continue;
    }
    if (!r.is("GROUnd")) {
      std::string hint =
          "the records are 'GROUnd,,y0,k[,zeta[,mu[,e]]]' and 'MEMBers,,k[,zeta[,r[,mu[,e]]]]'";
      failAt(r, 0, "unknown contact type '" + r.text(0) + "'", hint);
    }
    // One ground per mesh input, in one CONTact command or several (a MESH
    // re-entry may give a new one).
    if (!ctx.groundOrigin.blank())
      failAt(r, 0,
             "a second GROUnd record (the first is on line " +
                 std::to_string(ctx.groundOrigin.loc.line) + ")");
    ctx.maxFields(r, 7, "GROUnd,,y0,k[,zeta[,mu[,e]]]");
    if (!r.text(1).empty())
      failAt(r, 1, "GROUnd takes no option word (its second field is empty)",
             "write GROUnd,,y0,k[,zeta[,mu[,e]]]");
    Ground g;
    g.y0 = ctx.number(r, 2);
    g.k = ctx.number(r, 3);
    if (g.k <= 0) failAt(r, 3, "penalty stiffness k must be positive");
    g.zeta = optional(r, 4, 0.0, "the damping ratio zeta", "0 or absent: no dashpot");
    g.mu = optional(r, 5, 0.0, "the friction coefficient mu", "0 or absent: frictionless");
    g.restitution = restitution(r, 6);
    ctx.model.ground() = g;
    ctx.groundOrigin = r;
    previous = &r;
    if (auto* os = ctx.out()) {
      title(*os, "G r o u n d   C o n t a c t");
      *os << "      y0 ";
      num(*os, g.y0) << "   k ";
      num(*os, g.k);
      if (g.zeta > 0) num(*os << "   zeta ", g.zeta);
      if (g.mu > 0) num(*os << "   mu ", g.mu);
      if (g.restitution < 1) num(*os << "   e ", g.restitution);
      *os << "\n";
    }
  }
  if (!previous && !previousMembers)
    failAt(cmd.head, 0, "CONTact has no GROUnd or MEMBers record", "write GROUnd,,y0,k");
}

void applyGravity(MeshContext& ctx, const MeshCommand& cmd) {
  const Record& h = cmd.head;
  ctx.maxFields(h, 4, "GRAVity,,gx,gy");
  if (!h.text(1).empty())
    failAt(h, 1, "GRAVity takes no option word (its second field is empty)",
           "write GRAVity,,gx,gy");
  ctx.model.gravity() = Vec2(ctx.number(h, 2), ctx.number(h, 3));
  ctx.gravityOrigin = h;
  if (auto* os = ctx.out()) {
    title(*os, "G r a v i t y");
    *os << "      gx ";
    num(*os, ctx.model.gravity().x()) << "   gy ";
    num(*os, ctx.model.gravity().y()) << "\n";
  }
}

// ---------------------------------------------------------------------------
// SHIFt and POLAr (FEAP polar.f): POLAr converts nodes whose COORdinates hold
// (r, theta in degrees) to x = x0 + r cos(theta) + dx, y = y0 + r sin(theta) +
// dy about the SHIFt origin (x0, y0), now. Records 'NODE n1 n2 inc [dx dy]'
// (n2 = 0: n1 alone; both ends are converted whatever inc) or 'ALL' (every node
// with coordinates); a node is converted once.

void applyShift(MeshContext& ctx, const MeshCommand& cmd) {
  const bool inlineValues = cmd.data.empty();
  const Record& r = inlineValues ? cmd.head : cmd.data.front();
  const std::size_t first = inlineValues ? 1 : 0;
  ctx.maxFields(r, first + 3, inlineValues ? "SHIFt,x0,y0" : "x0 y0");
  ctx.polarOrigin = Vec2(ctx.number(r, first), ctx.number(r, first + 1));
  if (auto* os = ctx.out()) {
    title(*os, "P o l a r   O r i g i n");
    *os << "      x0 ";
    num(*os, ctx.polarOrigin.x()) << "   y0 ";
    num(*os, ctx.polarOrigin.y()) << "\n";
  }
}

void applyPolar(MeshContext& ctx, const MeshCommand& cmd) {
  std::vector<int> converted;
  const double deg = std::atan(1.0) / 45.0;
  for (const Record& r : cmd.data) {
    std::vector<int> nodes;
    Vec2 shift = Vec2::Zero();
    if (r.is("ALL")) {
      ctx.maxFields(r, 1, "ALL");
      for (int n = 1; n <= ctx.model.numNodes(); ++n)
        if (ctx.model.hasCoord(n - 1) && !ctx.polarConverted.count(n)) nodes.push_back(n);
    } else if (r.is("NODEs")) {
      ctx.maxFields(r, 6, "NODE n1 n2 inc dx dy");
      const int n1 = ctx.node(r, 1, "first node");
      // FEAP: n2 = 0 (or empty) converts n1 alone.
      const int n2 = ctx.integer(r, 2, "last node") == 0 ? n1 : ctx.node(r, 2, "last node");
      const long long inc =
          std::max(1LL, std::llabs(static_cast<long long>(ctx.integer(r, 3, "node increment")))) *
          (n2 >= n1 ? 1 : -1);
      for (long long n = n1; inc > 0 ? n <= n2 : n >= n2; n += inc)
        nodes.push_back(static_cast<int>(n));
      if (nodes.back() != n2) nodes.push_back(n2);
      shift = Vec2(ctx.number(r, 4), ctx.number(r, 5));
      for (int n : nodes) {
        if (!ctx.model.hasCoord(n - 1))
          failAt(r, 1, "POLAr: node " + std::to_string(n) + " has no coordinates yet");
        if (const auto it = ctx.polarConverted.find(n); it != ctx.polarConverted.end())
          failAt(r, 1,
                 "POLAr: node " + std::to_string(n) + " was converted already (line " +
                     std::to_string(it->second) + ")");
      }
    } else {
      failAt(r, 0, "unknown POLAr record '" + r.text(0) + "'",
             "the records are 'NODE n1 n2 inc [dx dy]' or 'ALL'");
    }
    for (int n : nodes) {
      const Vec2 p = ctx.model.coord(n - 1);  // (r, theta in degrees)
      ctx.model.setCoord(
          n - 1, ctx.polarOrigin +
                     Vec2(p.x() * std::cos(p.y() * deg), p.x() * std::sin(p.y() * deg)) + shift);
      ctx.polarConverted.emplace(n, r.loc.line);
      converted.push_back(n);
    }
  }
  ctx.topologyChanged = true;
  if (auto* os = ctx.out()) {
    title(*os, "C a r t e s i a n   C o o r d i n a t e s   f r o m   P o l a r");
    *os << "      node      1 Coord      2 Coord\n";
    for (int k : converted) {
      *os << std::setw(10) << k;
      num(*os, ctx.model.coord(k - 1).x());
      num(*os, ctx.model.coord(k - 1).y()) << "\n";
    }
  }
}

void applyPrint(MeshContext& ctx, const MeshCommand&) { ctx.print = true; }
void applyNoPrint(MeshContext& ctx, const MeshCommand&) { ctx.print = false; }

// ---------------------------------------------------------------------------
// specs

std::vector<FieldSpec> nodeValueFields(const std::string& what) {
  return {expr("node", "node number"), expr("ng", "generation increment to the next record", "0"),
          expr(what + "1", "x direction"), expr(what + "2", "y direction"),
          expr(what + "3", "rotation")};
}

}  // namespace

std::vector<MeshCommandEntry> meshCommandTable() {
  const std::vector<FieldSpec> mode{
      text("mode", "ADD (add values, set nonzero codes) or SET (replace)")};
  const std::string edgeDoc =
      " at every node whose coordinate idir equals x (within 1e-3 of the mesh size); applied when "
      "the mesh is complete";
  const std::string pointDoc =
      " at the node nearest the point (x, y); applied when the mesh is complete";
  auto edgeFields = [](const std::string& v) {
    return std::vector<FieldSpec>{expr("idir", "1: x coordinate, 2: y coordinate"),
                                  expr("x", "coordinate value"), expr(v + "1", "x direction"),
                                  expr(v + "2", "y direction"), expr(v + "3", "rotation")};
  };
  auto pointFields = [](const std::string& v) {
    return std::vector<FieldSpec>{text("NODE", "the word NODE"), expr("x", "point x"),
                                  expr("y", "point y"),          expr(v + "1", "x direction"),
                                  expr(v + "2", "y direction"),  expr(v + "3", "rotation")};
  };

  std::vector<MeshCommandEntry> t;
  t.push_back({meshSpec("COORdinates",
                        "Nodal coordinates. ng on the earlier of two records generates the nodes "
                        "n1+ng, n1+2ng, ... before n2 by linear interpolation.",
                        {}, "node ng x y",
                        {expr("node", "node number"),
                         expr("ng", "generation increment to the next record", "0"),
                         expr("x", "x coordinate"), expr("y", "y coordinate")}),
               applyCoordinates});
  t.push_back({meshSpec("ELEMents",
                        "Element connectivity, in increasing element order. A gap to the next "
                        "record is filled by copying this element with its nodes advanced by ng "
                        "(0 counts as 1). Elements are built when the mesh is complete.",
                        {}, "elem ng mat n1 n2",
                        {expr("elem", "element number"),
                         expr("ng", "node increment of generated elements", "1"),
                         expr("mat", "material set number"), expr("n1", "first node"),
                         expr("n2", "second node")}),
               applyElements});
  t.push_back({meshSpec("MATErial",
                        "Material set m: the element type record (FRAMe), then material records "
                        "(see Material records) up to the blank record. Given again in a MESH "
                        "re-entry, the set's elements take the new data from the next step: their "
                        "section forces at the converged state and their history (plastic "
                        "curvature, hinge, initial strain, joint rotations) are kept and the new "
                        "stiffness acts on the increments; stiffness, SHEAr, density, MASS, "
                        "DAMPing, HARDening and SOFTening may change. Refused: SMALl <-> FINIte "
                        "(use HINGe2joint), HARDening/SOFTening for elastic SMALl elements, "
                        "removing the SOFTening of an active hinge, a Mu or yield moment below "
                        "the element's moment, capacity given back to a failed hinge.",
                        {expr("m", "material set number"), text("label", "free text")},
                        "FRAMe, then material records", {}),
               applyMaterial});
  t.push_back({meshSpec("BOUNdary",
                        "Restraint codes: nonzero restrains the dof. A record's codes replace the "
                        "node's; a negative code is carried to the nodes generated with increment "
                        "ng and to a zero code of the next record's node (FEAP).",
                        {}, "node ng c1 c2 c3", nodeValueFields("c")),
               applyBoundary});
  t.push_back({meshSpec("FORCe",
                        "Nodal loads on free dofs, scaled by the proportional load. Generation "
                        "interpolates linearly between records.",
                        {}, "node ng f1 f2 f3", nodeValueFields("f")),
               applyForces});
  t.push_back({meshSpec("DISPlacement",
                        "Prescribed values of restrained dofs, scaled by the proportional load. "
                        "Generation interpolates linearly between records.",
                        {}, "node ng d1 d2 d3", nodeValueFields("d")),
               applyDisplacements});
  t.push_back({meshSpec("FPROportional",
                        "Proportional load table of each dof's FORCe or DISPlacement value "
                        "(PROP,,n defines table n; 0: table 1). Generation copies the earlier "
                        "record's numbers to the nodes generated with increment ng.",
                        {}, "node ng p1 p2 p3", nodeValueFields("p")),
               applyLoadTables});
  t.push_back({meshSpec("EBOUndary", "Restraint codes" + edgeDoc + ". Default mode ADD.", mode,
                        "idir x c1 c2 c3", edgeFields("c")),
               applyEbou});
  t.push_back({meshSpec("EFORce", "Nodal loads" + edgeDoc + ". Default mode ADD.", mode,
                        "idir x f1 f2 f3", edgeFields("f")),
               applyEfor});
  t.push_back({meshSpec("EDISplacement", "Prescribed values" + edgeDoc + ". Default mode ADD.",
                        mode, "idir x d1 d2 d3", edgeFields("d")),
               applyEdis});
  t.push_back({meshSpec("CBOUndary", "Restraint codes" + pointDoc + ". Default mode SET.", mode,
                        "NODE x y c1 c2 c3", pointFields("c")),
               applyCbou});
  t.push_back({meshSpec("CFORce", "Nodal loads" + pointDoc + ". Default mode SET.", mode,
                        "NODE x y f1 f2 f3", pointFields("f")),
               applyCfor});
  t.push_back({meshSpec("CDISplacement", "Prescribed values" + pointDoc + ". Default mode SET.",
                        mode, "NODE x y d1 d2 d3", pointFields("d")),
               applyCdis});
  t.push_back({meshSpec("BLOCk",
                        "A straight line of n two-node elements between master nodes 1 and 2: "
                        "nodes node1..node1+n, elements elem1..elem1+n-1. node1 = 0 continues "
                        "after the highest node so far, elem1 = 0 after the highest element, "
                        "mat = 0 repeats the previous block's.",
                        {}, "CARTesian n 0 node1 elem1 mat, then 'i x y' for i = 1, 2",
                        {text("CARTesian", "block type word"), expr("n", "number of elements"),
                         expr("ns", "0 (a line)", "0"), expr("node1", "first node", "0"),
                         expr("elem1", "first element", "0"), expr("mat", "material set", "0")}),
               applyBlock});
  t.push_back({meshSpec("JOINt",
                        "Revolute joints between two coincident nodes: same translations, free "
                        "relative rotation.",
                        {}, "master slave", {expr("master", "node"), expr("slave", "node")}),
               applyJoints});
  t.push_back(
      {meshSpec(
           "CONTact",
           "Penalty contact. GROUnd: rigid ground y = y0 for every node, penalty stiffness "
           "k (kN/m per node); zeta: damping ratio of a dashpot c dp/dt on the "
           "penetration p while the node touches, c = 2 zeta sqrt(k m) for the node's "
           "own mass m (1: critical; absent or 0: none), the same at every step (this "
           "field was alpha, a damper alpha k dt that vanished with the step: a value "
           "there is now read as zeta); mu: "
           "Coulomb friction, elastic-plastic: each node held by a horizontal spring of "
           "stiffness k anchored where it last slid, sliding when the spring force reaches "
           "mu N (N the normal force; no creep at rest); e: restitution of an impact "
           "(below 1 the contact crushes: loading with k beyond the largest penetration q "
           "since the node touched down, unloading and reloading with k/e^2 below it, so "
           "that a node strikes with speed v and leaves with e v; the work k(p^2 - "
           "q^2)(1 - e^2)/2 is dissipated, whatever DT: a dynamic step through an impact is "
           "taken in shorter parts where a contact needs it). The run reports the deepest any node "
           "went "
           "into the ground and warns when it is deeper than half its members' section "
           "depth sqrt(3 I/A) (k too soft for the impact). "
           "MEMBers,,k[,zeta[,r[,mu[,e]]]]: "
           "contact of every node with every element it is not part of "
           "(nor tied to by a joint), at the distance r_node + r_element with "
           "r = sqrt(3 I/A), half the section depth (r: the radius of members whose "
           "material has no A and I, default 1e-3 of the shortest element); mu and e: "
           "the ground's friction (along the member) and crushing law, per pair, and "
           "zeta its dashpot for the pair's reduced mass; k = 0: "
           "no member contact (a study's switch). Pairs already that close in the "
           "reference configuration do not contact while the members between them hold; "
           "a joint that ruptures sets them free, and pieces inside each other's contact "
           "distance then start at zero force, their full distance returning as they "
           "separate. One GROUnd per mesh input (a MESH re-entry may give another, not "
           "above the nodes); a k beyond 1/eps = 4.5e15 times the members' largest "
           "EA/L is warned: no step resolves the contact and the members together.",
           {}, "GROUnd,,y0,k[,zeta[,mu[,e]]] and/or MEMBers,,k[,zeta[,r[,mu[,e]]]]",
           {text("GROUnd", "contact type (or MEMBers)"), text("", "empty"),
            expr("y0", "ground level (MEMBers: k)"),
            expr("k", "penalty stiffness, kN/m per node (MEMBers: zeta)"),
            expr("zeta", "damping ratio of the contact's dashpot (MEMBers: r)", "0"),
            expr("mu", "friction coefficient", "0"), expr("e", "restitution of an impact", "1")}),
       applyContact});
  t.push_back({meshSpec("GRAVity",
                        "Self-weight of every element with a density: acceleration (gx, gy), "
                        "constant (not scaled by the proportional load). No data records.",
                        {text("", "empty"), expr("gx", "x acceleration", "0"),
                         expr("gy", "y acceleration", "0")}),
               applyGravity});
  {
    CommandSpec shift =
        meshSpec("SHIFt",
                 "Origin (x0, y0) of the POLAr conversions (FEAP; default 0 0), "
                 "on the next record or on the command record (SHIFt,x0,y0).",
                 {}, "x0 y0", {expr("x0", "origin x", "0"), expr("y0", "origin y", "0")});
    shift.data = DataForm::Single;
    t.push_back({shift, applyShift});
  }
  t.push_back({meshSpec("POLAr",
                        "Convert nodes whose COORdinates hold polar values (r, theta in degrees) "
                        "to x = x0 + r cos(theta) + dx, y = y0 + r sin(theta) + dy about the "
                        "SHIFt origin, now (FEAP). NODE n1 n2 inc: nodes n1 to n2 step inc (n2 "
                        "empty: n1 alone; n2 is converted whatever inc); ALL: every node with "
                        "coordinates not converted yet. A node is converted once.",
                        {}, "NODE n1 n2 inc [dx dy] | ALL",
                        {text("NODE/ALL", "which nodes"), expr("n1", "first node"),
                         expr("n2", "last node", "n1"), expr("inc", "node increment", "1"),
                         expr("dx", "x shift after the conversion", "0"),
                         expr("dy", "y shift after the conversion", "0")}),
               applyPolar});
  for (auto& e : loadCommandTable()) t.push_back(std::move(e));
  for (auto& e : blastCommandTable()) t.push_back(std::move(e));
  t.push_back({meshSpec("PRINt", "Echo the mesh data in the log (default).", {}), applyPrint});
  t.push_back({meshSpec("NOPRint", "Stop echoing the mesh data in the log.", {}), applyNoPrint});
  CommandSpec para = meshSpec("PARAmeter",
                              "Parameter block: records 'name = expression' up to the blank "
                              "record; names of any length, case-insensitive.",
                              {}, "name = expression",
                              {text("name", "parameter name"), expr("expression", "its value")});
  para.aliases = {"CONStant"};
  t.push_back({para, nullptr});
  t.push_back({meshSpec("INCLude", "Read another file here (relative to this file).",
                        {text("file", "file name")}),
               nullptr});
  t.push_back({meshSpec("END", "End of the mesh input.", {}), nullptr});
  return t;
}

void registerMeshCommands(CommandRegistry& registry) {
  for (auto& e : meshCommandTable()) registry.add(std::move(e.spec));
}

// ---------------------------------------------------------------------------
// end of the mesh input

void refuseKinematicsChange(const Record& r, int m, Kinematics before) {
  const std::string was = before == Kinematics::Small ? "SMALl" : "FINIte";
  failAt(r, 0,
         "material " + std::to_string(m) + " has elements with " + was +
             " kinematics: the kinematics of a material set cannot change in a MESH re-entry",
         "keep " + was +
             "; HINGe2joint switches the elements to finite kinematics with their "
             "state");
}

void finishMesh(MeshContext& ctx, const SourceLoc& where, const std::string& whereText) {
  Model& model = ctx.model;
  if (ctx.beforeElements) ctx.beforeElements(model);

  for (const auto& [num, pe] : ctx.elements) {
    const Record& r = *pe.origin;
    const std::string what =
        "element " + std::to_string(num) + (pe.generated ? " (generated from this record)" : "");
    const std::size_t matField = r.is("CARTesian") ? 5 : 2;
    const MaterialSet* mat = model.material(pe.material);
    if (!mat)
      failAt(r, matField,
             what + " uses material " + std::to_string(pe.material) + ", which is not defined",
             "define it with MATErial," + std::to_string(pe.material));
    for (int a = 0; a < 2; ++a) {
      const int n = pe.nodes[a];
      if (n < 1 || n > model.numNodes() || !model.hasCoord(n - 1))
        failAt(r, r.is("CARTesian") ? 3 : 3 + a,
               what + " uses node " + std::to_string(n) + ", which has no coordinates");
    }
    if (pe.nodes[0] == pe.nodes[1])
      failAt(r, 3, what + " connects node " + std::to_string(pe.nodes[0]) + " to itself");
    const Vec2& x1 = model.coord(pe.nodes[0] - 1);
    const Vec2& x2 = model.coord(pe.nodes[1] - 1);
    if ((x2 - x1).norm() == 0) failAt(r, 3, what + " has zero length");
    model.setElement(num - 1, makeElement(*mat, {pe.nodes[0] - 1, pe.nodes[1] - 1}, x1, x2));
  }

  // MATErial given again: its existing elements (not rebuilt above) take the
  // new data with their state. A change of kinematics is refused at the record;
  // an element that cannot take the data ends the analysis at the record.
  if (!ctx.changedMaterials.empty()) {
    std::vector<int> rebuilt;
    for (const auto& [num, pe] : ctx.elements) rebuilt.push_back(num - 1);
    const State none;
    for (const auto& [m, src] : ctx.changedMaterials) {
      const MaterialSet& mat = *model.material(m);
      bool used = false;
      for (int e = 0; e < model.numElements() && !used; ++e)
        used = model.elements()[e] && model.element(e).materialNumber() == m &&
               std::find(rebuilt.begin(), rebuilt.end(), e) == rebuilt.end();
      if (!used) continue;
      if (mat.kinematics != src.before)
        refuseKinematicsChange(src.kinematics.blank() ? src.head : src.kinematics, m, src.before);
      const Status st = changeMaterial(model, ctx.state ? *ctx.state : none, mat, rebuilt);
      if (!st)
        throw AnalysisError(src.head.fieldLoc(0).str() + ": error: MATErial," + std::to_string(m) +
                            " given again: " + st.why);
      if (auto* os = ctx.out())
        *os << "      Material set " << m << " given again: its elements take the new data\n";
    }
  }

  if (auto* os = ctx.out(); os && !ctx.deferred.empty()) {
    title(*os, "E d g e   a n d   C o o r d i n a t e   V a l u e s");
    *os << "      Command           Node   (codes, forces or displacements: u, v, theta)\n";
  }
  for (auto& f : ctx.deferred) f(ctx);

  for (const auto& [node, r] : ctx.referencedNodes)
    if (!model.hasCoord(node - 1))
      failAt(r, 0, "node " + std::to_string(node) + " has no coordinates");

  if (!ctx.joints.empty()) {
    const double tol = 1e-3 * model.characteristicLength();
    for (const auto& j : ctx.joints) {
      for (int a = 0; a < 2; ++a) {
        const int n = a == 0 ? j.master : j.slave;
        if (!model.hasCoord(n - 1))
          failAt(j.origin, a, "joint node " + std::to_string(n) + " has no coordinates");
      }
      const double gap = (model.coord(j.master - 1) - model.coord(j.slave - 1)).norm();
      if (gap > tol) {
        std::ostringstream s;
        s << "joint nodes " << j.master << " and " << j.slave << " are not coincident (distance "
          << gap << ")";
        failAt(j.origin, 1, s.str());
      }
      for (const auto& existing : model.joints())
        if (existing.slave == j.slave - 1)
          failAt(j.origin, 1,
                 "node " + std::to_string(j.slave) + " is already the slave of a joint");
      model.joints().push_back(Joint{j.master - 1, j.slave - 1, JointForm::Condensed});
      if (auto* os = ctx.out())
        *os << "      Joint: master node " << j.master << ", slave node " << j.slave << "\n";
    }
  }

  const int expected = ctx.maxElements > 0 ? ctx.maxElements : model.numElements();
  for (int e = 0; e < expected; ++e)
    if (e >= model.numElements() || (!model.elements()[e] && e >= ctx.elementsBefore))
      throw DeckError(
          where,
          "element " + std::to_string(e + 1) + " is not defined" +
              (ctx.maxElements > 0 ? " (numel = " + std::to_string(ctx.maxElements) + ")" : ""),
          whereText,
          ctx.maxElements > 0 ? "define it, or set numel to 0 to have elements counted"
                              : "element numbers must run from 1 without gaps");

  // A joint friction moment (SOFTening's Mr) acts on a joint condensed into
  // its one slave element; on a joint shared by more it would be ignored.
  for (const auto& j : ctx.joints)
    if (const Joint joint{j.master - 1, j.slave - 1, JointForm::Condensed};
        jointFriction(model, joint.slave) > 0 && !condensable(model, joint))
      failAt(j.origin, 1,
             "the joint friction Mr of the materials at node " + std::to_string(j.slave) +
                 " needs a joint condensed into one element: the slave node has more than one "
                 "element, nodal data, or is the master of another joint",
             "give the slave node one element only, or leave Mr out");

  if (ctx.topologyChanged) model.bumpTopology();
  ctx.elements.clear();
  ctx.changedMaterials.clear();
  ctx.deferred.clear();
  ctx.joints.clear();
  ctx.referencedNodes.clear();
  ctx.topologyChanged = false;
}

namespace meshspec {

void failAt(const Record& r, std::size_t i, const std::string& msg, const std::string& hint) {
  throw DeckError(r.fieldLoc(i), msg, r.excerpt(r.fieldLoc(i)), hint);
}

FieldSpec expr(std::string name, std::string doc, std::string dflt) {
  return {std::move(name), FieldKind::Expression, std::move(dflt), std::move(doc)};
}
FieldSpec text(std::string name, std::string doc, std::string dflt) {
  return {std::move(name), FieldKind::Text, std::move(dflt), std::move(doc)};
}

CommandSpec subSpec(std::string name, std::string doc, std::vector<FieldSpec> fields) {
  CommandSpec s;
  s.name = std::move(name);
  s.doc = std::move(doc);
  s.fields = std::move(fields);
  s.section = CommandSection::SubRecord;
  return s;
}

CommandSpec meshSpec(std::string name, std::string doc, std::vector<FieldSpec> fields,
                     std::string dataSyntax, std::vector<FieldSpec> dataFields) {
  CommandSpec s;
  s.name = std::move(name);
  s.doc = std::move(doc);
  s.fields = std::move(fields);
  s.section = CommandSection::Mesh;
  s.data = dataSyntax.empty() ? DataForm::None : DataForm::Records;
  s.dataSyntax = std::move(dataSyntax);
  s.dataFields = std::move(dataFields);
  return s;
}

}  // namespace meshspec
}  // namespace c2d
