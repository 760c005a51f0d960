#include "macro/mesh/InfillCommand.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "core/Brace.h"
#include "elements/InfillStrut.h"
#include "elements/Joints.h"
#include "materials/InfillPanel.h"

namespace c2d {

using namespace meshspec;

namespace {

constexpr double kDefaultModulusRatio = 550;  // Em / fm, FEMA 356 7.2.2.4
constexpr double kDefaultDensity = 1.8;       // t/m^3

// The members along one edge of a panel (from corner a to corner b): their
// count, length-weighted bending stiffness and depth, and whether any is
// geometrically exact.
struct Edge {
  int members = 0;
  double length = 0, EI = 0, depth = 0;
  bool finite = false;
};

// The depth of a member's section: SECTion's h, else that of the rectangle
// with its A and I; 0 when the set gives neither.
double sectionDepth(const MaterialSet& m) {
  if (m.section) return m.section->h;
  return m.A > 0 && m.I > 0 ? std::sqrt(12 * m.I / m.A) : 0.0;
}

Edge edgeMembers(const Model& model, const Vec2& a, const Vec2& b, double tol) {
  Edge edge;
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  auto onEdge = [&](const Vec2& x) {
    const double s = (x - a).dot(ab) / l2;
    return s > -tol && s < 1 + tol && (a + s * ab - x).norm() <= tol * std::sqrt(l2);
  };
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e) || isBrace(model.element(e))) continue;
    const auto n = model.element(e).nodes();
    if (!onEdge(model.coord(n[0])) || !onEdge(model.coord(n[1]))) continue;
    const MaterialSet* m = model.material(innermost(model.element(e)).materialNumber());
    if (!m) continue;
    const double l = (model.coord(n[1]) - model.coord(n[0])).norm();
    ++edge.members;
    edge.length += l;
    edge.EI += l * m->EI();
    edge.depth += l * sectionDepth(*m);
    edge.finite = edge.finite || m->kinematics == Kinematics::Finite;
  }
  if (edge.length > 0) {
    edge.EI /= edge.length;
    edge.depth /= edge.length;
  }
  return edge;
}

struct Panel {
  std::array<int, 4> nodes{};  // deck numbers, counterclockwise from the bottom left
  const Record* origin = nullptr;
};

struct Wall {
  InfillWall wall;
  const Record* head = nullptr;
};

int highestPanel(const Model& model) {
  int p = 0;
  for (const auto& el : model.elements())
    if (const auto* s = dynamic_cast<const InfillStrut*>(el.get())) p = std::max(p, s->data().panel);
  return p;
}

// The corners' coordinates; a DeckError unless they form a rectangle with
// horizontal and vertical edges, counterclockwise from the bottom left.
std::array<Vec2, 4> corners(const MeshContext& ctx, const Panel& p) {
  const Record& r = *p.origin;
  std::array<Vec2, 4> x;
  for (int k = 0; k < 4; ++k) {
    if (p.nodes[k] > ctx.model.numNodes() || !ctx.model.hasCoord(p.nodes[k] - 1))
      failAt(r, k, "infill corner node " + std::to_string(p.nodes[k]) + " has no coordinates");
    x[k] = ctx.model.coord(p.nodes[k] - 1);
  }
  const double size = std::max(x[1].x() - x[0].x(), x[3].y() - x[0].y());
  const double tol = 1e-3 * std::abs(size);
  const bool rectangle = size > 0 && x[1].x() > x[0].x() && x[3].y() > x[0].y() &&
                         std::abs(x[1].y() - x[0].y()) <= tol &&
                         std::abs(x[2].y() - x[3].y()) <= tol &&
                         std::abs(x[3].x() - x[0].x()) <= tol &&
                         std::abs(x[2].x() - x[1].x()) <= tol;
  if (!rectangle) {
    std::ostringstream s;
    s << "nodes " << p.nodes[0] << " " << p.nodes[1] << " " << p.nodes[2] << " " << p.nodes[3]
      << " do not form a panel";
    failAt(r, 0, s.str(),
           "give the corners of a bay counterclockwise from the bottom left: bottom left, bottom "
           "right, top right, top left (edges horizontal and vertical)");
  }
  return x;
}

