#include "core/contact/MemberCrossing.h"

#include <algorithm>
#include <array>

#include "core/Brace.h"
#include "core/contact/ContactGrid.h"
#include "core/contact/ContactSearch.h"

namespace c2d {

namespace {

// Two members whose centre lines cross within this fraction of their contact
// distance (the sum of their section radii) of an end of each: their tips
// overlap by less than the penalty contact lets them press into each other.
constexpr double kTipOverlap = 0.05;

// Twice the signed area of the triangle (a, b, c).
double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Whether the segments ab and cd cross at a point inside both; if so t is
// where along ab (0 at a, 1 at b) and v along cd.
bool properlyCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double& t,
                   double& v) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (!(((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))))
    return false;
  t = o3 / (o3 - o4);
  v = o1 / (o1 - o2);
  return true;
}

// The end of the member (nodes n) nearer to the crossing at fraction t along
// it, and the distance to it.
void nearEnd(const std::array<int, 2>& n, const Vec2& a, const Vec2& b, double t, int& node,
             double& along) {
  node = t <= 0.5 ? n[0] : n[1];
  along = std::min(t, 1.0 - t) * (b - a).norm();
}

}  // namespace

std::vector<MemberCrossing> findCrossings(const Model& model, const State& s) {
  std::vector<int> live;
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e) && !isBrace(model.element(e))) live.push_back(e);
  const int ne = static_cast<int>(live.size());
  const std::vector<int> group = jointGroups(model);
  auto at = [&](int n) { return nodePosition(model, s.u, n); };
  std::vector<Box> boxes(ne);
  for (int i = 0; i < ne; ++i) {
    const auto nodes = model.element(live[i]).nodes();
    const Vec2 a = at(nodes[0]), b = at(nodes[1]);
    boxes[i] = Box::point(a.x(), a.y());
    boxes[i].add(b.x(), b.y());
  }
  ContactGrid grid;
  grid.build(boxes, 1e-9 * model.characteristicLength());
  std::vector<MemberCrossing> out;
  for (int i = 0; i < ne; ++i) {
    const int e = live[i];
    const auto ne1 = model.element(e).nodes();
    const Vec2 a = at(ne1[0]), b = at(ne1[1]);
    grid.query(boxes[i], [&](int j) {
      const int f = live[j];
      if (f <= e) return;
      const auto ne2 = model.element(f).nodes();
      for (int m : ne1)
        for (int n : ne2)
          if (group[m] == group[n]) return;
      const Vec2 c = at(ne2[0]), d = at(ne2[1]);
      double t = 0.0, v = 0.0;
      if (!properlyCross(a, b, c, d, t, v)) return;
      MemberCrossing m;
      m.first = e;
      m.second = f;
      m.point = a + t * (b - a);
      nearEnd(ne1, a, b, t, m.nearNode[0], m.fromNode[0]);
      nearEnd(ne2, c, d, v, m.nearNode[1], m.fromNode[1]);
      const double tip = kTipOverlap * (sectionRadius(model, e) + sectionRadius(model, f));
      if (m.fromNode[0] < tip && m.fromNode[1] < tip) return;  // tips pressed together
      out.push_back(m);
    });
  }
  std::sort(out.begin(), out.end(), [](const MemberCrossing& p, const MemberCrossing& q) {
    return p.first != q.first ? p.first < q.first : p.second < q.second;
  });
  return out;
}

}  // namespace c2d
