#include "macro/output/DebrisZones.h"

#include <algorithm>
#include <set>

#include "macro/output/Debris.h"

namespace c2d {

double flyrockLimit(const Site& site, double total) {
  return site.flyrockMass >= 0 ? site.flyrockMass : kFlyrockShare * total;
}

double shareInZone(const Vec2& a, const Vec2& b, double x1, double x2, double ymin) {
  // Clip the segment a + t (b - a), t in [0, 1], to the half-open box.
  double t0 = 0, t1 = 1;
  const Vec2 d = b - a;
  auto clip = [&](double p, double q) {  // keep where p t <= q
    if (p == 0) return q >= 0;
    const double r = q / p;
    if (p < 0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
    return t0 <= t1;
  };
  if (!clip(-d.x(), a.x() - x1) || !clip(d.x(), x2 - a.x()) || !clip(-d.y(), a.y() - ymin))
    return 0;
  if (d.squaredNorm() == 0) return 1;
  return std::max(0.0, t1 - t0);
}

std::vector<ZoneFigures> zoneFigures(const Model& model, const State& state, const Site& site,
                                     double limit) {
  const double ground = model.ground() ? model.ground()->y0 : 0.0;
  const std::vector<MassPiece> all = massPieces(model, state);
  const std::vector<int> piece = pieceOfNodes(model);
  const std::vector<double> pieceMass = pieceMassAtNodes(model);
  std::vector<ZoneFigures> out;
  for (const ProtectedZone& z : protectedZones(site)) {
    ZoneFigures f;
    f.name = z.name;
    f.x1 = z.x1;
    f.x2 = z.x2;
    std::set<int> fragments;
    // A zone at height 0 takes debris at any height (also below the ground line).
    const double ymin = z.height > 0 ? ground + z.height : -kUnbounded;
    for (const MassPiece& p : all) {
      const double m =
          p.mass * shareInZone(Vec2(p.x0, p.y0), Vec2(p.x1, p.y1), z.x1, z.x2, ymin);
      if (m <= 0) continue;
      const double whole = pieceMass[p.node];
      f.heaviest = std::max(f.heaviest, whole);
      if (whole < limit) {
        fragments.insert(piece[p.node]);
        f.flyrockMass += m;
      } else {
        f.mass += m;
      }
    }
    f.flyrockCount = static_cast<int>(fragments.size());
    f.hit = f.mass > z.mass;
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace c2d