void buildPanel(MeshContext& ctx, const Wall& w, const Panel& p, int panelNumber) {
  const Record& r = *p.origin;
  Model& model = ctx.model;
  const std::array<Vec2, 4> x = corners(ctx, p);
  const double tol = 1e-3;
  const Edge left = edgeMembers(model, x[0], x[3], tol), right = edgeMembers(model, x[1], x[2], tol);
  const Edge bottom = edgeMembers(model, x[0], x[1], tol), top = edgeMembers(model, x[3], x[2], tol);
  for (const auto& [edge, field, name] :
       {std::tuple{&left, 0, "left (n1-n4)"}, std::tuple{&right, 1, "right (n2-n3)"}})
    if (edge->members == 0)
      failAt(r, field,
             std::string("the panel's ") + name + " edge has no column: an infill needs a bay "
             "with a frame member along each vertical edge");
  InfillFrame frame;
  frame.bay = x[1].x() - x[0].x();
  frame.storey = x[3].y() - x[0].y();
  frame.columnDepth = 0.5 * (left.depth + right.depth);
  frame.beamDepth = 0.5 * (bottom.depth + top.depth);
  frame.EIcol = 0.5 * (left.EI + right.EI);
  InfillStruts s;
  try {
    s = infillStruts(w.wall, frame);
  } catch (const std::invalid_argument& e) {
    failAt(r, 0, std::string("infill panel: ") + e.what());
  }
  const int first = std::max(ctx.maxElements, model.numElements());
  InfillStrutData d;
  d.law = StrutLaw(s.stiffness, s.strength);
  d.nodeMass = 0.25 * s.mass;
  d.finite = left.finite || right.finite;
  d.panel = panelNumber;
  const std::array<std::array<int, 2>, 2> diagonals{{{0, 2}, {1, 3}}};
  for (int k = 0; k < 2; ++k) {
    d.nodes = {p.nodes[diagonals[k][0]] - 1, p.nodes[diagonals[k][1]] - 1};
    d.x1 = x[diagonals[k][0]];
    d.x2 = x[diagonals[k][1]];
    d.partner = first + 1 - k;
    model.setElement(first + k, std::make_unique<InfillStrut>(d));
  }
  ctx.topologyChanged = true;
  if (auto* os = ctx.out()) {
    *os << "      Panel " << panelNumber << ": nodes " << p.nodes[0] << " " << p.nodes[1] << " "
        << p.nodes[2] << " " << p.nodes[3] << ", struts: element " << first + 1 << " (nodes "
        << p.nodes[0] << "-" << p.nodes[2] << "), element " << first + 2 << " (nodes "
        << p.nodes[1] << "-" << p.nodes[3] << ")\n        clear L, h";
    num(*os, s.Linf);
    num(*os, s.hinf) << "  lambda1 h_col";
    num(*os, s.lambda1 * frame.storey) << "  width a";
    num(*os, s.width) << "  R1";
    num(*os, s.reduction) << "\n        EA of a strut";
    num(*os, s.stiffness) << "  V crushing";
    num(*os, s.crushing) << "  V sliding";
    num(*os, s.sliding) << "  Pu";
    num(*os, s.strength) << (s.crushingGoverns() ? " (crushing)" : " (sliding)") << "  mass";
    num(*os, s.mass) << "\n";
  }
}

double headNumber(MeshContext& ctx, const Record& h, std::size_t i, double dflt) {
  return i < h.size() && !h[i].text.empty() ? ctx.number(h, i) : dflt;
}

Wall readWall(MeshContext& ctx, const Record& h) {
  const std::string syntax = "INFIll,,t,fm[,Em[,rho[,open]]]";
  ctx.maxFields(h, 7, syntax);
  if (!h.text(1).empty())
    failAt(h, 1, "INFIll takes no option word (its second field is empty)", "write " + syntax);
  Wall w;
  w.head = &h;
  w.wall.t = headNumber(ctx, h, 2, 0);
  w.wall.fm = headNumber(ctx, h, 3, 0);
  if (!(w.wall.t > 0) || !std::isfinite(w.wall.t))
    failAt(h, std::min<std::size_t>(2, h.size()), "INFIll needs a positive wall thickness t (m)",
           "write " + syntax);
  if (!(w.wall.fm > 0) || !std::isfinite(w.wall.fm))
    failAt(h, std::min<std::size_t>(3, h.size()),
           "INFIll needs a positive masonry compressive strength fm (kN/m^2)", "write " + syntax);
  w.wall.Em = headNumber(ctx, h, 4, kDefaultModulusRatio * w.wall.fm);
  if (!(w.wall.Em > 0) || !std::isfinite(w.wall.Em))
    failAt(h, 4, "the masonry modulus Em must be positive (empty: 550 fm)");
  w.wall.rho = headNumber(ctx, h, 5, kDefaultDensity);
  if (!(w.wall.rho >= 0) || !std::isfinite(w.wall.rho))
    failAt(h, 5, "the wall's density must be zero or positive (empty: 1.8 t/m^3)");
  w.wall.open = headNumber(ctx, h, 6, 0);
  if (!(w.wall.open >= 0 && w.wall.open <= 1))
    failAt(h, 6, "the opening ratio must lie in [0, 1] (0: solid, 1: no wall)");
  return w;
}

