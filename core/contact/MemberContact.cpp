#include "core/contact/MemberContact.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/contact/ContactDamper.h"
#include "core/contact/CrushingLaw.h"
#include "core/NodeMass.h"
#include "core/contact/PairMotion.h"
#include "core/contact/SpringFriction.h"

namespace c2d {

namespace {

using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat4 = Eigen::Matrix<double, 4, 4>;
using Mat2 = Eigen::Matrix2d;

// Penetration, its gradient and Hessian with respect to z = (r1, r2),
// r1 = x - a, r2 = b - a.
struct Penetration {
  double p = 0;
  Vec4 g = Vec4::Zero();
  Mat4 H = Mat4::Zero();
};

Vec2 perp(const Vec2& v) { return Vec2(-v.y(), v.x()); }  // J v: v turned by +90 degrees

// Held sides (the pairs of a ruptured joint), as fractions of the contact
// distance: a node this close to a segment is on it, a member whose far end
// is this close to the segment's line lies along it, and a held node this far
// clear of the line (or around the end) is let go.
constexpr double kOnSegment = 1e-6, kAlongLine = 1e-3, kLetGo = 0.25;

// The node's position along the segment, c = r1.r2 / |r2| (measured from a),
// its gradient and Hessian in z: the coordinate of the pair's friction.
void slipCoordinate(const Vec4& z, bool wantHessian, Penetration& out) {
  out.g.setZero();
  if (wantHessian) out.H.setZero();
  const Vec2 r1 = z.head<2>(), r2 = z.tail<2>();
  const double l2 = r2.squaredNorm();
  out.p = 0;
  if (l2 == 0) return;
  const double l = std::sqrt(l2), l3 = l2 * l;
  const double c = r1.dot(r2) / l;
  out.p = c;
  out.g.head<2>() = r2 / l;
  out.g.tail<2>() = r1 / l - c * r2 / l2;
  if (!wantHessian) return;
  const Mat2 h12 = Mat2::Identity() / l - r2 * r2.transpose() / l3;
  const Mat2 h22 = -(r1 * r2.transpose() + r2 * r1.transpose()) / l3 +
                   3 * c * r2 * r2.transpose() / (l2 * l2) - c * Mat2::Identity() / l2;
  out.H.topRightCorner<2, 2>() = h12;
  out.H.bottomLeftCorner<2, 2>() = h12.transpose();
  out.H.bottomRightCorner<2, 2>() = h22;
}

// Rounded end: p = h - |r| with r = r1 (end a, sign = 0) or r1 - r2 (end b).
void endPenetration(const Vec2& r, bool endB, double h, bool wantHessian, Penetration& out) {
  const double dist = r.norm();
  out.p = h - dist;
  if (dist == 0) return;  // the node on the end point itself: no direction
  const Vec2 e = r / dist;
  out.g.head<2>() = -e;
  out.g.tail<2>() = endB ? e : Vec2::Zero();
  if (!wantHessian) return;
  const Mat2 P = -(Mat2::Identity() - e * e.transpose()) / dist;
  out.H.topLeftCorner<2, 2>() = P;
  if (endB) {
    out.H.topRightCorner<2, 2>() = -P;
    out.H.bottomLeftCorner<2, 2>() = -P;
    out.H.bottomRightCorner<2, 2>() = P;
  }
}

// The side's penetration p = h - s d, d = (r2 x r1) / |r2| the signed
// distance from the segment's line.
void sidePenetration(const Vec4& z, int side, double h, bool wantHessian, Penetration& out) {
  const Vec2 r1 = z.head<2>(), r2 = z.tail<2>();
  const double l2 = r2.squaredNorm();
  const double l = std::sqrt(l2), l3 = l2 * l;
  const double c = r2.x() * r1.y() - r2.y() * r1.x();
  const double s = side;
  out.p = h - s * c / l;
  const Vec2 jr1 = perp(r1), jr2 = perp(r2);
  out.g.head<2>() = -s * jr2 / l;
  out.g.tail<2>() = -s * (-jr1 / l - c * r2 / l3);
  if (!wantHessian) return;
  Mat2 J;
  J << 0, -1, 1, 0;
  const Mat2 h12 = J / l - jr2 * r2.transpose() / l3;
  const Mat2 h22 = (jr1 * r2.transpose() + r2 * jr1.transpose()) / l3 - c * Mat2::Identity() / l3 +
                   3 * c * r2 * r2.transpose() / (l2 * l3);
  out.H.topRightCorner<2, 2>() = -s * h12;
  out.H.bottomLeftCorner<2, 2>() = -s * h12.transpose();
  out.H.bottomRightCorner<2, 2>() = -s * h22;
}

void penetration(const Vec4& z, int side, double h, bool wantHessian, Penetration& out,
                 bool held = false) {
  out.g.setZero();
  if (wantHessian) out.H.setZero();
  const Vec2 r1 = z.head<2>(), r2 = z.tail<2>();
  const double l2 = r2.squaredNorm();
  if (l2 == 0) return endPenetration(r1, false, h, wantHessian, out);
  const double xi = r1.dot(r2) / l2;
  if (xi < 0 || xi > 1) {
    // A held node beyond an end on the wrong side: with rho its distance from
    // the end point and e its distance beyond the end along the segment,
    // p = h + rho - 2 e^2 / rho = h + (d^2 - e^2) / rho. It is the span's
    // h + |d| where e = 0 (value and slope), and the rounded end's h - rho
    // where the node crosses the line beyond the end (d = 0: value and slope
    // again), so that a node held end to end with the member (a ruptured
    // joint's pieces in line) meets no kink in its force there.
    if (held && side * (r2.x() * r1.y() - r2.y() * r1.x()) < 0) {
      const Vec2 r = xi < 0 ? r1 : Vec2(r1 - r2);
      Penetration end;  // -rho, -grad rho, -Hess rho
      endPenetration(r, xi > 1, 0.0, wantHessian, end);
      const double rho = -end.p;
      if (rho == 0) return endPenetration(r, xi > 1, h, wantHessian, out);
      Penetration e;
      slipCoordinate(z, wantHessian, e);  // c, measured from a
      if (xi > 1) {                       // e = c - l
        const double l = std::sqrt(l2);
        e.p -= l;
        e.g.tail<2>() -= r2 / l;
        if (wantHessian)
          e.H.bottomRightCorner<2, 2>() -= (Mat2::Identity() - r2 * r2.transpose() / l2) / l;
      } else {  // e = -c
        e.p = -e.p;
        e.g = -e.g;
        if (wantHessian) e.H = -e.H;
      }
      const double ee = e.p, a = 2 * ee * ee / (rho * rho), b = 4 * ee / rho;
      const Vec4 gr = -end.g;
      out.p = h + rho - 2 * ee * ee / rho;
      out.g = (1 + a) * gr - b * e.g;
      if (wantHessian) {
        const Vec4 da = (b / rho) * e.g - (2 * a / rho) * gr;  // grad a
        const Vec4 db = (4 / rho) * e.g - (b / rho) * gr;      // grad b
        out.H = -(1 + a) * end.H + gr * da.transpose() - b * e.H - e.g * db.transpose();
      }
      return;
    }
    return xi < 0 ? endPenetration(r1, false, h, wantHessian, out)
                  : endPenetration(r1 - r2, true, h, wantHessian, out);
  }
  sidePenetration(z, side, h, wantHessian, out);
}

Vec4 relative(const PairPositions& q) {
  Vec4 z;
  z << q.x - q.a, q.b - q.a;
  return z;
}

// Force and tangent in z to the node and segment translations (x, a, b):
// r1 = x - a, r2 = b - a.
void toPair(const Vec4& fz, const Mat4* kz, PairVec& f, PairMat* k) {
  f.segment<2>(0) = fz.head<2>();
  f.segment<2>(2) = -fz.head<2>() - fz.tail<2>();
  f.segment<2>(4) = fz.tail<2>();
  if (!kz) return;
  Eigen::Matrix<double, 4, 6> B = Eigen::Matrix<double, 4, 6>::Zero();
  B.block<2, 2>(0, 0).setIdentity();
  B.block<2, 2>(0, 2) = -Mat2::Identity();
  B.block<2, 2>(2, 2) = -Mat2::Identity();
  B.block<2, 2>(2, 4).setIdentity();
  *k = B.transpose() * (*kz) * B;
}

}  // namespace

int pairSide(const PairPositions& q) {
  const Vec2 r1 = q.x - q.a, r2 = q.b - q.a;
  return r2.x() * r1.y() - r2.y() * r1.x() >= 0 ? 1 : -1;
}

double pairPenetration(const PairPositions& q, int side, double h, bool held) {
  Penetration p;
  penetration(relative(q), side, h, false, p, held);
  return p.p;
}

double pairPenetrationRate(const PairPositions& q, const PairPositions& v, int side, double h,
                           bool held) {
  Penetration p;
  penetration(relative(q), side, h, false, p, held);
  return p.g.dot(relative(v));
}

namespace {

// The discrete gradient (Gonzalez) of a function f of z between z0 and z1:
// D = grad f(z_m) + (f1 - f0 - grad f(z_m).dz) dz / |dz|^2, so that D.dz = f1 - f0,
// and, times w, its derivative with respect to z1 (wdD). em: f at z_m with its
// Hessian; g1: grad f(z1). Below a relative step of 1e-7 the correction,
// O(|dz|^2), is left out: there its round-off (eps |z| / |dz|) would exceed it.
Vec4 discreteGradient(const Vec4& z0, const Vec4& z1, double f0, double f1, const Penetration& em,
                      const Vec4& g1, double scale, double w, Mat4* wdD) {
  const Vec4 dz = z1 - z0;
  const double n2 = dz.squaredNorm();
  const bool corrected = n2 > 1e-14 * scale * scale;
  Vec4 D = em.g;
  double c = 0;
  if (corrected) {
    c = (f1 - f0 - em.g.dot(dz)) / n2;
    D += c * dz;
  }
  if (wdD) {
    *wdD = 0.5 * w * em.H;
    if (corrected) {
      const Vec4 dc = (g1 - em.g - 0.5 * em.H * dz) / n2 - 2 * c * dz / n2;
      *wdD += w * (c * Mat4::Identity() + dz * dc.transpose());
    }
  }
  return D;
}

}  // namespace

bool pairContact(const PairPositions& q0, const PairPositions& q1, int side, double h,
                 const PairLaw& law, const StepRule& rule, bool wantTangent, PairVec& force,
                 PairMat& tangent, PairOutcome* outcome, bool held) {
  const Vec4 z0 = relative(q0), z1 = relative(q1);
  const double k = law.k;
  const bool midPoint = rule.scheme == Scheme::MidPoint;
  const bool rubs = law.mu > 0;
  Penetration e0, e1;
  penetration(z0, side, h, false, e0, held);
  penetration(z1, side, h, wantTangent && !midPoint, e1, held);
  const double p0 = e0.p, p1 = e1.p;
  if (outcome) *outcome = PairOutcome{p0, p1, 0.0, 0.0};
  // Out of contact over the step: no force, and the friction spring lets go.
  const bool touches = midPoint ? (p0 > 0 || p1 > 0) : p1 > 0;
  if (!touches) {
    if (outcome) outcome->slipped = springFrictionEnergy(k, law.stretch);
    return false;
  }
  // The normal law: w, its derivative dw w.r.t. p1, and the normal force N
  // (without the dissipative term) with dN/dp1.
  double w = 0, dw = 0;
  const CrushingLaw normal(k, law.restitution, std::max(law.q, p0));
  if (!midPoint) {
    w = normal.force(p1);
    dw = normal.slope(p1);
  } else {
    normal.midPoint(p0, p1, w, dw);  // phi'(p0, p1): the law's discrete derivative
  }
  // The dashpot: along D with the penalty (mid-point), along grad p at t_n+1
  // with the rate dp/dt = grad p . dz/dt there (Newmark, below).
  const bool damped = law.c > 0 && rule.dynamic();
  if (damped && midPoint) {
    const DamperForce f = damperForce(law.c, normal.ps, p0, p1, 0.0, 0.0, rule);
    w += f.force;
    dw += f.slope;
  }
  // Friction's N: the whole normal force while it pushes (the dashpot's too),
  // and dN/dz1.
  // Newmark's dashpot c r dp/dt ramps in over the step's motion beyond the set
  // as the ground's does (ContactDamper: r from 0 where the pair begins or
  // ends touching, so that the force is continuous there).
  const bool newmarkDamped = damped && !midPoint && p1 > normal.ps;
  const DamperRamp ramp = newmarkDamped ? damperRamp(normal.ps, p0, p1) : DamperRamp{};
  const double cr = law.c * ramp.w;
  const Vec4 rate1 =
      newmarkDamped ? Vec4(rule.velocity(Vec4(z1 - z0), law.zv, law.za)) : Vec4(Vec4::Zero());
  const double r1 = e1.g.dot(rate1);  // dp/dt at t_n+1
  // d(c r dp/dt)/dz1
  const Vec4 dDamper =
      newmarkDamped ? Vec4(cr * (rule.cv * e1.g + e1.H * rate1) + law.c * ramp.slope * r1 * e1.g)
                    : Vec4(Vec4::Zero());
  const double w1 = w + cr * r1;
  const double N = std::max(w1, 0.0);
  Vec4 dNdz = Vec4::Zero();
  if (rubs && w1 > 0 && wantTangent) dNdz = dw * e1.g + dDamper;
  const double scale = z0.norm() + z1.norm() + h;
  Vec4 fz;
  Mat4 kz, wdD;
  if (!midPoint) {
    fz = w * e1.g;
    if (wantTangent) kz = dw * e1.g * e1.g.transpose() + w * e1.H;
    if (newmarkDamped) {
      fz += cr * r1 * e1.g;
      if (wantTangent) kz += e1.g * dDamper.transpose() + cr * r1 * e1.H;
    }
  } else {
    Penetration em;
    penetration(0.5 * (z0 + z1), side, h, wantTangent, em, held);
    const Vec4 D = discreteGradient(z0, z1, p0, p1, em, e1.g, scale, w, wantTangent ? &wdD : nullptr);
    fz = w * D;
    if (wantTangent) kz = D * (dw * e1.g).transpose() + wdD;
  }
  // Friction along the segment: the spring law on the slip coordinate c, its
  // force F = -f on c (an internal force, as the penalty's) through the
  // coordinate's gradient (discrete gradient under the mid-point scheme).
  if (rubs) {
    Penetration c0, c1;
    slipCoordinate(z0, false, c0);
    slipCoordinate(z1, wantTangent && !midPoint, c1);
    const SpringFrictionForce fr =
        springFriction(k, law.stick, law.mu, N, c0.p - law.stretch, c0.p, c1.p,
                       rule.dynamic() ? rule.h : 0.0, midPoint);
    const double F = -fr.force;
    if (outcome) {
      outcome->stretch = c1.p - fr.anchor;
      outcome->slipped = fr.slipped;
    }
    const Vec4 dF = -fr.dx * c1.g - fr.dN * dNdz;  // dF/dz1
    if (!midPoint) {
      fz += F * c1.g;
      if (wantTangent) kz += c1.g * dF.transpose() + F * c1.H;
    } else {
      Penetration cm;
      slipCoordinate(0.5 * (z0 + z1), wantTangent, cm);
      const Vec4 Dc =
          discreteGradient(z0, z1, c0.p, c1.p, cm, c1.g, scale, F, wantTangent ? &wdD : nullptr);
      fz += F * Dc;
      if (wantTangent) kz += Dc * dF.transpose() + wdD;
    }
  }
  toPair(fz, wantTangent ? &kz : nullptr, force, wantTangent ? &tangent : nullptr);
  return true;
}

namespace {

// Joint groups merged further with the nodes at one reference position: the
// nodes of the original mesh (a joint that ruptured still joins its two nodes
// here).
std::vector<int> originalGroups(const Model& model, const std::vector<int>& groups) {
  const int nn = model.numNodes();
  std::vector<int> parent = groups, order(nn);
  auto find = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const Vec2 &x = model.coord(a), &y = model.coord(b);
    return x.x() < y.x() || (x.x() == y.x() && x.y() < y.y());
  };
  std::sort(order.begin(), order.end(), less);
  for (int i = 1; i < nn; ++i)
    if (!less(order[i - 1], order[i])) {
      const int a = find(order[i - 1]), b = find(order[i]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  for (int n = 0; n < nn; ++n) parent[n] = find(n);
  return parent;
}

// The node groups joined by the live elements.
class GroupGraph {
 public:
  GroupGraph(const Model& model, const std::vector<int>& live, std::vector<int> group)
      : model_(model), group_(std::move(group)), start_(group_.size() + 1, 0) {
    for (int e : live)
      for (int n : model.element(e).nodes()) ++start_[group_[n] + 1];
    for (std::size_t g = 1; g < start_.size(); ++g) start_[g] += start_[g - 1];
    elements_.resize(start_.back());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (int e : live)
      for (int n : model.element(e).nodes()) elements_[fill[group_[n]]++] = e;
  }
  // Elements on the shortest path from node n's group to a node of element e
  // (0: e has a node in it), counted up to maxHops; beyond: maxHops + 1.
  int hops(int n, int e, int maxHops) const {
    const auto target = model_.element(e).nodes();
    std::vector<int> frontier{group_[n]}, seen{group_[n]}, next;
    for (int depth = 0; depth <= maxHops; ++depth) {
      for (int g : frontier)
        if (g == group_[target[0]] || g == group_[target[1]]) return depth;
      next.clear();
      for (int g : frontier)
        for (int i = start_[g]; i < start_[g + 1]; ++i)
          for (int m : model_.element(elements_[i]).nodes())
            if (std::find(seen.begin(), seen.end(), group_[m]) == seen.end()) {
              seen.push_back(group_[m]);
              next.push_back(group_[m]);
            }
      frontier.swap(next);
    }
    return maxHops + 1;
  }

 private:
  const Model& model_;
  std::vector<int> group_;
  std::vector<int> start_, elements_;
};

}  // namespace

double sectionRadius(const Model& model, int element) {
  const MaterialSet* m = model.material(model.element(element).materialNumber());
  return m && m->A > 0 && m->I > 0 ? std::sqrt(3 * m->I / m->A) : 0.0;
}

std::vector<int> jointGroups(const Model& model) {
  std::vector<int> parent(model.numNodes());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (const Joint& j : model.joints()) {
    const int a = find(j.master), b = find(j.slave);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  for (int n = 0; n < model.numNodes(); ++n) parent[n] = find(n);
  return parent;
}

// ---------------------------------------------------------------------------

MemberContact::MemberContact(const Model& model, const DofMap& dofs)
    : data_(*model.memberContact()) {
  const int nn = model.numNodes();
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e)) live_.push_back(e);
  const int ne = static_cast<int>(live_.size());
  group_ = jointGroups(model);
  masses_ = translationalMasses(model);
  usedNode_.assign(nn, 0);
  for (int n = 0; n < nn; ++n) {
    if (!dofs.used(n)) continue;
    usedNode_[n] = 1;
    if (!dofs.aliased(n)) contactNodes_.push_back(n);
  }
  const double shortest = model.characteristicLength();
  const double fallback = data_.radius >= 0 ? data_.radius : 1e-3 * shortest;
  elementRadius_.assign(model.numElements(), fallback);
  nodeRadius_.assign(nn, 0.0);
  double length = 0;
  for (int e : live_) {
    const Element& el = model.element(e);
    if (const double r = sectionRadius(model, e); r > 0) elementRadius_[e] = r;
    const auto nodes = el.nodes();
    length += (model.coord(nodes[0]) - model.coord(nodes[1])).norm();
    for (int n : nodes) nodeRadius_[n] = std::max(nodeRadius_[n], elementRadius_[e]);
  }
  // A node's contact radius is that of its joint group.
  for (int n = 0; n < nn; ++n)
    nodeRadius_[group_[n]] = std::max(nodeRadius_[group_[n]], nodeRadius_[n]);
  for (int n = 0; n < nn; ++n) nodeRadius_[n] = nodeRadius_[group_[n]];
  // The margin of the candidate search: half the mean element length.
  margin_ = ne > 0 ? 0.5 * length / ne : 1.0;

