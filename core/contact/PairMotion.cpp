#include "core/contact/PairMotion.h"

#include <algorithm>

#include "core/contact/CrushingLaw.h"

namespace c2d {

PairPositions pairValues(const Eigen::VectorXd& nodal, const ContactPair& pair) {
  auto at = [&](int n) { return Vec2(nodal[3 * n], nodal[3 * n + 1]); };
  return {at(pair.node), at(pair.a), at(pair.b)};
}

double pairMass(const std::vector<double>& masses, const ContactPair& pair,
                const PairPositions& q) {
  const double mx = masses[pair.node], ma = masses[pair.a], mb = masses[pair.b];
  if (mx <= 0 || ma <= 0 || mb <= 0) return 0.0;
  const Vec2 t = q.b - q.a;
  const double l2 = t.squaredNorm();
  const double xi = l2 > 0 ? std::clamp((q.x - q.a).dot(t) / l2, 0.0, 1.0) : 0.5;
  return 1.0 / (1.0 / mx + (1 - xi) * (1 - xi) / ma + xi * xi / mb);
}

double pairLoadingPoint(const MemberContactData& data, const std::vector<double>& masses,
                        const ContactPair& pair, const State& s, const PairPositions& q0,
                        const PairPositions& q1, int side, double h, double face, double q,
                        double p1) {
  if (data.restitution >= 1 || p1 <= 0) return crushingLoadingPoint(q, p1);
  const double r0 = pairPenetrationRate(q0, pairValues(s.vn, pair), side, h, face);
  const double r1 = pairPenetrationRate(q1, pairValues(s.v, pair), side, h, face);
  return crushingLoadingPoint(data.k, data.restitution, q, pairMass(masses, pair, q0), p1, r0, r1);
}

}  // namespace c2d
