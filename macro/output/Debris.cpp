#include "macro/output/Debris.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Brace.h"
#include "macro/output/DebrisZones.h"
#include "core/FloorLoad.h"
#include "core/contact/ContactSearch.h"
#include "core/contact/GroundContact.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

Vec2 position(const Model& model, const State& s, int n) {
  const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs;
  const Vec2 u = i + 1 < s.u.size() ? Vec2(s.u[i], s.u[i + 1]) : Vec2::Zero();
  return model.coord(n) + u;
}

std::string num(double v) { return formatNumber("%.6e", v); }

}  // namespace

bool DebrisFigures::outside() const { return site && (xmin < site->xmin || xmax > site->xmax); }

bool DebrisFigures::unintendedFall() const { return site && unintended(site->dir, verdict); }

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
    const Vec2 a = position(model, state, n[0]), b = position(model, state, n[1]);
    if (isBrace(model.element(e))) {  // a wall's mass lies at the frame's nodes
      pieces.push_back({a.x(), a.x(), 0.5 * m, a.y(), a.y(), n[0]});
      pieces.push_back({b.x(), b.x(), 0.5 * m, b.y(), b.y(), n[1]});
      continue;
    }
    if (a.x() <= b.x())
      pieces.push_back({a.x(), b.x(), m, a.y(), b.y(), n[0]});
    else
      pieces.push_back({b.x(), a.x(), m, b.y(), a.y(), n[0]});
  }
  const std::vector<char> held = model.heldNodes();
  for (int n = 0; n < model.numNodes(); ++n) {
    const double m = nodalPointMass(model, n);
    if (m <= 0 || !model.hasCoord(n) || !held[n]) continue;
    const Vec2 x = position(model, state, n);
    pieces.push_back({x.x(), x.x(), m, x.y(), x.y(), n});
  }
  return pieces;
}

std::vector<int> pieceOfNodes(const Model& model) {
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
  for (int n = 0; n < nn; ++n) parent[n] = root(n);
  return parent;
}

std::vector<double> pieceMassAtNodes(const Model& model) {
  const int nn = model.numNodes();
  const std::vector<int> root = pieceOfNodes(model);
  std::vector<double> mass(static_cast<std::size_t>(nn), 0.0);
  const std::vector<double> carried = carriedMass(model);
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e)) {
      const auto n = model.element(e).nodes();
      const double m = std::max(0.0, elementMass(model, e, carried));
      if (isBrace(model.element(e))) {
        mass[root[n[0]]] += 0.5 * m;
        mass[root[n[1]]] += 0.5 * m;
      } else {
        mass[root[n[0]]] += m;
      }
    }
  const std::vector<char> held = model.heldNodes();
  for (int n = 0; n < nn; ++n)
    if (held[n] && model.hasCoord(n)) mass[root[n]] += nodalPointMass(model, n);
  std::vector<double> out(static_cast<std::size_t>(nn), 0.0);
  for (int n = 0; n < nn; ++n)
    if (held[n]) out[n] = mass[root[n]];
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

namespace {

// The footprint: the x-extent of every node of the building at the start.
void footprintOf(const Model& model, DebrisFigures& d) {
  bool any = false;
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n)) continue;
    const double x0 = model.coord(n).x();
    d.footprintMin = any ? std::min(d.footprintMin, x0) : x0;
    d.footprintMax = any ? std::max(d.footprintMax, x0) : x0;
    any = true;
  }
}

// Where the bed lies: the extent and highest point of the nodes still held by
// elements (a removed member's nodes are gone) in pieces of the bed. False: none.
bool bedExtent(const Model& model, const State& state, const std::vector<char>& bed,
               DebrisFigures& d) {
  bool any = false;
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n) || !bed[n]) continue;
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
  return any;
}

// The heaviest piece (pieceMass at its nodes) with a node of the model left of
// `lo` or right of `hi` now; 0 when none. A node on a line (to 1e-9 of the
// footprint's width) is not beyond it.
double heaviestBeyond(const Model& model, const State& state, const std::vector<double>& pieceMass,
                      double lo, double hi) {
  const double tol = 1e-9 * std::max(1.0, hi - lo);
  const std::vector<char> held = model.heldNodes();
  double heaviest = 0;
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n) || !held[n]) continue;
    const double x = position(model, state, n).x();
    if (x < lo - tol || x > hi + tol) heaviest = std::max(heaviest, pieceMass[n]);
  }
  return heaviest;
}

