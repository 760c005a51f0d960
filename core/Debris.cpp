#include "core/Debris.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Brace.h"
#include "core/FloorLoad.h"
#include "core/contact/GroundContact.h"
#include "core/contact/MemberContact.h"

namespace c2d {

namespace {

Vec2 position(const Model& model, const State& s, int n) {
  const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs;
  const Vec2 u = i + 1 < s.u.size() ? Vec2(s.u[i], s.u[i + 1]) : Vec2::Zero();
  return model.coord(n) + u;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6e", v);
  return buf;
}

}  // namespace

bool DebrisFigures::outside() const { return site && (xmin < site->xmin || xmax > site->xmax); }

std::string DebrisFigures::siteStatus() const {
  return !site ? "none" : outside() ? "outside" : "inside";
}

namespace {

// The floor mass per length each element carries (QLOAd MASS).
std::vector<double> carriedMass(const Model& model) {
  std::vector<double> carried(model.numElements(), 0.0);
  for (const ElementLoad& l : model.elementLoads())
    if (l.element >= 0 && l.element < model.numElements())
      carried[l.element] += carriedMassPerLength(model, l);
  return carried;
}

// An element's translational mass (e^T M e for a unit rigid translation e) with
// the floor mass it carries.
double elementMass(const Model& model, int e, const std::vector<double>& carried) {
  ElemVec ex = ElemVec::Zero();
  ex(0) = ex(3) = 1;
  const Element& el = model.element(e);
  const auto n = el.nodes();
  return ex.dot(el.mass() * ex) + carried[e] * (model.coord(n[1]) - model.coord(n[0])).norm();
}

double nodalPointMass(const Model& model, int n) {
  return std::max(model.nodalMass(n)[0], model.nodalMass(n)[1]);
}

}  // namespace

std::vector<MassPiece> massPieces(const Model& model, const State& state) {
  std::vector<MassPiece> pieces;
  const std::vector<double> carried = carriedMass(model);
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.elements()[e]) continue;
    const double m = elementMass(model, e, carried);
    if (m <= 0) continue;
    const auto n = model.element(e).nodes();
    const double a = position(model, state, n[0]).x(), b = position(model, state, n[1]).x();
    if (isBrace(model.element(e))) {  // a wall's mass lies at the frame's nodes
      pieces.push_back({a, a, 0.5 * m});
      pieces.push_back({b, b, 0.5 * m});
      continue;
    }
    pieces.push_back({std::min(a, b), std::max(a, b), m});
  }
  const std::vector<char> held = model.heldNodes();
  for (int n = 0; n < model.numNodes(); ++n) {
    const double m = nodalPointMass(model, n);
    if (m <= 0 || !model.hasCoord(n) || !held[n]) continue;
    const double x = position(model, state, n).x();
    pieces.push_back({x, x, m});
  }
  return pieces;
}

std::vector<double> pieceMassAtNodes(const Model& model) {
  const int nn = model.numNodes();
  std::vector<int> parent(static_cast<std::size_t>(nn));
  for (int n = 0; n < nn; ++n) parent[n] = n;
  auto root = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  auto join = [&](int a, int b) {
    if (a >= 0 && b >= 0 && a < nn && b < nn) parent[root(a)] = root(b);
  };
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e) && !isBrace(model.element(e)))  // a strut joins no pieces
      join(model.element(e).nodes()[0], model.element(e).nodes()[1]);
  for (const Joint& j : model.joints()) join(j.master, j.slave);
  std::vector<double> mass(static_cast<std::size_t>(nn), 0.0);
  const std::vector<double> carried = carriedMass(model);
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e)) {
      const auto n = model.element(e).nodes();
      const double m = std::max(0.0, elementMass(model, e, carried));
      if (isBrace(model.element(e))) {
        mass[root(n[0])] += 0.5 * m;
        mass[root(n[1])] += 0.5 * m;
      } else {
        mass[root(n[0])] += m;
      }
    }
  const std::vector<char> held = model.heldNodes();
  for (int n = 0; n < nn; ++n)
    if (held[n] && model.hasCoord(n)) mass[root(n)] += nodalPointMass(model, n);
  std::vector<double> out(static_cast<std::size_t>(nn), 0.0);
  for (int n = 0; n < nn; ++n)
    if (held[n]) out[n] = mass[root(n)];
  return out;
}