  // Pairs within contact distance in the reference configuration.
  std::vector<Box> boxes(ne);
  for (int i = 0; i < ne; ++i) {
    const int e = live_[i];
    const auto nodes = model.element(e).nodes();
    Box b = Box::point(model.coord(nodes[0]).x(), model.coord(nodes[0]).y());
    b.add(model.coord(nodes[1]).x(), model.coord(nodes[1]).y());
    boxes[i] = b.inflated(elementRadius_[e]);
  }
  // Such a pair stays excluded while the members between them hold: while the
  // node is as few elements from the segment as in the original mesh (joints
  // that ruptured since are counted as broken), or when it was not within a
  // few elements of it there.
  ContactGrid grid;
  grid.build(boxes, 1e-6 * shortest);
  const GroupGraph now(model, live_, group_), original(model, live_, originalGroups(model, group_));
  constexpr int kNearHops = 3;
  for (int n : contactNodes_) {
    const Vec2& x = model.coord(n);
    grid.query(Box::point(x.x(), x.y()).inflated(nodeRadius_[n]), [&](int i) {
      const int e = live_[i];
      if (excluded(n, e, model)) return;
      const auto nodes = model.element(e).nodes();
      const PairPositions q{x, model.coord(nodes[0]), model.coord(nodes[1])};
      const double h = nodeRadius_[n] + elementRadius_[e];
      // Without a side: the distance itself (p = h - |d| inside the span).
      if (pairPenetration(q, pairSide(q), h) <= 0) return;
      const int was = original.hops(n, e, kNearHops);
      if (was > kNearHops || now.hops(n, e, was) <= was)
        referenceExcluded_.push_back(ContactPair{n, e}.key());
    });
  }
  std::sort(referenceExcluded_.begin(), referenceExcluded_.end());
  anchor_.resize(nn);
}

bool MemberContact::excluded(int node, int element, const Model& model) const {
  for (int m : model.element(element).nodes())
    if (group_[m] == group_[node]) return true;
  return false;
}

bool MemberContact::valid(const Model& model, const State& s) const {
  if (!searched_) return false;
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!usedNode_[n]) continue;
    const Box& a = anchor_[n];
    const Vec2& X = model.coord(n);
    for (const Eigen::VectorXd* u : {&s.un, &s.u}) {
      const double x = X.x() + (*u)[3 * n], y = X.y() + (*u)[3 * n + 1];
      if (x < a.x0 - margin_ || x > a.x1 + margin_ || y < a.y0 - margin_ || y > a.y1 + margin_)
        return false;
    }
  }
  return true;
}

