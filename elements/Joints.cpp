#include "elements/Joints.h"

#include <memory>

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

}  // namespace

std::vector<JointedElement*> jointedElements(Model& model) {
  std::vector<JointedElement*> out;
  for (int e = 0; e < model.numElements(); ++e)
    if (auto* j = dynamic_cast<JointedElement*>(&model.element(e))) out.push_back(j);
  return out;
}

std::vector<const JointedElement*> jointedElements(const Model& model) {
  std::vector<const JointedElement*> out;
  for (int e = 0; e < model.numElements(); ++e)
    if (auto* j = dynamic_cast<const JointedElement*>(&model.element(e))) out.push_back(j);
  return out;
}

int installJoints(Model& model) {
  int changed = 0;
  for (Joint& joint : model.joints()) {
    if (joint.form != JointForm::Condensed) continue;
    bool installed = false;
    for (const JointedElement* je : jointedElements(model))
      if (je->slaveNode() == joint.slave) installed = true;
    if (installed) continue;

    int attached = 0, element = -1, end = -1;
    for (int e = 0; e < model.numElements(); ++e) {
      const auto n = model.element(e).nodes();
      for (int a = 0; a < 2; ++a)
        if (n[a] == joint.slave) {
          ++attached;
          element = e;
          end = a;
        }
    }
    if (attached == 0) continue;
    if (attached > 1 || carriesNodalData(model, joint.slave) ||
        isMasterOfAnotherJoint(model, joint.slave)) {
      joint.form = JointForm::Shared;
      ++changed;
      continue;
    }
    auto& slot = model.elements()[element];
    slot = std::make_unique<JointedElement>(std::move(slot), end, joint.master);
    ++changed;
  }
  if (changed) model.bumpTopology();
  return changed;
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
  }
}

}  // namespace c2d
