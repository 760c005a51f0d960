// The mesh commands of the geometry: COORdinates, ELEMents, BLOCk (generated
// lines of elements), JOINt (revolute joints between nodes), SHIFt and POLAr
// (polar coordinates).
#include "macro/mesh/MeshCommands.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

#include "macro/deck/NumberRanges.h"
#include "macro/mesh/SubRecordFields.h"
#include "macro/deck/Limits.h"

namespace c2d {

using namespace meshspec;

namespace {

using subrecord::looksNumeric;

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
// BLOCk: CARTesian nr ns ni ne ma [nodinc ntyp], then the two master nodes
// "1 x1 y1" and "2 x2 y2": nr two-node elements on the straight line, nodes
// ni..ni+nr, elements ne..ne+nr-1 of material ma. As in FEAP, ni = 0 continues
// after the highest node given so far, ne = 0 after the highest element, ma = 0
// repeats the previous block's material.

// The block's line: nr elements from node ni and element ne, of material ma.
struct BlockLine {
  int nr = 0, ni = 0, ne = 0, ma = 0;
};

// The CARTesian record, its zeros resolved and its numbers checked.
BlockLine readBlockLine(MeshContext& ctx, const MeshCommand& cmd) {
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
  BlockLine b;
  b.nr = ctx.integer(t, 1, "number of elements");
  if (b.nr < 1) failAt(t, 1, "a block needs at least one element, got " + std::to_string(b.nr));
  const int ns = ctx.integer(t, 2, "second direction count");
  b.ni = ctx.integer(t, 3, "first node number");
  b.ne = ctx.integer(t, 4, "first element number");
  b.ma = ctx.integer(t, 5, "material number");
  const int ntyp = ctx.integer(t, 7, "block type");
  if (ns > 1) failAt(t, 2, "only a line of two-node elements is available (ns = 0)");
  if (ntyp != 0) failAt(t, 7, "only block type 0 is available");
  if (b.ni < 0 || b.ne < 0 || b.ma < 0)
    failAt(t, b.ni < 0 ? 3 : b.ne < 0 ? 4 : 5, "numbers must not be negative");
  if (b.ni == 0) b.ni = ctx.highestNode + 1;
  if (b.ne == 0) b.ne = ctx.highestElement + 1;
  // In 64 bits: the block's last node and element must be numbers this program takes.
  checkNumber(t, 1, static_cast<long long>(b.ni) + b.nr, DeckLimits::maxNodes(),
              "the block's last node", "first node + number of elements");
  checkNumber(t, 1, static_cast<long long>(b.ne) + b.nr - 1, DeckLimits::maxElements(),
              "the block's last element", "first element + number of elements - 1");
  checkNumber(t, 5, std::max(b.ma, 1), DeckLimits::kMaxMaterials, "material set");
  if (b.ma == 0) b.ma = std::max(1, ctx.lastBlockMaterial);
  if (ctx.maxMaterials > 0 && b.ma > ctx.maxMaterials)
    failAt(t, 5,
           "material " + std::to_string(b.ma) +
               " is beyond nummat = " + std::to_string(ctx.maxMaterials));
  return b;
}

// The master nodes "1 x1 y1" and "2 x2 y2", each once.
std::array<Vec2, 2> readMasterNodes(MeshContext& ctx, const MeshCommand& cmd) {
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
  return master;
}

void applyBlock(MeshContext& ctx, const MeshCommand& cmd) {
  const BlockLine b = readBlockLine(ctx, cmd);
  const Record& t = cmd.data[0];
  const std::array<Vec2, 2> master = readMasterNodes(ctx, cmd);
  const int nr = b.nr, ni = b.ni, ne = b.ne, ma = b.ma;

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

}  // namespace

std::vector<MeshCommandEntry> geometryCommandTable() {
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
  return t;
}

}  // namespace c2d
