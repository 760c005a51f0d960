#include "elements/RigidEnds.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace c2d {

namespace {

Vec2 rotated(double theta, const Vec2& a) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * a.x() - s * a.y(), s * a.x() + c * a.y()};
}

// The quarter turn W a = (-a_y, a_x); (W a) . f = a x f.
Vec2 quarter(const Vec2& a) { return {-a.y(), a.x()}; }

constexpr int rotDof(int end) { return kNodeDofs * end + 2; }

}  // namespace

RigidEnds::RigidEnds(const Vec2& x1, const Vec2& x2, double o1, double o2) : offsets_{o1, o2} {
  const double l = (x2 - x1).norm();
  if (!(o1 >= 0) || !(o2 >= 0))
    throw std::invalid_argument("rigid end zones must not be negative");
  if (!(o1 + o2 < l))
    throw std::invalid_argument("the rigid end zones (" + std::to_string(o1) + " + " +
                                std::to_string(o2) + ") leave no flexible length of the element (" +
                                std::to_string(l) + ")");
  const Vec2 t = (x2 - x1) / l;
  arms_ = {o1 * t, -o2 * t};
}

RigidEnds RigidEnds::single(int end, const Vec2& arm) {
  RigidEnds r;
  r.offsets_[end] = arm.norm();
  r.arms_[end] = arm;
  return r;
}

Vec2 RigidEnds::armMotion(int end, double theta) const {
  return rotated(theta, arms_[end]) - arms_[end];
}

ElemMat RigidEnds::linearMap() const {
  ElemMat g = ElemMat::Identity();
  for (int a = 0; a < 2; ++a) g.block<2, 1>(kNodeDofs * a, rotDof(a)) = quarter(arms_[a]);
  return g;
}

ElemVec RigidEnds::faceDisplacement(const ElemVec& d) const {
  ElemVec f = d;
  for (int a = 0; a < 2; ++a)
    f.segment<2>(kNodeDofs * a) += rotated(d(rotDof(a)), arms_[a]) - arms_[a];
  return f;
}

ElemMat RigidEnds::jacobian(const ElemVec& d) const {
  ElemMat g = ElemMat::Identity();
  for (int a = 0; a < 2; ++a)
    g.block<2, 1>(kNodeDofs * a, rotDof(a)) = quarter(rotated(d(rotDof(a)), arms_[a]));
  return g;
}

void RigidEnds::toNodes(const ElemVec& d, const ElemVec* dn, ElemVec& fFace, ElemMat* kFace) const {
  // The right factor of the tangent: the exact derivative of the face motion.
  if (kFace) *kFace = *kFace * jacobian(d);
  for (int a = 0; a < 2; ++a) {
    const int r = rotDof(a);
    const Vec2 f = fFace.segment<2>(kNodeDofs * a);
    // lever: the nodal moment is m_face + lever . f; slope: d(lever . f)/d theta_n+1.
    Vec2 lever;
    double slope = 0;
    if (!dn) {
      const Vec2 ra = rotated(d(r), arms_[a]);
      lever = quarter(ra);
      slope = -ra.dot(f);
    } else {
      const double half = 0.5 * (d(r) - (*dn)(r));
      const Vec2 ra = rotated(0.5 * (d(r) + (*dn)(r)), arms_[a]);
      const double c = std::cos(half), s = std::sin(half);
      lever = c * quarter(ra);
      slope = -0.5 * (s * quarter(ra).dot(f) + c * ra.dot(f));
    }
    if (kFace) {
      // Left factor: the (algorithmic) transpose map, then the lever's change with theta.
      kFace->row(r) += lever.x() * kFace->row(kNodeDofs * a) + lever.y() * kFace->row(kNodeDofs * a + 1);
      (*kFace)(r, r) += slope;
    }
    fFace(r) += lever.dot(f);
  }
}

}  // namespace c2d