void MemberContact::search(const Model& model, const State& s) const {
  const int ne = static_cast<int>(live_.size());
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!usedNode_[n]) continue;
    const Vec2& X = model.coord(n);
    Box b = Box::point(X.x() + s.un[3 * n], X.y() + s.un[3 * n + 1]);
    b.add(X.x() + s.u[3 * n], X.y() + s.u[3 * n + 1]);
    anchor_[n] = b;
  }
  boxes_.resize(ne);
  for (int i = 0; i < ne; ++i) {
    const int e = live_[i];
    const auto nodes = model.element(e).nodes();
    Box b = anchor_[nodes[0]];
    b.add(anchor_[nodes[1]].x0, anchor_[nodes[1]].y0);
    b.add(anchor_[nodes[1]].x1, anchor_[nodes[1]].y1);
    boxes_[i] = b.inflated(elementRadius_[e] + margin_);
  }
  grid_.build(boxes_, 1e-6 * margin_);
  candidates_.clear();
  for (int n : contactNodes_) {
    grid_.query(anchor_[n].inflated(nodeRadius_[n] + margin_), [&](int i) {
      const int e = live_[i];
      if (excluded(n, e, model)) return;
      const ContactPair key{n, e};
      if (std::binary_search(referenceExcluded_.begin(), referenceExcluded_.end(), key.key()))
        return;
      const auto nodes = model.element(e).nodes();
      candidates_.push_back({n, e, nodes[0], nodes[1], nodeRadius_[n] + elementRadius_[e]});
    });
  }
  std::sort(candidates_.begin(), candidates_.end(),
            [](const ContactPair& p, const ContactPair& q) { return p.key() < q.key(); });
  // Room for the list to double before a later search must allocate (steps
  // allocate nothing while the contacts change little).
  if (candidates_.capacity() < 2 * candidates_.size()) candidates_.reserve(2 * candidates_.size());
  searched_ = true;
  ++candidatesVersion_;
}