namespace {

bool isPoint(const MassPiece& p) { return p.x1 - p.x0 <= 1e-12 * std::max(1.0, std::abs(p.x0)); }

}  // namespace

double massQuantile(const std::vector<MassPiece>& pieces, double q) {
  // The mass below x is piecewise linear in x: sweep the pieces' ends, with the
  // density of the pieces spanning each stretch and the point masses as jumps.
  struct Event {
    double x, density, point;
  };
  std::vector<Event> events;
  double total = 0;
  for (const MassPiece& p : pieces) {
    if (p.mass <= 0) continue;
    total += p.mass;
    if (isPoint(p)) {
      events.push_back({p.x0, 0, p.mass});
    } else {
      const double rho = p.mass / (p.x1 - p.x0);
      events.push_back({p.x0, rho, 0});
      events.push_back({p.x1, -rho, 0});
    }
  }
  if (events.empty()) return 0;
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.x < b.x; });
  const double target = std::clamp(q, 0.0, 1.0) * total;
  double below = 0, density = 0, x = events.front().x;
  for (const Event& ev : events) {
    const double grown = below + density * (ev.x - x);
    if (grown >= target && density > 0) return x + (target - below) / density;
    below = grown;
    x = ev.x;
    density += ev.density;
    if (ev.point > 0 && below + ev.point >= target) return x;
    below += ev.point;
  }
  return x;
}

std::vector<std::pair<double, double>> massCover(const std::vector<MassPiece>& pieces) {
  std::vector<std::pair<double, double>> spans;
  for (const MassPiece& p : pieces)
    if (p.mass > 0) spans.emplace_back(p.x0, p.x1);
  std::sort(spans.begin(), spans.end());
  std::vector<std::pair<double, double>> cover;
  for (const auto& [a, b] : spans) {
    if (!cover.empty() && a <= cover.back().second)
      cover.back().second = std::max(cover.back().second, b);
    else
      cover.emplace_back(a, b);
  }
  return cover;
}

namespace {

// Fraction of a piece inside [lo, hi].
double fractionIn(const MassPiece& p, double lo, double hi) {
  if (isPoint(p)) return (p.x0 >= lo && p.x0 <= hi) ? 1.0 : 0.0;
  return std::max(0.0, std::min(p.x1, hi) - std::max(p.x0, lo)) / (p.x1 - p.x0);
}

}  // namespace

double massOutside(const std::vector<MassPiece>& pieces, const Site& site) {
  double m = 0;
  for (const MassPiece& p : pieces) m += p.mass * (1.0 - fractionIn(p, site.xmin, site.xmax));
  return m;
}

std::vector<double> massHistogram(const std::vector<MassPiece>& pieces, double x0, double width,
                                  int bins) {
  std::vector<double> h(static_cast<std::size_t>(std::max(bins, 0)), 0.0);
  if (width <= 0) return h;
  for (const MassPiece& p : pieces) {
    if (isPoint(p)) {
      const int k = std::clamp(static_cast<int>(std::floor((p.x0 - x0) / width)), 0, bins - 1);
      if (bins > 0) h[k] += p.mass;
      continue;
    }
    for (int k = 0; k < bins; ++k)
      h[k] += p.mass * fractionIn(p, x0 + k * width, x0 + (k + 1) * width);
  }
  return h;
}

