#include "solvers/TopologyEvents.h"

#include "elements/HingeToJoint.h"
#include "elements/Joints.h"

namespace c2d {

bool TopologyEvents::afterCommit(Model& model, State& state) {
  std::vector<TopologyEvent> events;
  for (const CreatedJoint& j : jointFailedHinges(model, state))
    events.push_back({TopologyEvent::Kind::JointFormed, j.element, j.master, j.slave,
                      j.relativeRotation, 0});
  for (const RupturedJoint& j : ruptureJoints(model, state))
    events.push_back(
        {TopologyEvent::Kind::JointRuptured, j.element, j.master, j.slave, j.rotation, j.limit});
  if (onEvent)
    for (const TopologyEvent& e : events) onEvent(e);
  return !events.empty();
}

}  // namespace c2d