const std::vector<ContactPair>& MemberContact::candidates(const Model& model,
                                                          const State& s) const {
  if (!valid(model, s)) search(model, s);
  return candidates_;
}


const PairMemory* MemberContact::memory(const State& s, std::uint64_t key) {
  const auto it = std::lower_bound(s.pairs.begin(), s.pairs.end(), key,
                                   [](const PairMemory& m, std::uint64_t k) { return m.key < k; });
  return it != s.pairs.end() && it->key == key ? &*it : nullptr;
}

bool MemberContact::evaluate(const ContactPair& pair, const Model& model, const State& s,
                             const StepRule& rule, bool wantTangent, PairVec& force,
                             PairMat& tangent) const {
  lastRule_ = rule;
  PairPositions q0, q1;
  // The memory only of a pair within reach (slack_: the most a memory's
  // contact distance exceeds its pair's present one).
  if (!positions(pair, model, s, q0, q1, slack_)) return false;
  const PairMemory* m = memory(s, pair.key());
  const int sd = side(m, q0);
  const double h = reach(pair, m);
  // Most candidates are apart (a twelfth carries a force): their law (the
  // dashpot's pair mass and rates) is not formed.
  if (!touches(q0, q1, sd, h, held(m), rule)) return false;
  return pairContact(q0, q1, sd, h, law(pair, s, q0, m), rule, wantTangent, force, tangent, nullptr,
                     held(m));
}

