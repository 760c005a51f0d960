#include "elements/Joints.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/contact/GroundContact.h"

namespace c2d {

namespace {

bool carriesNodalData(const Model& model, int node) {
  for (int d = 0; d < kNodeDofs; ++d)
    if (model.bound(node)[d] != 0 || model.force(node)[d] != 0 || model.disp(node)[d] != 0)
      return true;
  return false;
}

bool isMasterOfAnotherJoint(const Model& model, int node) {
  for (const Joint& j : model.joints())
    if (j.master == node) return true;
  return false;
}

// The element at the slave of a joint and its end there, when exactly one.
struct Attached {
  int count = 0, element = -1, end = -1;
};
Attached attachedTo(const Model& model, int node) {
  Attached out;
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    const auto n = model.element(e).nodes();
    for (int a = 0; a < 2; ++a)
      if (n[a] == node) {
        ++out.count;
        out.element = e;
        out.end = a;
      }
  }
  return out;
}

bool condensableWith(const Model& model, const Joint& joint, const Attached& at) {
  return at.count == 1 && !carriesNodalData(model, joint.slave) &&
         !isMasterOfAnotherJoint(model, joint.slave);
}

}  // namespace

bool condensable(const Model& model, const Joint& joint) {
  return condensableWith(model, joint, attachedTo(model, joint.slave));
}

std::vector<int> nodeAttachments(const Model& model, const std::vector<char>& gone) {
  std::vector<int> attached(model.numNodes(), 0);
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e))
      for (int node : model.element(e).nodes()) ++attached[node];
  for (std::size_t k = 0; k < model.joints().size(); ++k)
    if (k >= gone.size() || !gone[k])
      attached[model.joints()[k].master] = attached[model.joints()[k].slave] = 2;
  return attached;
}

bool freeEnd(const Model& model, int node, int attachments) {
  return attachments == 1 && model.bound(node)[2] == 0 && model.force(node)[2] == 0;
}

std::vector<int> freeEnds(const Model& model, const std::vector<int>& attached) {
  std::vector<int> ends;
  for (int n = 0; n < static_cast<int>(attached.size()); ++n)
    if (freeEnd(model, n, attached[n])) ends.push_back(n);
  return ends;
}

int freeEndWithin(const Model& model, const std::vector<int>& ends, int node, double lb) {
  if (!(lb > 0)) return -1;
  constexpr double kCoincident = 1e-9;  // of lb: nodes at one place (a ruptured joint's)
  const Vec2 x = model.coord(node);
  int nearest = -1;
  double best = lb;
  for (int n : ends) {
    if (n == node) continue;
    const double d = (model.coord(n) - x).norm();
    if (d < best && d > kCoincident * lb) {
      best = d;
      nearest = n;
    }
  }
  return nearest;
}

bool nearFreeEnd(const Model& model, const std::vector<int>& attached, int node, double lb) {
  return lb > 0 && freeEndWithin(model, freeEnds(model, attached), node, lb) >= 0;
}

double jointFriction(const Model& model, int node) {
  double Mr = 0;
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    const auto n = model.element(e).nodes();
    if (n[0] != node && n[1] != node) continue;
    const MaterialSet* mat = model.material(innermost(model.element(e)).materialNumber());
    if (mat && mat->softening) Mr = std::max(Mr, mat->softening->Mr);
  }
  return Mr;
}

Element& innermost(Element& e) {
  Element* el = &e;
  while (auto* j = asJointed(el)) el = &j->inner();
  return *el;
}

const Element& innermost(const Element& e) {
  const Element* el = &e;
  while (auto* j = asJointed(el)) el = &j->inner();
  return *el;
}

ElementKinematics innermostKinematics(const Element& e, const State& state) {
  ElementKinematics kin = state.kinematics(e.nodes());
  for (const Element* el = &e; const auto* je = asJointed(el); el = &je->inner())
    kin = je->innerKinematics(kin, je->relativeRotation());
  return kin;
}

std::vector<JointedElement*> jointedElements(Model& model) {
  std::vector<JointedElement*> out;
  forEachJointed(model, [&](int, JointedElement* j) { out.push_back(j); });
  return out;
}

std::vector<const JointedElement*> jointedElements(const Model& model) {
  std::vector<const JointedElement*> out;
  forEachJointed(model, [&](int, const JointedElement* j) { out.push_back(j); });
  return out;
}

