#pragma once
// The rigid arm at the slave end of a joint at the face of a rigid end zone
// (elements/JointedElement.h, elements/RigidEnds.h): the arm a belongs to the
// member the joint's master is part of and turns with the master's rotation;
// the wrapped element, which applies its own arm with the slave rotation it
// is given, gets its slave node where its face lands right.
//   phi(t) = (R(t) - I) a   (t W a, the linear part, for elements of SMALl
//                            kinematics, whose arms are linear)
// Face coordinates: the outer kinematics with the slave end's translation
// moved by phi(psi_m) (the face's translation), its rotation unchanged. The
// wrapped element's slave node: the face's translation less phi(psi_s), which
// is the master's plus the shift s = phi(psi_m) - phi(psi_s). Forces and
// tangents go from the wrapped element to face coordinates by the face-to-node
// map's transpose (RigidEnds with arm -a) and from there to the master by the
// node-to-face map's (arm a), with their geometric terms and, under the
// mid-point scheme, the algorithmic transposes that keep the work identity.
#include "core/Element.h"
#include "core/StepRule.h"
#include "core/Types.h"
#include "elements/RigidEnds.h"

namespace c2d {

class JointArm {
 public:
  JointArm() = default;  // none
  // The arm of element e's rigid zone at `end` (e the innermost of a joint's
  // wrappers; none for element types without zones).
  JointArm(const Element& e, int end);

  bool any() const { return arm_.x() != 0 || arm_.y() != 0; }
  const Vec2& arm() const { return arm_; }
  Vec2 motion(double theta) const;  // phi(theta)
  // The shift s of the wrapped element's slave node for psi_m, psi_r.
  Vec2 shift(double psiM, double psiR) const {
    return any() ? Vec2(motion(psiM) - motion(psiM + psiR)) : Vec2::Zero();
  }

  // Outer kinematics to face coordinates (d and dn), in place.
  void toFace(ElementKinematics& kin) const;
  // The wrapped element's slave translation from face coordinates at the slave
  // rotation in `in` (d; dn too when withHistory), in place.
  void toNode(ElementKinematics& in, bool withHistory) const;
  // The wrapped element's force (and tangent) at `in` to face coordinates.
  void faceForces(const ElementKinematics& in, const StepRule& rule, ElemVec& force,
                  ElemMat* tangent) const;
  // Forces (and tangent) in face coordinates to the outer dofs at `outer`.
  void nodeForces(const ElementKinematics& outer, const StepRule& rule, ElemVec& force,
                  ElemMat* tangent) const;
  // A gradient (dN/dd) of the wrapped element at its d to face coordinates,
  // and one in face coordinates to the outer dofs at the outer d.
  ElemVec faceGradient(const ElemVec& g, const ElemVec& in) const;
  ElemVec nodeGradient(const ElemVec& g, const ElemVec& outer) const;

 private:
  void pullBack(const RigidEnds& map, const ElementKinematics& at, const StepRule& rule,
                ElemVec& force, ElemMat* tangent) const;
  ElemMat jacobian(const RigidEnds& map, const ElemVec& d) const;

  int end_ = 0;
  Vec2 arm_ = Vec2::Zero();
  bool exact_ = true;
  RigidEnds toFace_, fromFace_;  // arms a and -a at end_
};

}  // namespace c2d