PairOutcome MemberContact::outcome(const ContactPair& pair, const Model& model, const State& s,
                                   const StepRule& rule, double* full) const {
  PairPositions q0, q1;
  const PairMemory* m = memory(s, pair.key());
  if (!positions(pair, model, s, q0, q1, slack_)) {  // apart: a friction spring lets go
    if (full) *full = 0;
    PairOutcome out;
    if (m) out.slipped = springFrictionEnergy(data_.k, m->stretch);
    return out;
  }
  const int sd = side(m, q0);
  if (full) *full = pairPenetration(q1, sd, distance(pair, m), held(m));
  PairOutcome out;
  if (q0.x == q1.x && q0.a == q1.a && q0.b == q1.b) {
    // No step (the committed state itself): nothing slides or lets go; the
    // energy is that of the memory (so that the account sees no jump where a
    // commit in place or a topology change evaluates it).
    out.p0 = out.p1 = pairPenetration(q1, sd, reach(pair, m), held(m));
    out.stretch = m ? m->stretch : 0.0;
    return out;
  }
  out.p0 = pairPenetration(q0, sd, reach(pair, m), held(m));
  out.p1 = pairPenetration(q1, sd, reach(pair, m), held(m));
  if (data_.mu <= 0) return out;  // frictionless: the penetrations tell all
  if (!(out.p1 > 0 || (rule.scheme == Scheme::MidPoint && out.p0 > 0))) {
    // Apart over the step (as pairContact decides): the friction spring lets
    // go, and the law is not formed.
    out.slipped = springFrictionEnergy(data_.k, m ? m->stretch : 0.0);
    return out;
  }
  PairVec f;
  PairMat k;
  pairContact(q0, q1, sd, reach(pair, m), law(pair, s, q0, m), rule, false, f, k, &out, held(m));
  return out;
}

