#include "elements/BarFractures.h"

#include <cmath>

#include "core/contact/GroundContact.h"
#include "core/Hinge.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"

namespace c2d {

namespace {

RcMember* memberOf(Element& e) { return dynamic_cast<RcMember*>(&innermost(e)); }

bool onGround(const Model& model, const State& state, int node) {
  const auto& g = model.ground();
  return g && penetration(*g, model.coord(node).y() +
                                  state.un[static_cast<Eigen::Index>(node) * kNodeDofs + 1]) > 0;
}

}  // namespace

bool fracturesDue(const Model& model) {
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e))
      if (const RcMember* m = memberOf(const_cast<Model&>(model).element(e)); m && m->fractureDue())
        return true;
  return false;
}

std::vector<FracturedMember> separateFractured(Model& model, State& state) {
  std::vector<FracturedMember> out;
  bool synced = false;
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    RcMember* m = memberOf(model.element(e));
    if (!m || !m->fractureDue()) continue;
    Element& el = model.element(e);
    const std::array<int, 2> nodes = el.nodes();
    // The end: a joint's (the broken section; the one turned most), else the
    // end of the larger moment.
    int end = -1;
    double turned = -1;
    for (const JointedElement* j = asJointed(&el); j; j = asJointed(&j->inner()))
      if (std::abs(j->committedRelativeRotation()) > turned) {
        turned = std::abs(j->committedRelativeRotation());
        end = j->slaveEnd();
      }
    FracturedMember f;
    f.element = e;
    f.axialForce = m->axialForce();
    f.shear = m->parting() == Parting::Sheared;
    f.shearForce = m->shearForce();
    f.shearCapacity = m->shearCapacity();
    if (end >= 0) {
      if (onGround(model, state, nodes[end])) continue;
      if (!synced) {  // the slave nodes' state from the joints, before any is removed
        syncSlaveNodes(model, state);
        synced = true;
      }
      int slave = -1;
      for (const JointedElement* j = asJointed(&el); j; j = asJointed(&j->inner()))
        if (j->slaveEnd() == end) slave = j->slaveNode();
      model.elements()[e] = withoutJoint(std::move(model.elements()[e]), slave);
      auto& joints = model.joints();
      for (std::size_t k = 0; k < joints.size(); ++k)
        if (joints[k].slave == slave) {
          joints.erase(joints.begin() + static_cast<std::ptrdiff_t>(k));
          break;
        }
      f.joint = true;
      f.newNode = slave;
    } else {
      const SectionForces s = innermost(el).sectionForces();
      const double l = (model.coord(nodes[1]) - model.coord(nodes[0])).norm();
      end = std::abs(s.M - 0.5 * l * s.V) > std::abs(s.M + 0.5 * l * s.V) ? 1 : 0;
      if (onGround(model, state, nodes[end])) continue;
      const Vec2 x = model.coord(nodes[end]);  // a copy: addNode reallocates the coordinates
      f.newNode = model.addNode(x);
      state.resize(model.numNodes());
      const Eigen::Index from = static_cast<Eigen::Index>(nodes[end]) * kNodeDofs,
                         to = static_cast<Eigen::Index>(f.newNode) * kNodeDofs;
      for (Eigen::VectorXd* v : {&state.u, &state.v, &state.a, &state.un, &state.vn, &state.an})
        v->segment<kNodeDofs>(to) = v->segment<kNodeDofs>(from);
      std::array<int, 2> n = nodes;
      n[end] = f.newNode;
      el.setNodes(n);
    }
    f.end = end;
    f.node = nodes[end];
    memberOf(model.element(e))->fractureDone();
    out.push_back(f);
  }
  if (!out.empty()) model.bumpTopology();
  return out;
}

}  // namespace c2d