void applyInfill(MeshContext& ctx, const MeshCommand& cmd) {
  const Wall w = readWall(ctx, cmd.head);
  if (cmd.data.empty())
    failAt(cmd.head, 0, "INFIll needs data records 'n1 n2 n3 n4 [ng dn]' up to a blank record");
  std::vector<Panel> panels;
  for (const Record& r : cmd.data) {
    ctx.maxFields(r, 6, "n1 n2 n3 n4 ng dn");
    Panel p;
    p.origin = &r;
    for (int k = 0; k < 4; ++k) p.nodes[k] = ctx.node(r, k, "infill corner node");
    const int ng = ctx.integer(r, 4, "panel count");
    const int dn = ctx.integer(r, 5, "node increment");
    if (ng < 0) failAt(r, 4, "the number of generated panels ng must be zero or positive");
    if (ng > 0 && dn == 0) failAt(r, 5, "generated panels need a nonzero node increment dn");
    for (int g = 0; g <= ng; ++g) {
      Panel q = p;
      for (int k = 0; k < 4; ++k) {
        const long long n = static_cast<long long>(p.nodes[k]) + static_cast<long long>(g) * dn;
        ctx.ensureNode(n, r, g == 0 ? k : 5);
        q.nodes[k] = static_cast<int>(n);
      }
      panels.push_back(q);
    }
  }
  if (w.wall.open >= 1) {  // no wall: no struts, no numbers
    if (auto* os = ctx.out())
      *os << "      INFIll with opening ratio 1: no wall, " << panels.size()
          << " panel(s) left empty\n";
    return;
  }
  ctx.afterElements.push_back([w, panels](MeshContext& c) {
    if (auto* os = c.out()) title(*os, "I n f i l l   P a n e l s");
    int number = highestPanel(c.model);
    for (const Panel& p : panels) buildPanel(c, w, p, ++number);
  });
}

}  // namespace

std::vector<MeshCommandEntry> infillCommandTable() {
  std::vector<MeshCommandEntry> t;
  t.push_back(
      {meshSpec(
           "INFIll",
           "Masonry infill panels in the frame's bays, each as two compression-only diagonal "
           "struts between its corner nodes (FEMA 356 7.5.2 / ASCE 41-17 11.3). Width "
           "a = 0.175 (lambda1 h_col)^-0.4 r_inf, lambda1 = [Em t sin(2 theta) / (4 EIcol "
           "h_inf)]^(1/4): h_col the storey height between the beams' axes, h_inf, L_inf the "
           "clear panel (centreline size less the mean depth of the beams, of the columns: "
           "SECTion's h or sqrt(12 I/A)), r_inf its diagonal, theta = atan(h_inf/L_inf), EIcol "
           "the mean of the columns (the members along the vertical edges: each edge needs "
           "one). Opening: a and the strengths times R1 = 0.6 open^2 - 1.6 open + 1 (Al-Chaar "
           "2002). Strength as storey shear: the lesser of the strut's crushing a t fm "
           "cos(theta_s) and the sliding shear L_inf t f_vie with f_vie = 0.03 fm (FEMA 356 "
           "Table 7-1); theta_s the strut's angle between the corner nodes, axial stiffness "
           "Em a t. Law: elastic to Pu, linear to 0.2 Pu at 5 times the peak strain, held to "
           "8 times, zero at 10 times: then the strut is gone (one log line) and its panel's "
           "other strut goes as soon as it carries nothing. The wall's mass rho t L_inf h_inf "
           "(1 - open) lies at the four corners. Addressing: the struts are numbered after the "
           "deck's elements (after numel when given), in record order, two per panel: first "
           "n1-n3, then n2-n4 (the mesh echo lists them); BLASt, REMOve and WEAKen take those "
           "numbers. Struts carry no moment, strike nothing, are not debris pieces; kinematics "
           "as the columns' (FINIte: geometrically exact truss).",
           {text("", "empty"), expr("t", "wall thickness (m)"),
            expr("fm", "masonry compressive strength (kN/m^2)"),
            expr("Em", "masonry modulus", "550 fm"), expr("rho", "density (t/m^3)", "1.8"),
            expr("open", "opening ratio, area of the openings over the panel's (0..1)", "0")},
           "n1 n2 n3 n4 ng dn",
           {expr("n1", "bottom left corner node"), expr("n2", "bottom right corner node"),
            expr("n3", "top right corner node"), expr("n4", "top left corner node"),
            expr("ng", "more panels generated", "0"),
            expr("dn", "node number increment of each generated panel", "0")}),
       applyInfill});
  return t;
}

}  // namespace c2d