DebrisFigures debrisFigures(const Model& model, const State& state) {
  DebrisFigures d;
  d.site = model.site();
  // The footprint from every node of the building; where the debris lies from
  // the nodes still held by elements (a removed member's nodes are gone).
  bool footprint = false, any = false;
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n)) continue;
    const double x0 = model.coord(n).x();
    d.footprintMin = footprint ? std::min(d.footprintMin, x0) : x0;
    d.footprintMax = footprint ? std::max(d.footprintMax, x0) : x0;
    footprint = true;
  }
  const std::vector<char> held = model.heldNodes();
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n) || !held[n]) continue;
    const Vec2 x = position(model, state, n);
    if (!any) {
      d.xmin = d.xmax = x.x();
      d.height = x.y();
      d.leftNode = d.rightNode = n;
      any = true;
      continue;
    }
    d.height = std::max(d.height, x.y());
    if (x.x() < d.xmin) d.xmin = x.x(), d.leftNode = n;
    if (x.x() > d.xmax) d.xmax = x.x(), d.rightNode = n;
  }
  if (!any) return d;
  d.left = std::max(0.0, d.footprintMin - d.xmin);
  d.right = std::max(0.0, d.xmax - d.footprintMax);
  const auto pieces = massPieces(model, state);
  double moment = 0, moment0 = 0;
  const std::vector<MassPiece> start = massPieces(model, State{});
  for (const MassPiece& p : pieces) {
    d.totalMass += p.mass;
    moment += p.mass * 0.5 * (p.x0 + p.x1);
  }
  for (const MassPiece& p : start) moment0 += p.mass * 0.5 * (p.x0 + p.x1);
  if (d.site) d.outsideMass = massOutside(pieces, *d.site);
  if (d.totalMass > 0) {
    d.centroid = moment / d.totalMass;
    d.centroidShift = d.centroid - moment0 / d.totalMass;
  }
  d.left95 = std::max(0.0, d.footprintMin - massQuantile(pieces, 0.05));
  d.right95 = std::max(0.0, massQuantile(pieces, 0.95) - d.footprintMax);
  d.cover = massCover(pieces);
  const std::vector<double> pieceMass = pieceMassAtNodes(model);
  d.leftPieceMass = pieceMass[d.leftNode];
  d.rightPieceMass = pieceMass[d.rightNode];
  return d;
}

namespace {

// f(node, y) for every node in contact with the ground's model: the nodes
// with equations of their own (a shared joint's slave moves with its master,
// whose contact is its own), at their vertical position in the state.
template <class F>
void forEachGroundNode(const Model& model, const DofMap& dofs, const State& state, F&& f) {
  for (int n = 0; n < model.numNodes() && n < dofs.numNodes(); ++n)
    if (dofs.used(n) && !dofs.aliased(n)) f(n, model.coord(n).y() + state.u[n * kNodeDofs + 1]);
}

}  // namespace

double groundForce(const Model& model, const DofMap& dofs, const State& state) {
  const auto& ground = model.ground();
  if (!ground) return 0;
  double f = 0;
  // The contact law's force at this state (a crushed node rests in its set).
  forEachGroundNode(model, dofs, state, [&](int n, double y) {
    f += groundContact(*ground, state.crush[n], y, y, StepRule{}).normal;
  });
  return f;
}

GroundDepth deepestNode(const Model& model, const DofMap& dofs, const State& state) {
  GroundDepth d;
  const auto& ground = model.ground();
  if (!ground) return d;
  forEachGroundNode(model, dofs, state, [&](int n, double y) {
    const double depth = penetration(*ground, y);
    if (depth > 0 && (d.node < 0 || depth > d.depth)) d = GroundDepth{n, depth};
  });
  return d;
}

double halfSectionDepth(const Model& model, int node) {
  double r = 0;
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e))
      for (int n : model.element(e).nodes())
        if (n == node) r = std::max(r, sectionRadius(model, e));
  return r;
}

