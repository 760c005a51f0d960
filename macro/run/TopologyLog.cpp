#include "macro/run/TopologyLog.h"

#include <cstdio>
#include <string>

#include "elements/JointedElement.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

std::string num(double v) { return formatNumber("%.6e", v); }

}  // namespace

void logTopologyEvent(std::ostream& log, const Model& model, double t, const TopologyEvent& ev,
                      TopologyCounts& counts) {
  switch (ev.kind) {
    case TopologyEvent::Kind::JointFormed: {
      ++counts.jointsFormed;
      log << "  joint  formed at t = " << num(t) << ": element " << ev.element + 1
          << ", fully softened hinge, at node " << ev.master + 1 << " (slave node " << ev.slave + 1
          << "), relative rotation " << num(ev.rotation);
      // A member's second joint (elements/HingeToJoint.h): a link from now on.
      const JointedElement* j = asJointed(&model.element(ev.element));
      if (j && asJointed(&j->inner()))
        log << "; its second: the member is a link pinned at both ends";
      log << "\n";
      break;
    }
    case TopologyEvent::Kind::JointRuptured:
      ++counts.jointsRuptured;
      log << "  joint  ruptured at t = " << num(t) << ": element " << ev.element + 1
          << " separates at node " << ev.master + 1 << " (new node " << ev.slave + 1
          << "), relative rotation " << num(ev.rotation) << " beyond thetaR = " << num(ev.limit)
          << "\n";
      break;
    case TopologyEvent::Kind::JointHeld:
      // Held in every step while it stays past thetaR: its first lines only.
      if (!counts.folding.admit("joint held past thetaR within Lb of a free end (no rupture)",
                                std::to_string(ev.element) + "/" + std::to_string(ev.master)))
        break;
      log << "  joint  held at t = " << num(t) << ": element " << ev.element + 1 << " at node "
          << ev.master + 1 << ", relative rotation " << num(ev.rotation)
          << " beyond thetaR = " << num(ev.limit)
          << ", does not rupture: within the shortest piece Lb = " << num(ev.pieceLength)
          << " of the free end at node " << ev.end + 1 << " (it turns on with its friction)\n";
      break;
    case TopologyEvent::Kind::HingeOpened:
      ++counts.hinges;
      log << "  hinge  opened at t = " << num(t) << ": element " << ev.element + 1 << " end "
          << ev.end + 1 << " (node " << ev.master + 1 << ", joint's slave node " << ev.slave + 1
          << "), M = " << num(ev.moment) << ", Mu(N) = " << num(ev.ultimate)
          << " at N = " << num(ev.axialForce) << ", failure jump " << num(ev.failureJump);
      if (ev.shearSpan > 0) log << " (shear span L_V = " << num(ev.shearSpan) << ")";
      log << "\n";
      break;
    case TopologyEvent::Kind::BarsFractured:
      ++counts.fractures;
      log << "  bars   fractured at t = " << num(t) << ": element " << ev.element + 1
          << " separates at node " << ev.master + 1 << " (its end " << ev.end + 1 << ", new node "
          << ev.slave + 1 << (ev.throughJoint ? ", through its joint" : "") << "), axial force "
          << num(ev.axialForce) << "\n";
      break;
    case TopologyEvent::Kind::Sheared:
      ++counts.shears;
      log << "  shear  failure at t = " << num(t) << ": element " << ev.element + 1
          << " separates at node " << ev.master + 1 << " (its end " << ev.end + 1 << ", new node "
          << ev.slave + 1 << (ev.throughJoint ? ", through its joint" : "") << "), V = "
          << num(ev.moment) << ", Vu(N) = " << num(ev.ultimate) << " at N = " << num(ev.axialForce)
          << "\n";
      break;
  }
}

}  // namespace c2d
