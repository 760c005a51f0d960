#include "macro/mesh/LoadCommands.h"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <ostream>
#include <set>

#include "macro/mesh/MeshCommands.h"
#include "macro/mesh/SiteCommand.h"
#include "macro/deck/Expression.h"
#include "macro/deck/NumberRanges.h"

namespace c2d {

using namespace meshspec;

namespace {

// QLOAd: n1 n2 inc qx qy [MASS]. Elements are built when the mesh is complete,
// so the loads are checked and added then (in deck order).
void applyElementLoads(MeshContext& ctx, const MeshCommand& cmd) {
  const std::string syntax = "n1 n2 inc qx qy [MASS]";
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 6, syntax);
    const int n1 = ctx.elementNumber(r, 0);
    int n2 = ctx.integer(r, 1, "last element");
    int inc = ctx.integer(r, 2, "element increment");
    if (n2 == 0) n2 = n1;
    if (inc == 0) inc = 1;
    if (n2 < n1) failAt(r, 1, "the last element " + std::to_string(n2) + " comes before the first");
    if (inc < 0) failAt(r, 2, "the element increment must be positive");
    const Vec2 q(ctx.number(r, 3), ctx.number(r, 4));
    bool asMass = false;
    if (r.size() > 5 && !r[5].text.empty()) {
      if (!keywordMatches(r[5].text, "MASS"))
        failAt(r, 5, "unknown option '" + r[5].text + "'",
               "the record is '" + syntax + "': MASS makes the load a weight that is also mass");
      asMass = true;
    }
    ctx.deferred.push_back([=](MeshContext& c) {
      if (asMass && c.model.gravity().norm() == 0)
        failAt(r, 5, "QLOAd with MASS needs GRAVity: the mass is |q|/|g|",
               "give GRAVity,,gx,gy in the mesh input");
      // A weight pulls along gravity: one against it would be mass |q|/|g| pushed up.
      if (asMass && q.dot(c.model.gravity()) < 0)
        failAt(
            r, q.y() * c.model.gravity().y() < 0 ? 4 : 3,
            "QLOAd with MASS is a weight, and this load points against gravity: its mass |q|/|g| "
            "would be pushed up",
            "a floor's weight has the sign of GRAVity's (qy < 0 under GRAVity,,0,-9.81); an "
            "upward load is given without MASS");
      // The first element beyond the mesh, before the range is generated.
      if (const long long first = firstBeyond(n1, n2, inc, c.model.numElements()))
        failAt(r, first == n1 ? 0 : 1,
               "QLOAd: element " + std::to_string(first) + " is not defined");
      for (int e : steppedRange(n1, n2, inc)) {
        if (e > c.model.numElements() || !c.model.elements()[e - 1])
          failAt(r, e == n1 ? 0 : 1, "QLOAd: element " + std::to_string(e) + " is not defined");
        c.model.elementLoads().push_back(ElementLoad{e - 1, q, asMass});
        if (auto* os = c.out()) {
          *os << "      QLOAd       " << std::setw(8) << e;
          num(*os, q.x());
          num(*os, q.y()) << (asMass ? "   also mass" : "") << "\n";
        }
      }
    });
  }
}

// MASS: node ng m1 m2 m3, generation by linear interpolation between records
// (FEAP genvec, as for FORCe).
void applyNodalMasses(MeshContext& ctx, const MeshCommand& cmd) {
  using V3 = Eigen::Matrix<double, kNodeDofs, 1>;
  std::set<int> touched;
  int l = 0, lg = 0;
  auto set = [&](int n, const V3& v) {
    for (int i = 0; i < kNodeDofs; ++i) ctx.model.nodalMass(n - 1)[i] = v[i];
    touched.insert(n);
  };
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 2 + kNodeDofs, "node ng m1 m2 m3");
    const int n = ctx.node(r, 0);
    const int ng = ctx.integer(r, 1, "generation increment");
    V3 v;
    for (int i = 0; i < kNodeDofs; ++i) {
      v[i] = ctx.number(r, 2 + i);
      if (v[i] < 0) failAt(r, 2 + i, "a mass must not be negative");
    }
    if (n == l) failAt(r, 0, "node " + std::to_string(n) + " is given on two records in a row");
    V3 vl = V3::Zero();
    if (l > 0)
      for (int i = 0; i < kNodeDofs; ++i) vl[i] = ctx.model.nodalMass(l - 1)[i];
    set(n, v);
    generateBetween(l, lg, n, vl, v, [&](int k, const V3& x) { set(k, x); });
    ctx.referencedNodes.emplace(n, r);
    l = n;
    lg = ng;
  }
  if (auto* os = ctx.out()) {
    title(*os, "N o d a l   M a s s e s");
    *os << "      Node" << std::setw(13) << "u" << std::setw(13) << "v" << std::setw(13) << "theta"
        << "\n";
    for (int k : touched) {
      *os << std::setw(10) << k;
      for (int i = 0; i < kNodeDofs; ++i) num(*os, ctx.model.nodalMass(k - 1)[i]);
      *os << "\n";
    }
  }
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

}  // namespace

std::vector<MeshCommandEntry> loadCommandTable() {
  std::vector<MeshCommandEntry> t;
  t.push_back(
      {meshSpec("QLOAd",
                "Uniform load per unit length (e.g. a floor's dead + live load, kN/m) on "
                "elements n1..n2 with step inc, global components qx, qy; constant (not scaled "
                "by the proportional load), qL/2 to each end node, no nodal moments. MASS: the "
                "load is a weight, |q|/|g| is also mass per length (lumped at the end nodes' "
                "translations; needs GRAVity, which does not load it again; a weight points along "
                "gravity, so a load against it with MASS is an error). Loads add up; "
                "checked when the mesh is complete. A QLOAd without MASS in a dynamic run is "
                "warned (its weight acts without its mass).",
                {}, "n1 n2 inc qx qy [MASS]",
                {expr("n1", "first element"), expr("n2", "last element", "n1"),
                 expr("inc", "element step", "1"), expr("qx", "load per length, x"),
                 expr("qy", "load per length, y (down: negative)"),
                 text("MASS", "the load is also mass", "load only")}),
       applyElementLoads});
  t.push_back(
      {meshSpec(
           "MASS",
           "Lumped nodal masses (FEAP's nodal mass input): m1, m2 on the "
           "translations, m3 rotary inertia; in dynamics, and loaded by GRAVity. "
           "Generation interpolates linearly between records.",
           {}, "node ng m1 m2 m3",
           {expr("node", "node number"), expr("ng", "generation increment to the next record", "0"),
            expr("m1", "mass, x"), expr("m2", "mass, y"), expr("m3", "rotary inertia", "0")}),
       applyNodalMasses});
  t.push_back(siteCommandEntry());
  t.push_back({meshSpec("GRAVity",
                        "Self-weight of every element with a density: acceleration (gx, gy), "
                        "constant (not scaled by the proportional load). No data records.",
                        {text("", "empty"), expr("gx", "x acceleration", "0"),
                         expr("gy", "y acceleration", "0")}),
               applyGravity});
  return t;
}

}  // namespace c2d
