#include "elements/JointArm.h"

#include "elements/InelasticFrame.h"
#include "elements/LinearFrame.h"
#include "elements/ReissnerFrame.h"

namespace c2d {

JointArm::JointArm(const Element& e, int end) : end_(end) {
  const RigidEnds* rigid = nullptr;
  if (const auto* f = dynamic_cast<const ReissnerFrame*>(&e)) {
    rigid = &f->rigidEnds();
  } else if (const auto* f = dynamic_cast<const InelasticFrame*>(&e)) {
    rigid = &f->rigidEnds();
    exact_ = false;
  } else if (const auto* f = dynamic_cast<const LinearFrame*>(&e)) {
    rigid = &f->rigidEnds();
    exact_ = false;
  }
  if (!rigid) return;
  arm_ = rigid->arm(end);
  toFace_ = RigidEnds::single(end, arm_);
  fromFace_ = RigidEnds::single(end, -arm_);
}

Vec2 JointArm::motion(double theta) const {
  if (exact_) return toFace_.armMotion(end_, theta);
  return theta * Vec2(-arm_.y(), arm_.x());
}

void JointArm::toFace(ElementKinematics& kin) const {
  const int t = kNodeDofs * end_;
  kin.d.segment<2>(t) += motion(kin.d(t + 2));
  kin.dn.segment<2>(t) += motion(kin.dn(t + 2));
}

void JointArm::toNode(ElementKinematics& in, bool withHistory) const {
  const int t = kNodeDofs * end_;
  in.d.segment<2>(t) -= motion(in.d(t + 2));
  if (withHistory) in.dn.segment<2>(t) -= motion(in.dn(t + 2));
}

ElemMat JointArm::jacobian(const RigidEnds& map, const ElemVec& d) const {
  return exact_ ? map.jacobian(d) : map.linearMap();
}

void JointArm::pullBack(const RigidEnds& map, const ElementKinematics& at, const StepRule& rule,
                        ElemVec& force, ElemMat* tangent) const {
  if (exact_) {
    map.toNodes(at.d, rule.scheme == Scheme::MidPoint ? &at.dn : nullptr, force, tangent);
    return;
  }
  const ElemMat g = map.linearMap();
  force = g.transpose() * force;
  if (tangent) *tangent = g.transpose() * *tangent * g;
}

void JointArm::faceForces(const ElementKinematics& in, const StepRule& rule, ElemVec& force,
                          ElemMat* tangent) const {
  pullBack(fromFace_, in, rule, force, tangent);
}

void JointArm::nodeForces(const ElementKinematics& outer, const StepRule& rule, ElemVec& force,
                          ElemMat* tangent) const {
  pullBack(toFace_, outer, rule, force, tangent);
}

ElemVec JointArm::faceGradient(const ElemVec& g, const ElemVec& in) const {
  return jacobian(fromFace_, in).transpose() * g;
}

ElemVec JointArm::nodeGradient(const ElemVec& g, const ElemVec& outer) const {
  return jacobian(toFace_, outer).transpose() * g;
}

}  // namespace c2d
