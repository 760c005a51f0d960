#pragma once
// One softening hinge per localization zone (the collapse phase's midpoint
// hinges in geometrically exact elements, elements/ReissnerFrame).
//
// A midpoint hinge localizes the member's failure in one element, and the
// moment next to it is bounded by the hinge's: as it softens, the moment along
// the member falls with it. Without a bound, every element of a member whose
// moment reaches Mu together opens a hinge of its own, each softening with its
// own law, so a finer mesh gives a member more hinges and more softening
// rotation (the six-storey fall opened 70, 125 and 182 hinges at 84, 288 and
// 576 elements, most next to another open hinge in the same member). So no
// second hinge opens within the zone length of an open one in the same member:
// an element there is held (ReissnerFrame::setHeld): it opens no hinge and its
// moment stays at most Mu (materials/HingedBending: perfectly plastic at Mu
// instead of hardening past it; the zone's hinge takes the rotation).
//
// The zone length of an open hinge is its material's shortest piece Lb
// (SOFTening's fifth value or a SECTion's STIRrups, Mu/Vu: the nearest a
// second hinge can open next to a section whose moment falls), else a SECTion's
// depth h (the plastic hinge length is of the order of h), else none (hinges
// anywhere: the laws as the paper gives them). A member is a chain of elements
// meeting two by two at nodes (a joint's slave is the jointed element's own
// node: a joint cuts the member; one that goes on through a joint's master,
// e.g. a column through a connection whose beam has a joint, is not cut), in
// line within kInLine in the reference configuration; distances are along it, in the reference
// configuration, between the elements' midpoints: an element is held when its
// midpoint lies nearer than the zone length to the open hinge's. Open hinges
// count whether softening or failed.
//
// An element end that carries no moment holds its zone the same way, from the
// end node: a free or pinned end (the element alone holds the node, its
// rotation free and no nodal moment on it), and the nodes of a joint (made
// from a midpoint or an end hinge, or given) where the element alone holds
// its side of it (a joint's slave; its master unless other members meet
// there and carry the moment between them). Next to such a section the
// moment grows as V x from zero, so within Mu/Vu of it no second hinge
// forms: a hinge that became a joint hands its zone to the joint (on both
// sides), and a ruptured joint's pieces hold theirs from their free ends, so
// no failed hinge (which would turn freely: elements/HingeToJoint.h nearJoint
// makes no joint there) opens within Lb of a joint or a free end. A hinge
// open there before (one that opened before the joint formed) stays open.
// The zone is the element's material's. Joint friction (SOFTening's Mr) is
// not counted (the moment grows from Mr << Mu). Small-displacement elements
// (the paper's failure phase) and hinges at the element ends are not held.
#include <vector>

#include "core/MaterialSet.h"
#include "core/Model.h"

namespace c2d {

class ReissnerFrame;

// The zone length of a material's midpoint hinges (m; 0: no zone).
double zoneLength(const MaterialSet& mat);

// Sets every geometrically exact element's held flag from the hinges of the
// last evaluated (committed) state. Returns the number of elements held. Its
// work lists are kept between calls: no allocation once sized (a commit's).
class LocalizationZones {
 public:
  int hold(Model& model);

 private:
  std::vector<ReissnerFrame*> frame_;  // per element: a midpoint-hinge frame, else null
  std::vector<int> first_, second_;    // per node: the (first two) elements holding it
  std::vector<int> count_;             // per node: how many elements hold it
  std::vector<char> held_;
};

}  // namespace c2d
