#include "core/MemberCrossing.h"

#include <algorithm>

#include "core/ContactGrid.h"
#include "core/MemberContact.h"

namespace c2d {

namespace {

// Twice the signed area of the triangle (a, b, c).
double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool properlyCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

}  // namespace

std::vector<MemberCrossing> findCrossings(const Model& model, const State& s) {
  std::vector<int> live;
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e)) live.push_back(e);
  const int ne = static_cast<int>(live.size());
  const std::vector<int> group = jointGroups(model);
  auto at = [&](int n) {
    return Vec2(model.coord(n).x() + s.u[3 * n], model.coord(n).y() + s.u[3 * n + 1]);
  };
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
      if (properlyCross(a, b, at(ne2[0]), at(ne2[1]))) out.push_back({e, f});
    });
  }
  std::sort(out.begin(), out.end(), [](const MemberCrossing& p, const MemberCrossing& q) {
    return p.first != q.first ? p.first < q.first : p.second < q.second;
  });
  return out;
}

}  // namespace c2d
