#pragma once
// Rigid end zones of a frame element (deck: RIGId): the lengths o1, o2 (m)
// from the element's first and second node, along its reference axis t, to
// the faces where the flexible member begins (a beam framing into a wall's or
// a column's face). The element's law acts on the flexible part between the
// faces, of length l - o1 - o2; the nodes drive the faces through rigid arms
//   a1 = o1 t,  a2 = -o2 t   (reference vectors from node to face),
//   u_face = u_node + (R(theta) - I) a,   theta_face = theta_node,
// with R the rotation by the nodal rotation theta: exact under FINIte
// kinematics; SMALl kinematics take the linear map u_face = u_node + theta W a
// (W the counterclockwise quarter turn).
//
// Forces go back by the transpose of the map's derivative G(d) (the work of the
// face forces on the face motion is the work of the nodal forces on the nodal
// motion): the nodal translations take the face forces, the nodal rotation the
// face moment plus the moment of the face force about the node,
//   m_node = m_face + (R(theta) a) x f_face.
// Its derivative adds to the tangent the geometric term
//   d m_node / d theta = -(R(theta) a) . f_face.
// Under the energy-momentum (mid-point) scheme, whose rotations pair with their
// Cayley increments c = 2 tan(dtheta/2), the face's translation increment is
// exactly (R(theta_n+1) - R(theta_n)) a = c cos(dtheta/2) W R(theta_mid) a, so
//   m_node = m_face + cos(dtheta/2) (R(theta_mid) a) x f_face
// keeps the work identity (and the moment balance about the mid-point
// configuration) of the flexible element exact for the nodal forces.
//
// Dof order: the element's (node 1: u, v, theta; node 2: u, v, theta), global frame.
#include <array>

#include "core/Types.h"

namespace c2d {

class RigidEnds {
 public:
  RigidEnds() = default;  // no rigid zones
  // x1, x2: the nodes' reference coordinates; offsets o1, o2 >= 0 with
  // o1 + o2 < |x2 - x1| (std::invalid_argument otherwise).
  RigidEnds(const Vec2& x1, const Vec2& x2, double o1, double o2);
  // One arm, any reference vector, at end `end` (none at the other): the maps
  // of a joint at a face (elements/JointedElement.h).
  static RigidEnds single(int end, const Vec2& arm);

  bool any() const { return offsets_[0] > 0 || offsets_[1] > 0; }
  double offset(int end) const { return offsets_[end]; }
  const std::array<double, 2>& offsets() const { return offsets_; }
  // The reference arm from node `end` to its face.
  const Vec2& arm(int end) const { return arms_[end]; }
  // The faces' reference coordinates (the flexible part's ends).
  Vec2 face(int end, const Vec2& node) const { return node + arms_[end]; }

  // The arm's motion (R(theta) - I) a at end `end` for the nodal rotation theta.
  Vec2 armMotion(int end, double theta) const;

  // The linear (SMALl) map: d_face = G d.
  ElemMat linearMap() const;
  // The exact (FINIte) face displacements and the map's derivative at d.
  ElemVec faceDisplacement(const ElemVec& d) const;
  ElemMat jacobian(const ElemVec& d) const;

  // Nodal force and tangent from the flexible part's face force fFace and its
  // derivative kFace = dfFace/dd_face at d (in place: fFace becomes the nodal
  // force, kFace the nodal tangent when given). Static and Newmark steps: the
  // exact transpose map at d; with dn (the mid-point scheme) the algorithmic
  // one above. kFace may be null (no tangent).
  void toNodes(const ElemVec& d, const ElemVec* dn, ElemVec& fFace, ElemMat* kFace) const;

 private:
  std::array<double, 2> offsets_{0.0, 0.0};
  std::array<Vec2, 2> arms_{Vec2::Zero(), Vec2::Zero()};
};

}  // namespace c2d