// The pieces whose node is in the bed.
std::vector<MassPiece> inBed(std::vector<MassPiece> pieces, const std::vector<char>& bed) {
  std::erase_if(pieces, [&](const MassPiece& p) { return p.node >= 0 && !bed[p.node]; });
  return pieces;
}

}  // namespace

DebrisFigures debrisFigures(const Model& model, const State& state) {
  DebrisFigures d;
  d.site = model.site();
  footprintOf(model, d);
  const std::vector<MassPiece> all = massPieces(model, state);
  for (const MassPiece& p : all) d.totalMass += p.mass;
  // With a site, the pieces lighter than its flyrock limit fly apart from the
  // bed (macro/output/DebrisZones.h): the bed's figures leave them out.
  const std::vector<double> pieceMass = pieceMassAtNodes(model);
  std::vector<char> bed = model.heldNodes();
  if (d.site) {
    d.flyrockLimit = flyrockLimit(*d.site, d.totalMass);
    std::vector<char> kept = bed;
    for (int n = 0; n < model.numNodes(); ++n) kept[n] = bed[n] && pieceMass[n] >= d.flyrockLimit;
    if (std::find(kept.begin(), kept.end(), 1) != kept.end()) bed = kept;
  }
  if (!bedExtent(model, state, bed, d)) return d;
  d.left = std::max(0.0, d.footprintMin - d.xmin);
  d.right = std::max(0.0, d.xmax - d.footprintMax);
  const std::vector<MassPiece> pieces = inBed(all, bed);
  const std::vector<MassPiece> start = inBed(massPieces(model, State{}), bed);
  double moment = 0, moment0 = 0, bedMass = 0;
  for (const MassPiece& p : pieces) {
    bedMass += p.mass;
    moment += p.mass * 0.5 * (p.x0 + p.x1);
  }
  for (const MassPiece& p : start) moment0 += p.mass * 0.5 * (p.x0 + p.x1);
  if (d.site) d.outsideMass = massOutside(pieces, *d.site);
  if (bedMass > 0) {
    d.centroid = moment / bedMass;
    d.centroidShift = d.centroid - moment0 / bedMass;
  }
  d.left95 = std::max(0.0, d.footprintMin - massQuantile(pieces, 0.05));
  d.right95 = std::max(0.0, massQuantile(pieces, 0.95) - d.footprintMax);
  d.cover = massCover(all);
  d.leftPieceMass = pieceMass[d.leftNode];
  d.rightPieceMass = pieceMass[d.rightNode];
  d.heaviestBeyond95 = heaviestBeyond(model, state, pieceMass, d.footprintMin - d.left95,
                                      d.footprintMax + d.right95);
  d.buildingHeight = buildingHeight(model);
  d.tilt = standingTilt(model, state);
  if (d.site) {
    d.verdict = fallVerdict(d.site->dir, d.centroidShift, d.buildingHeight,
                            d.footprintMax - d.footprintMin);
    d.zones = zoneFigures(model, state, *d.site, d.flyrockLimit);
    for (const MassPiece& p : all)
      if (p.node >= 0 && !bed[p.node]) d.flyrockMass += p.mass;
    const std::vector<int> roots = pieceOfNodes(model);
    const std::vector<char> held = model.heldNodes();
    std::vector<char> seen(roots.size(), 0);
    for (int n = 0; n < model.numNodes(); ++n)
      if (held[n] && !bed[n] && !seen[roots[n]]) seen[roots[n]] = 1, ++d.flyrockCount;
  }
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
         "kinetic_ratio,left_piece_mass,right_piece_mass,heaviest_beyond95,footprint_xmin,footprint_xmax,verdict,"
         "centroid_move_h,tilt,building_height,flyrock_limit,flyrock_count,flyrock_mass,"
         "risk_level,risk_confidence";
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
  for (double v : {d.kineticRatio, d.leftPieceMass, d.rightPieceMass, d.heaviestBeyond95,
                   d.footprintMin, d.footprintMax})
    cell(num(v));
  cell(fallVerdictName(d.verdict));
  for (double v : {d.centroidMoveH(), d.tilt, d.buildingHeight, d.flyrockLimit}) cell(num(v));
  cell(std::to_string(d.flyrockCount));
  cell(num(d.flyrockMass));
  cell(d.site ? num(d.site->riskLevel) : std::string());
  cell(d.site ? num(d.site->riskConfidence) : std::string());
  return row;
}

const std::vector<std::string> kZoneColumns = {"mass_",          "hit_",          "heaviest_",
                                               "flyrock_count_", "flyrock_mass_", "x1_",
                                               "x2_"};

