#include "core/MemberContact.h"

#include <algorithm>
#include <cmath>
#include <numeric>

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

void penetration(const Vec4& z, int side, double h, bool wantHessian, Penetration& out) {
  out.g.setZero();
  if (wantHessian) out.H.setZero();
  const Vec2 r1 = z.head<2>(), r2 = z.tail<2>();
  const double l2 = r2.squaredNorm();
  if (l2 == 0) return endPenetration(r1, false, h, wantHessian, out);
  const double xi = r1.dot(r2) / l2;
  if (xi < 0) return endPenetration(r1, false, h, wantHessian, out);
  if (xi > 1) return endPenetration(r1 - r2, true, h, wantHessian, out);
  // Inside: d = (r2 x r1) / |r2|, p = h - s d.
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

double pairPenetration(const PairPositions& q, int side, double h) {
  Penetration p;
  penetration(relative(q), side, h, false, p);
  return p.p;
}

bool pairContact(const PairPositions& q0, const PairPositions& q1, int side, double h, double k,
                 double alpha, const StepRule& rule, bool wantTangent, PairVec& force,
                 PairMat& tangent) {
  const Vec4 z0 = relative(q0), z1 = relative(q1);
  Penetration e1;
  penetration(z1, side, h, wantTangent && rule.scheme != Scheme::MidPoint, e1);
  const double p1 = e1.p;
  Vec4 fz;
  Mat4 kz;
  if (rule.scheme != Scheme::MidPoint) {
    if (p1 <= 0) return false;
    fz = k * p1 * e1.g;
    if (wantTangent) kz = k * (e1.g * e1.g.transpose() + p1 * e1.H);
    toPair(fz, wantTangent ? &kz : nullptr, force, wantTangent ? &tangent : nullptr);
    return true;
  }
  Penetration e0;
  penetration(z0, side, h, false, e0);
  const double p0 = e0.p;
  if (p0 <= 0 && p1 <= 0) return false;
  // phi'(p0, p1): the discrete derivative of k <p>^2 / 2, in closed form per
  // branch (see core/GroundContact.cpp), and its derivative w.r.t. p1.
  const double dp = p1 - p0;
  double w = 0, dw = 0;
  if (p0 > 0 && p1 > 0) {
    w = 0.5 * k * (p0 + p1);
    dw = 0.5 * k;
  } else if (p1 > 0) {
    w = 0.5 * k * p1 * p1 / dp;
    dw = k * p1 / dp - 0.5 * k * p1 * p1 / (dp * dp);
  } else {
    w = -0.5 * k * p0 * p0 / dp;
    dw = 0.5 * k * p0 * p0 / (dp * dp);
  }
  if (alpha > 0) {
    w += alpha * k * (std::max(p1, 0.0) - std::max(p0, 0.0));
    if (p1 > 0) dw += alpha * k;
  }
  // D: the discrete gradient of p (Gonzalez) between z0 and z1. Below a
  // relative step of 1e-7 the correction, O(|dz|^2), is left out: there its
  // round-off (eps |z| / |dz|) would exceed it.
  const Vec4 dz = z1 - z0, zm = 0.5 * (z0 + z1);
  Penetration em;
  penetration(zm, side, h, wantTangent, em);
  const double n2 = dz.squaredNorm();
  const double scale = z0.norm() + z1.norm() + h;
  const bool corrected = n2 > 1e-14 * scale * scale;
  double c = 0;
  Vec4 D = em.g;
  if (corrected) {
    c = (p1 - p0 - em.g.dot(dz)) / n2;
    D += c * dz;
  }
  fz = w * D;
  if (wantTangent) {
    kz = D * (dw * e1.g).transpose() + 0.5 * w * em.H;
    if (corrected) {
      const Vec4 dc = (e1.g - em.g - 0.5 * em.H * dz) / n2 - 2 * c * dz / n2;
      kz += w * (c * Mat4::Identity() + dz * dc.transpose());
    }
  }
  toPair(fz, wantTangent ? &kz : nullptr, force, wantTangent ? &tangent : nullptr);
  return true;
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
    if (const MaterialSet* m = model.material(el.materialNumber()); m && m->A > 0 && m->I > 0)
      elementRadius_[e] = std::sqrt(3 * m->I / m->A);
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
  ContactGrid grid;
  grid.build(boxes, 1e-6 * shortest);
  for (int n : contactNodes_) {
    const Vec2& x = model.coord(n);
    grid.query(Box::point(x.x(), x.y()).inflated(nodeRadius_[n]), [&](int i) {
      const int e = live_[i];
      if (excluded(n, e, model)) return;
      const auto nodes = model.element(e).nodes();
      const PairPositions q{x, model.coord(nodes[0]), model.coord(nodes[1])};
      const double h = nodeRadius_[n] + elementRadius_[e];
      // Without a side: the distance itself (p = h - |d| inside the span).
      if (pairPenetration(q, pairSide(q), h) > 0)
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

bool MemberContact::positions(const ContactPair& pair, const Model& model, const State& s,
                              PairPositions& q0, PairPositions& q1, double extra) const {
  auto at = [&](const Eigen::VectorXd& u, int n) {
    return Vec2(model.coord(n).x() + u[3 * n], model.coord(n).y() + u[3 * n + 1]);
  };
  q0 = {at(s.un, pair.node), at(s.un, pair.a), at(s.un, pair.b)};
  q1 = {at(s.u, pair.node), at(s.u, pair.a), at(s.u, pair.b)};
  Box node = Box::point(q0.x.x(), q0.x.y()), seg = Box::point(q0.a.x(), q0.a.y());
  node.add(q1.x.x(), q1.x.y());
  seg.add(q0.b.x(), q0.b.y());
  seg.add(q1.a.x(), q1.a.y());
  seg.add(q1.b.x(), q1.b.y());
  return node.inflated(pair.h + extra).overlaps(seg);
}

bool MemberContact::evaluate(const ContactPair& pair, const Model& model, const State& s,
                             const StepRule& rule, bool wantTangent, PairVec& force,
                             PairMat& tangent) const {
  PairPositions q0, q1;
  if (!positions(pair, model, s, q0, q1)) return false;
  return pairContact(q0, q1, pairSide(q0), pair.h, data_.k, alpha(rule), rule, wantTangent, force,
                     tangent);
}

double MemberContact::energy(const Model& model, const State& s) const {
  double w = 0;
  PairPositions q0, q1;
  for (const ContactPair& pair : candidates(model, s)) {
    if (!positions(pair, model, s, q0, q1)) continue;
    const double p = pairPenetration(q1, pairSide(q0), pair.h);
    if (p > 0) w += 0.5 * data_.k * p * p;
  }
  return w;
}

double MemberContact::dissipation(const Model& model, const State& s, const StepRule& rule) const {
  const double a = alpha(rule);
  if (rule.scheme != Scheme::MidPoint || a <= 0) return 0;
  double d = 0;
  PairPositions q0, q1;
  for (const ContactPair& pair : candidates(model, s)) {
    if (!positions(pair, model, s, q0, q1)) continue;
    const int side = pairSide(q0);
    const double p0 = pairPenetration(q0, side, pair.h), p1 = pairPenetration(q1, side, pair.h);
    d += a * data_.k * (std::max(p1, 0.0) - std::max(p0, 0.0)) * (p1 - p0);
  }
  return d;
}

}  // namespace c2d