double MemberContact::energy(const Model& model, const State& s) const {
  double w = 0;
  for (const ContactPair& pair : candidates(model, s)) {
    const PairMemory* m = memory(s, pair.key());
    const PairOutcome o = outcome(pair, model, s, lastRule_);
    w += crushingEnergy(data_.k, data_.restitution, m ? m->q : 0.0, o.p1) +
         springFrictionEnergy(data_.k, o.stretch);
  }
  return w;
}

double MemberContact::dissipation(const Model& model, const State& s, const StepRule& rule) const {
  const bool damped = data_.zeta > 0 && rule.scheme == Scheme::MidPoint;
  const bool crushes = data_.restitution < 1;
  if (!damped && !crushes && data_.mu <= 0) return 0;
  double d = 0;
  PairPositions q0, q1;
  for (const ContactPair& pair : candidates(model, s)) {
    const PairMemory* m = memory(s, pair.key());
    const PairOutcome o = outcome(pair, model, s, rule);
    const double q = m ? m->q : 0.0;
    if (crushes) d += CrushingLaw(data_.k, data_.restitution, q).dissipated(o.p0, o.p1);
    if (damped && positions(pair, model, s, q0, q1, slack_))
      d += damperDissipation(law(pair, s, q0, m).c,
                             CrushingLaw(data_.k, data_.restitution, std::max(q, o.p0)).ps, o.p0,
                             o.p1, rule);
    d += o.slipped;
  }
  return d;
}