int installJoints(Model& model) {
  int changed = 0;
  // The slaves that have their wrapper (one pass over the elements, not one per joint).
  std::vector<char> installed(model.numNodes(), 0);
  for (const JointedElement* je : jointedElements(model)) installed[je->slaveNode()] = 1;
  for (Joint& joint : model.joints()) {
    if (joint.form != JointForm::Condensed) continue;
    if (installed[joint.slave]) continue;

    const Attached at = attachedTo(model, joint.slave);
    if (at.count == 0) continue;
    if (!condensableWith(model, joint, at)) {
      joint.form = JointForm::Shared;
      ++changed;
      continue;
    }
    const int element = at.element, end = at.end;
    auto& slot = model.elements()[element];
    auto jointed = std::make_unique<JointedElement>(std::move(slot), end, joint.master);
    // The broken section's residual moment (SOFTening's Mr), regularised over
    // the member's elastic rotation under it.
    if (const MaterialSet* mat = model.material(innermost(*jointed).materialNumber());
        mat && mat->softening && mat->softening->Mr > 0 && mat->EI() > 0) {
      const auto n = jointed->nodes();
      const double l = (model.coord(n[0]) - model.coord(n[1])).norm();
      jointed->setFriction(mat->softening->Mr, mat->softening->Mr * l / mat->EI());
    }
    slot = std::move(jointed);
    installed[joint.slave] = 1;
    ++changed;
  }
  if (changed) model.bumpTopology();
  return changed;
}

std::unique_ptr<Element> withoutJoint(std::unique_ptr<Element> el, int slave) {
  auto* je = asJointed(el.get());
  if (!je) return el;
  if (je->slaveNode() == slave) return je->release();
  je->replaceInner(withoutJoint(je->takeInner(), slave));
  return el;
}

namespace {

// The elements at each node (a condensed joint's element counts at its master).
std::vector<int> elementsAtNodes(const Model& model) {
  std::vector<int> count(model.numNodes(), 0);
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e))
      for (int n : model.element(e).nodes()) ++count[n];
  return count;
}

}  // namespace

std::vector<Joint> dissolveLooseJoints(Model& model, State& state) {
  std::vector<Joint> out;
  bool synced = false;
  // One pass per joint removed: dissolving one changes the counts of the others.
  for (bool again = true; again;) {
    again = false;
    const std::vector<int> count = elementsAtNodes(model);
    for (std::size_t k = 0; k < model.joints().size() && !again; ++k) {
      const Joint joint = model.joints()[k];
      int holder = -1;  // the element wrapped at a condensed joint's slave
      if (joint.form == JointForm::Condensed)
        for (int e = 0; e < model.numElements() && holder < 0; ++e) {
          if (!model.hasElement(e)) continue;
          for (auto* je = asJointed(&model.element(e)); je; je = asJointed(&je->inner()))
            if (je->slaveNode() == joint.slave) holder = e;
        }
      // Condensed: its element is gone, or nothing but it holds the master.
      // Shared: one side has no element left.
      const bool loose = joint.form == JointForm::Condensed
                             ? holder < 0 || count[joint.master] <= 1
                             : count[joint.master] == 0 || count[joint.slave] == 0;
      if (!loose) continue;
      if (!synced) {
        syncSlaveNodes(model, state);
        synced = true;
      }
      if (holder >= 0)
        model.elements()[holder] = withoutJoint(std::move(model.elements()[holder]), joint.slave);
      model.joints().erase(model.joints().begin() + static_cast<std::ptrdiff_t>(k));
      out.push_back(joint);
      again = true;
    }
  }
  if (!out.empty()) model.bumpTopology();
  return out;
}

namespace {

// Per node: the lowest element that holds it (nodes() of the outermost wrapper)
// and the lowest element with a joint wrapper whose slave it is; -1: none. One
// pass over the elements serves every joint of ruptureJoints (a search over the
// elements per joint made every commit of the ten-storey falls cost
// joints x elements dynamic casts).
void jointHolders(const Model& model, std::vector<int>& holder, std::vector<int>& wrapper) {
  holder.assign(model.numNodes(), -1);
  wrapper.assign(model.numNodes(), -1);
  for (int e = model.numElements() - 1; e >= 0; --e) {
    if (!model.hasElement(e)) continue;
    for (int n : model.element(e).nodes()) holder[n] = e;
    for (auto* je = asJointed(&model.element(e)); je; je = asJointed(&je->inner()))
      wrapper[je->slaveNode()] = e;
  }
}

}  // namespace