std::string debrisCsvHeader() {
  return "left,right,height,total_mass,outside_mass,site,site_xmin,site_xmax,peak_ground_force,"
         "peak_time,deepest,deepest_time,centroid,centroid_shift,left95,right95,at_rest,"
         "kinetic_ratio,left_piece_mass,right_piece_mass,footprint_xmin,footprint_xmax";
}

std::string debrisCsvRow(const DebrisFigures& d) {
  std::string row;
  auto cell = [&row](const std::string& text) {
    if (!row.empty()) row += ',';
    row += text;
  };
  for (double v : {d.left, d.right, d.height, d.totalMass, d.outsideMass}) cell(num(v));
  cell(d.siteStatus());
  cell(d.site ? num(d.site->xmin) : std::string());
  cell(d.site ? num(d.site->xmax) : std::string());
  for (double v : {d.peakGroundForce, d.peakTime, d.deepest, d.deepestTime, d.centroid,
                   d.centroidShift, d.left95, d.right95})
    cell(num(v));
  cell(d.atRest() ? "yes" : "no");
  for (double v : {d.kineticRatio, d.leftPieceMass, d.rightPieceMass, d.footprintMin, d.footprintMax})
    cell(num(v));
  return row;
}

std::string debrisLogLines(const DebrisFigures& d) {
  char buf[512];
  std::string out;
  std::snprintf(buf, sizeof buf,
                "  debris: footprint x in [%.4e, %.4e] m, nodes now in [%.4e (node %d), %.4e "
                "(node %d)] m, highest point y = %.4e m\n",
                d.footprintMin, d.footprintMax, d.xmin, d.leftNode + 1, d.xmax, d.rightNode + 1,
                d.height);
  out += buf;
  std::snprintf(buf, sizeof buf,
                "  debris: beyond the footprint %.4e m on the left, %.4e m on the right\n", d.left,
                d.right);
  out += buf;
  if (d.site) {
    std::snprintf(buf, sizeof buf,
                  "  debris: site x in [%.4e, %.4e] m: %s, mass outside %.4e t of %.4e t\n",
                  d.site->xmin, d.site->xmax, d.outside() ? "OUTSIDE the site" : "inside the site",
                  d.outsideMass, d.totalMass);
  } else {
    std::snprintf(buf, sizeof buf, "  debris: no site given (SITE,,xmin,xmax), total mass %.4e t\n",
                  d.totalMass);
  }
  out += buf;
  std::snprintf(buf, sizeof buf,
                "  debris: the furthest points are set by pieces of %.4e t (left) and %.4e t "
                "(right); without the outermost 5 %% of the mass on each side %.4e m on the left, "
                "%.4e m on the right\n",
                d.leftPieceMass, d.rightPieceMass, d.left95, d.right95);
  out += buf;
  std::snprintf(buf, sizeof buf, "  debris: mass centroid x = %.4e m, moved by %.4e m\n",
                d.centroid, d.centroidShift);
  out += buf;
  std::snprintf(buf, sizeof buf, "  debris: %s: kinetic energy %.4e of its peak (at rest at or below %.1e)\n",
                d.atRest() ? "at rest" : "STILL MOVING at the end", d.kineticRatio, d.restRatio);
  out += buf;
  std::snprintf(buf, sizeof buf, "  debris: peak ground force %.4e kN at t = %.4e s\n",
                d.peakGroundForce, d.peakTime);
  out += buf;
  if (d.deepestNode < 0) return out;
  std::snprintf(buf, sizeof buf, "  debris: deepest in the ground %.4e m (node %d at t = %.4e s)",
                d.deepest, d.deepestNode + 1, d.deepestTime);
  out += buf;
  if (d.deepestLimit > 0) {
    std::snprintf(buf, sizeof buf, ", half its members' section depth %.4e m%s", d.deepestLimit,
                  d.sunk() ? ": BURIED, the ground is too soft for the impact (GROUnd's k)" : "");
    out += buf;
  }
  return out + "\n";
}

}  // namespace c2d