void MemberContact::motions(const Model& model, const State& s,
                            std::vector<ContactMotion>& out) const {
  PairPositions q0, q1;
  for (const ContactPair& pair : candidates(model, s)) {
    if (!positions(pair, model, s, q0, q1, slack_)) continue;
    const PairMemory* m = memory(s, pair.key());
    const int sd = side(m, q0);
    const double h = reach(pair, m);
    const double p0 = pairPenetration(q0, sd, h, held(m)), p1 = pairPenetration(q1, sd, h, held(m));
    if (p0 <= 0 && p1 <= 0) continue;
    const PairLaw l = law(pair, s, q0, m);
    out.push_back({p0, p1, pairPenetrationRate(q0, pairValues(s.vn, pair), sd, h, held(m)),
                   pairPenetrationRate(q1, pairValues(s.v, pair), sd, h, held(m)), l.k,
                   l.restitution, l.q, l.c, pairMass(masses_, pair, q0)});
  }
}

PairLaw MemberContact::law(const ContactPair& pair, const State& s, const PairPositions& q0,
                           const PairMemory* m) const {
  PairLaw out{data_.k, 0.0, data_.restitution, m ? m->q : 0.0, data_.mu, m ? m->stretch : 0.0};
  if (data_.mu > 0) out.stick = frictionStickDamping(data_.k, pairMass(masses_, pair, q0));
  if (data_.zeta > 0) {
    out.c = damperCoefficient(data_.zeta, data_.k, pairMass(masses_, pair, q0));
    out.zv = pairZ(pairValues(s.vn, pair));
    out.za = pairZ(pairValues(s.an, pair));
  }
  return out;
}

double MemberContact::commit(const Model& model, State& s, int& pushed,
                             double& pushedEnergy) const {
  const std::vector<ContactPair>& pairs = candidates(model, s);
  nextMemory_.clear();
  if (nextMemory_.capacity() < pairs.size()) nextMemory_.reserve(2 * pairs.size());
  double released = 0, letGo = 0, crushed = 0;
  committedEnergy_ = 0;
  PairPositions q0, q1;
  for (const ContactPair& pair : pairs) {
    const PairMemory* m = memory(s, pair.key());
    double full = 0;
    const PairOutcome o = outcome(pair, model, s, lastRule_, &full);
    const bool near = positions(pair, model, s, q0, q1, slack_);
    PairMemory next{pair.key(), 0.0, 0.0, o.stretch, distance(pair, m), m ? m->side : 0};
    bool flipped = false;
    // The offset shrinks with the penetration at the full distance (never
    // while the pair presses on: its force and energy are unchanged).
    if (m) next.offset = std::min(m->offset, std::max(full, 0.0));
    if (o.p1 > 0) {
      const double plain = std::max(m ? m->q : 0.0, o.p1);
      // A turn inside the step: the peak the pair's mass came back from.
      next.q = near ? pairLoadingPoint(data_, masses_, pair, s, q0, q1, side(m, q0), reach(pair, m),
                                       held(m), plain, o.p1)
                    : plain;
      crushed += crushingEnergy(data_.k, data_.restitution, plain, o.p1) -
                 crushingEnergy(data_.k, data_.restitution, next.q, o.p1);
      const int was = near ? side(m, q0) : 0;
      // A held side changes only past the centre line by the full distance.
      if (near && pairSide(q1) != was && (!next.side || o.p1 > reach(pair, m) + next.h)) {
        if (next.side) next.side = -next.side;
        // Seen from the new side the penetration is smaller (the loading point
        // kept, so that the energy only drops).
        const double seen = pairPenetration(q1, -was, reach(pair, m), held(&next));
        released += crushingEnergy(data_.k, data_.restitution, next.q, o.p1) -
                    crushingEnergy(data_.k, data_.restitution, next.q, seen);
        if (seen <= 0) next.q = 0;
        ++pushed;
        flipped = true;
      }
    }
    // A held side is let go once the node has cleared the centre line on it
    // by kLetGo of the contact distance, or gone as far around the end (from
    // then on the side at t_n is that side, and the contact distance it has
    // gained keeps it there), and when the offset is gone.
    const bool wasHeld = next.side != 0;
    if (next.side && (!near || next.offset <= 0 ||
                      pairPenetration(q1, next.side, 0.0, true) < -kLetGo * next.h))
      next.side = 0;
    // A held node can press on beyond the reach of the pair's boxes at the
    // committed positions alone (far on the wrong side beyond an end), where
    // energy() does not see it.
    const bool nearAfter = near && reachesAt(pair, q1);
    const bool kept = next.q > 0 || next.offset > 0 || next.stretch != 0;
    // Its energy at the committed state (as energy() finds it there).
    const double after =
        kept && nearAfter
            ? crushingEnergy(data_.k, data_.restitution, next.q,
                             pairPenetration(q1, side(&next, q1), reach(pair, &next), held(&next))) +
                  springFrictionEnergy(data_.k, next.stretch)
            : 0.0;
    committedEnergy_ += after;
    // What a held pair stored at the end of the step and does not store so
    // seen from its new side, or apart, is released (the trial energy counted
    // it; a pushed pair booked its own above). From the loading point it gets
    // now: what the new loading point took is in `crushed` already (taken
    // from the memory's, it was booked twice: the account's balance at such a
    // commit stood off by that much until the next step).
    if (wasHeld && !flipped)
      letGo += crushingEnergy(data_.k, data_.restitution, next.q, o.p1) +
               springFrictionEnergy(data_.k, o.stretch) - after;
    if (kept) nextMemory_.push_back(next);
  }
  // Candidates are sorted by key, so is the memory. Copied, with room to
  // double, so that steps allocate nothing while the contacts change little.
  if (s.pairs.capacity() < nextMemory_.size()) s.pairs.reserve(2 * nextMemory_.size());
  s.pairs.assign(nextMemory_.begin(), nextMemory_.end());
  committed_ = true;
  pushedEnergy += released;
  return released + letGo + crushed;
}