std::vector<RupturedJoint> ruptureJoints(Model& model, State& state, std::vector<HeldJoint>* held) {
  std::vector<RupturedJoint> out;
  if (model.joints().empty()) return out;
  std::vector<char> gone(model.joints().size(), 0);
  bool synced = false;
  std::vector<int> holder, wrapper, ends;
  bool indexed = false;  // a rupture of a condensed joint changes the wrappers
  bool counted = false;  // ends: the free ends, the joints gone counted out
  for (std::size_t k = 0; k < model.joints().size(); ++k) {
    const Joint& joint = model.joints()[k];
    if (!indexed) {
      jointHolders(model, holder, wrapper);
      indexed = true;
    }
    int element = -1;
    double rotation = 0;
    if (joint.form == JointForm::Condensed) {
      element = wrapper[joint.slave];
      if (element >= 0)
        for (auto* je = asJointed(&model.element(element)); je; je = asJointed(&je->inner()))
          if (je->slaveNode() == joint.slave) rotation = je->committedRelativeRotation();
    } else {
      element = holder[joint.slave];
      if (element >= 0)
        rotation = state.un[joint.slave * kNodeDofs + 2] - state.un[joint.master * kNodeDofs + 2];
    }
    if (element < 0) continue;
    const MaterialSet* mat = model.material(innermost(model.element(element)).materialNumber());
    if (!mat || !mat->softening || !mat->softening->thetaR) continue;
    const double limit = *mat->softening->thetaR;
    if (!(std::abs(rotation) > limit)) continue;
    // Not while the joint presses on the ground: the new node would get a
    // penalty force of its own at the master's penetration p, k p^2 / 2 of
    // energy out of nothing that throws the pieces apart. The joint ruptures
    // when its node leaves the ground (it turns freely meanwhile).
    if (const auto& g = model.ground();
        g &&
        penetration(*g, model.coord(joint.master).y() +
                            state.un[static_cast<Eigen::Index>(joint.master) * kNodeDofs + 1]) > 0)
      continue;
    if (const double lb = mat->softening->pieceLength; lb > 0) {
      if (!counted) {
        ends = freeEnds(model, nodeAttachments(model, gone));
        counted = true;
      }
      if (const int end = freeEndWithin(model, ends, joint.master, lb); end >= 0) {
        if (held) held->push_back({joint.master, joint.slave, element, end, rotation, limit, lb});
        continue;
      }
    }
    if (!synced) {  // the slave nodes' state from the joints, before any is removed
      syncSlaveNodes(model, state);
      synced = true;
    }
    if (joint.form == JointForm::Condensed) {
      model.elements()[element] = withoutJoint(std::move(model.elements()[element]), joint.slave);
      indexed = false;
    }
    gone[k] = 1;
    counted = false;
    out.push_back(RupturedJoint{joint.master, joint.slave, element, rotation, limit});
  }
  if (out.empty()) return out;
  std::vector<Joint> kept;
  for (std::size_t k = 0; k < model.joints().size(); ++k)
    if (!gone[k]) kept.push_back(model.joints()[k]);
  model.joints() = std::move(kept);
  model.bumpTopology();
  return out;
}

void syncSlaveNodes(const Model& model, State& state) {
  if (state.u.size() < static_cast<Eigen::Index>(model.numNodes()) * kNodeDofs)
    state.resize(model.numNodes());
  for (const JointedElement* je : jointedElements(model)) {
    const Eigen::Index m = static_cast<Eigen::Index>(je->masterNode()) * kNodeDofs;
    const Eigen::Index s = static_cast<Eigen::Index>(je->slaveNode()) * kNodeDofs;
    state.u.segment<kNodeDofs>(s) = state.u.segment<kNodeDofs>(m);
    state.v.segment<kNodeDofs>(s) = state.v.segment<kNodeDofs>(m);
    state.a.segment<kNodeDofs>(s) = state.a.segment<kNodeDofs>(m);
    state.un.segment<kNodeDofs>(s) = state.un.segment<kNodeDofs>(m);
    state.vn.segment<kNodeDofs>(s) = state.vn.segment<kNodeDofs>(m);
    state.an.segment<kNodeDofs>(s) = state.an.segment<kNodeDofs>(m);
    state.u[s + 2] += je->relativeRotation();
    state.v[s + 2] += je->relativeVelocity();
    state.a[s + 2] += je->relativeAcceleration();
    state.un[s + 2] += je->committedRelativeRotation();
    state.vn[s + 2] += je->committedRelativeVelocity();
    state.an[s + 2] += je->committedRelativeAcceleration();
    // A joint at the face of a rigid end zone: the wrapped element's slave
    // node is shifted (JointedElement.h).
    if (je->hasArm()) {
      state.u.segment<2>(s) += je->shiftAt(state.u[m + 2], je->relativeRotation());
      state.v.segment<2>(s) += je->shiftVelocity();
      state.a.segment<2>(s) += je->shiftAcceleration();
      state.un.segment<2>(s) += je->shiftAt(state.un[m + 2], je->committedRelativeRotation());
      state.vn.segment<2>(s) += je->committedShiftVelocity();
      state.an.segment<2>(s) += je->committedShiftAcceleration();
    }
  }
}

}  // namespace c2d