std::string zoneCsvHeader(const std::vector<std::string>& zones) {
  std::string h;
  for (const std::string& z : zones)
    for (const std::string& c : kZoneColumns) h += (h.empty() ? "" : ",") + c + z;
  return h;
}

std::string zoneCsvCells(const DebrisFigures& d, const std::vector<std::string>& zones) {
  std::string row;
  for (const std::string& name : zones) {
    const auto z = std::find_if(d.zones.begin(), d.zones.end(),
                                [&](const ZoneFigures& f) { return f.name == name; });
    const bool has = z != d.zones.end();
    for (const std::string& cell :
         {has ? num(z->mass) : "", has ? std::string(z->hit ? "1" : "0") : "",
          has ? num(z->heaviest) : "", has ? std::to_string(z->flyrockCount) : "",
          has ? num(z->flyrockMass) : "", has && std::isfinite(z->x1) ? num(z->x1) : "",
          has && std::isfinite(z->x2) ? num(z->x2) : ""})
      row += (row.empty() ? "" : ",") + cell;
  }
  return row;
}

std::vector<std::string> zoneNames(const std::optional<Site>& site) {
  std::vector<std::string> names;
  if (site)
    for (const ProtectedZone& z : protectedZones(*site)) names.push_back(z.name);
  return names;
}

std::string debrisCsvHeader(const std::vector<std::string>& zones) {
  return zones.empty() ? debrisCsvHeader() : debrisCsvHeader() + "," + zoneCsvHeader(zones);
}

std::string debrisCsvRow(const DebrisFigures& d, const std::vector<std::string>& zones) {
  return zones.empty() ? debrisCsvRow(d) : debrisCsvRow(d) + "," + zoneCsvCells(d, zones);
}

std::vector<std::string> zoneNames(const DebrisFigures& d) {
  std::vector<std::string> names;
  for (const ZoneFigures& z : d.zones) names.push_back(z.name);
  return names;
}

namespace {

// The verdict's line: where the building went against where it was meant to go.
std::string fallLogLine(const DebrisFigures& d) {
  char buf[512];
  const double h = d.buildingHeight, w = d.footprintMax - d.footprintMin;
  if (!d.site || d.site->dir == FallDirection::None) {
    std::snprintf(buf, sizeof buf,
                  "  debris: the centroid moved %.4g H (H = %.4g m), the standing part tilts at "
                  "most %.3g deg; no intended fall given (SITE's dir)\n",
                  d.centroidMoveH(), h, d.tilt);
    return buf;
  }
  const double t = fellingThreshold(h, w);
  std::snprintf(buf, sizeof buf,
                "  debris: %s (intended %s): the centroid moved %.4e m = %.4g H (threshold T = "
                "%.4e m, H = %.4e m, W = %.4e m), the standing part tilts at most %.3g deg%s\n",
                fallVerdictName(d.verdict), fallDirectionName(d.site->dir), d.centroidShift,
                d.centroidMoveH(), t, h, w, d.tilt,
                d.unintendedFall() ? ": NOT AS INTENDED" : "");
  return buf;
}

// The flying fragments and every protected zone, one line each.
std::string zoneLogLines(const DebrisFigures& d) {
  if (!d.site) return {};
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "  debris: flying fragments (pieces below %.4e t, left out of the bed's figures): "
                "%d, %.4e t\n",
                d.flyrockLimit, d.flyrockCount, d.flyrockMass);
  std::string out = buf;
  for (const ZoneFigures& z : d.zones) {
    std::snprintf(buf, sizeof buf,
                  "  debris: zone %s: %.4e t of the bed%s, heaviest piece there %.4e t, %d "
                  "fragment%s (%.4e t)\n",
                  z.name.c_str(), z.mass, z.hit ? ": HIT" : "", z.heaviest, z.flyrockCount,
                  z.flyrockCount == 1 ? "" : "s", z.flyrockMass);
    out += buf;
  }
  return out;
}

}  // namespace

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
                "%.4e m on the right; the heaviest piece beyond those %.4e t\n",
                d.leftPieceMass, d.rightPieceMass, d.left95, d.right95, d.heaviestBeyond95);
  out += buf;
  std::snprintf(buf, sizeof buf, "  debris: mass centroid x = %.4e m, moved by %.4e m\n",
                d.centroid, d.centroidShift);
  out += buf;
  out += fallLogLine(d);
  out += zoneLogLines(d);
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
