#include "solvers/TopologyEvents.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "elements/BarFractures.h"
#include "elements/EndHinges.h"
#include "elements/HingeToJoint.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"

namespace c2d {

void TopologyEvents::index(const Model& model) {
  if (indexedModel_ == &model && indexedVersion_ == model.topologyVersion()) return;
  carriers_.clear();
  jointCarriers_.clear();
  wrappers_.clear();
  const std::vector<int> attached = nodeAttachments(model);
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    const auto* c = dynamic_cast<const HingeCarrier*>(&innermost(model.element(e)));
    if (!c) continue;
    carriers_.push_back(c);
    if (jointsWhenFailed(model, attached, model.element(e))) jointCarriers_.push_back(c);
  }
  for (const JointedElement* j : jointedElements(model)) wrappers_.push_back(j);
  indexedModel_ = &model;
  indexedVersion_ = model.topologyVersion();
}

bool TopologyEvents::anyEndHingeOrFracture() const {
  // An opened end hinge or a fracture is also an activated event of a carrier.
  for (const HingeCarrier* c : carriers_) {
    const HingeInfo h = c->hinge();
    if (h.fracture || h.jointDue) return true;
  }
  return false;
}

bool TopologyEvents::anyFailedHinge() const {
  // The condition of jointFailedHinges: when no hinge that can become a
  // joint has failed it makes none.
  for (const HingeCarrier* c : jointCarriers_) {
    const HingeInfo h = c->hinge();
    if (h.active && h.failed) return true;
  }
  return false;
}

bool TopologyEvents::anyJointPastRupture(const Model& model, const State& state) const {
  // The condition of ruptureJoints with the smallest rupture rotation of any
  // material: when no joint's relative rotation exceeds it, none ruptures.
  double limit = std::numeric_limits<double>::infinity();
  for (const auto& [number, mat] : model.materials())
    if (mat.softening && mat.softening->thetaR) limit = std::min(limit, *mat.softening->thetaR);
  if (model.joints().empty() || !(limit < std::numeric_limits<double>::infinity())) return false;
  // A joint held within Lb of a free end stays held (free ends only grow in
  // number, and Lb is measured in the reference configuration): it does not
  // call for a rupture pass at every commit.
  const auto held = [&](int slave) {
    return std::find(heldReported_.begin(), heldReported_.end(), slave) != heldReported_.end();
  };
  for (const JointedElement* j : wrappers_)
    if (std::abs(j->committedRelativeRotation()) > limit && !held(j->slaveNode())) return true;
  for (const Joint& joint : model.joints())
    if (joint.form != JointForm::Condensed &&
        std::abs(state.un[static_cast<Eigen::Index>(joint.slave) * kNodeDofs + 2] -
                 state.un[static_cast<Eigen::Index>(joint.master) * kNodeDofs + 2]) > limit &&
        !held(joint.slave))
      return true;
  return false;
}

bool TopologyEvents::afterCommit(Model& model, State& state) {
  std::vector<TopologyEvent> events;
  index(model);
  if (anyEndHingeOrFracture()) {
    if (endHingesDue(model))
      for (const OpenedHinge& h : openEndHinges(model, state)) {
        TopologyEvent ev{TopologyEvent::Kind::HingeOpened, h.element, h.master, h.slave, 0, 0};
        ev.end = h.end;
        ev.moment = h.moment;
        ev.ultimate = h.ultimate;
        ev.axialForce = h.axialForce;
        ev.failureJump = h.failureJump;
        ev.shearSpan = h.shearSpan;
        events.push_back(ev);
      }
    if (fracturesDue(model))
      for (const FracturedMember& f : separateFractured(model, state)) {
        TopologyEvent ev{f.shear ? TopologyEvent::Kind::Sheared : TopologyEvent::Kind::BarsFractured,
                         f.element, f.node, f.newNode, 0, 0};
        ev.end = f.end;
        ev.axialForce = f.axialForce;
        ev.moment = f.shearForce;
        ev.ultimate = f.shearCapacity;
        ev.throughJoint = f.joint;
        events.push_back(ev);
      }
    index(model);
  }
  if (anyFailedHinge()) {
    for (const CreatedJoint& j : jointFailedHinges(model, state))
      events.push_back(
          {TopologyEvent::Kind::JointFormed, j.element, j.master, j.slave, j.relativeRotation, 0});
    index(model);  // the joints just made
  }
  std::vector<HeldJoint> held;
  if (anyJointPastRupture(model, state))
    for (const RupturedJoint& j : ruptureJoints(model, state, &held))
      events.push_back(
          {TopologyEvent::Kind::JointRuptured, j.element, j.master, j.slave, j.rotation, j.limit});
  const bool changed = !events.empty();
  for (const HeldJoint& h : held) {
    if (std::find(heldReported_.begin(), heldReported_.end(), h.slave) != heldReported_.end())
      continue;  // another joint's pass found it again
    heldReported_.push_back(h.slave);
    TopologyEvent ev{
        TopologyEvent::Kind::JointHeld, h.element, h.master, h.slave, h.rotation, h.limit};
    ev.end = h.freeEnd;
    ev.pieceLength = h.pieceLength;
    events.push_back(ev);
  }
  if (onEvent)
    for (const TopologyEvent& e : events) onEvent(e);
  return changed;
}

}  // namespace c2d
