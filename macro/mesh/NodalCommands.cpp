// The mesh commands of nodal data: BOUNdary, FORCe, DISPlacement,
// FPROportional, and the edge and point forms (EBOUndary, EFORce,
// EDISplacement, CBOUndary, CFORce, CDISplacement) applied when the mesh is
// complete.
#include "macro/mesh/MeshCommands.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

#include "macro/deck/NumberRanges.h"
#include "macro/deck/Limits.h"

namespace c2d {

using namespace meshspec;

namespace {

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

// A prescribed value beyond the coordinates' limit moves a node where the
// element's length, squared, is no number (DISPlacement 1e308 made the first
// residual infinite, reported as a Newton failure at a step): a deck error at
// the value, with the limit of the coordinates.
void checkPrescribed(const Record& r, std::size_t first, const double* v) {
  for (int i = 0; i < kNodeDofs; ++i)
    if (!(std::abs(v[i]) <= DeckLimits::kMaxCoordinate)) {
      char what[200];
      std::snprintf(what, sizeof what,
                    "a prescribed %s of %g: beyond the largest this program takes (%g in the "
                    "deck's units, the limit of the coordinates)",
                    i < 2 ? "displacement" : "rotation", v[i], DeckLimits::kMaxCoordinate);
      failAt(r, first + static_cast<std::size_t>(i), what,
             "a prescribed value is scaled by the proportional load (PROP): give its size here "
             "and its history there");
    }
}

void applyNodalValues(MeshContext& ctx, const MeshCommand& cmd, NodalArray array,
                      const char* what, bool prescribed = false) {
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
    if (prescribed) checkPrescribed(r, 2, v.data());
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
  applyNodalValues(ctx, cmd, static_cast<NodalArray>(&Model::disp), "D i s p l a c e m e n t s",
                   true);
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
  if (t == Target::Disp) checkPrescribed(r, first, v.data());
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
// specs

std::vector<FieldSpec> nodeValueFields(const std::string& what) {
  return {expr("node", "node number"), expr("ng", "generation increment to the next record", "0"),
          expr(what + "1", "x direction"), expr(what + "2", "y direction"),
          expr(what + "3", "rotation")};
}

}  // namespace

std::vector<MeshCommandEntry> nodalCommandTable() {
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
  return t;
}

}  // namespace c2d