int MemberContact::membersSide(const ContactPair& pair, const Model& model, const State& s,
                               const PairPositions& q) const {
  // The far ends of the node's members (the elements at its joint group) seen
  // from the segment's line; members along the line tell nothing.
  const Vec2 t = q.b - q.a;
  const double l = t.norm();
  if (l == 0) return 0;
  int found = 0;
  for (int e : live_) {
    const auto nodes = model.element(e).nodes();
    for (int end = 0; end < 2; ++end) {
      if (group_[nodes[end]] != group_[pair.node]) continue;
      const int far = nodes[1 - end];
      const Vec2 x = model.coord(far) + Vec2(s.u[3 * far], s.u[3 * far + 1]);
      const double d = (t.x() * (x - q.a).y() - t.y() * (x - q.a).x()) / l;
      if (std::abs(d) <= kAlongLine * pair.h) continue;
      const int sd = d > 0 ? 1 : -1;
      if (found && sd != found) return 0;  // members on both sides
      found = sd;
    }
  }
  return found;
}

void MemberContact::openPairs(const Model& model, State& s) const {
  // Pairs in memory keep the contact distance they met at: the candidates'
  // boxes reach as far as the largest excess over the present distances.
  slack_ = 0;
  for (const PairMemory& m : s.pairs) {
    const int node = static_cast<int>(m.key >> 32), element = static_cast<int>(m.key & 0xffffffffu);
    if (node < static_cast<int>(nodeRadius_.size()) && element < model.numElements() &&
        model.hasElement(element))
      slack_ = std::max(slack_, m.h - nodeRadius_[node] - elementRadius_[element]);
  }
  // Room for four pairs in contact per node before a commit must allocate.
  const std::size_t room = 4 * contactNodes_.size();
  if (s.pairs.capacity() < room) s.pairs.reserve(room);
  if (nextMemory_.capacity() < room) nextMemory_.reserve(room);
  PairPositions q0, q1;
  // The new pairs gathered apart: appended to the memory they would unsort
  // it for the lookups of the pairs after them.
  nextMemory_.clear();
  for (const ContactPair& pair : candidates(model, s)) {
    if (memory(s, pair.key()) || !positions(pair, model, s, q0, q1)) continue;
    // A node on the segment itself (a ruptured joint's end node, on the
    // centre line of the member it was joined to) has no side of its own.
    const bool onSegment = pairPenetration(q1, pairSide(q1), pair.h) >= (1 - kOnSegment) * pair.h;
    const int sd = onSegment ? membersSide(pair, model, s, q1) : 0;
    const double p = pairPenetration(q1, sd ? sd : pairSide(q1), pair.h, sd != 0);
    if (p <= 0) continue;
    nextMemory_.push_back({pair.key(), 0.0, p, 0.0, pair.h, sd});
  }
  if (nextMemory_.empty()) return;
  s.pairs.insert(s.pairs.end(), nextMemory_.begin(), nextMemory_.end());
  std::sort(s.pairs.begin(), s.pairs.end(),
            [](const PairMemory& a, const PairMemory& b) { return a.key < b.key; });
}

}  // namespace c2d
