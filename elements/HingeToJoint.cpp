#include "elements/HingeToJoint.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "core/Hinge.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/ReissnerFrame.h"

namespace c2d {

namespace {

// Relative tolerance under which the two end moments of a hinge element count as equal.
constexpr double kTieTolerance = 1e-12;

struct Relative {
  int master = -1;
  double psi = 0, vel = 0, acc = 0;
};

ElementKinematics gather(const std::array<int, 2>& nodes, const State& s) {
  ElementKinematics kin;
  for (int a = 0; a < 2; ++a) {
    const Eigen::Index base = static_cast<Eigen::Index>(nodes[a]) * kNodeDofs;
    kin.d.segment<kNodeDofs>(a * kNodeDofs) = s.u.segment<kNodeDofs>(base);
    kin.dn.segment<kNodeDofs>(a * kNodeDofs) = s.un.segment<kNodeDofs>(base);
    kin.vn.segment<kNodeDofs>(a * kNodeDofs) = s.vn.segment<kNodeDofs>(base);
    kin.an.segment<kNodeDofs>(a * kNodeDofs) = s.an.segment<kNodeDofs>(base);
  }
  return kin;
}

bool isReissner(const Element& e) {
  if (dynamic_cast<const ReissnerFrame*>(&e)) return true;
  if (auto* j = dynamic_cast<const JointedElement*>(&e))
    return dynamic_cast<const ReissnerFrame*>(&j->inner()) != nullptr;
  return false;
}

[[noreturn]] void fail(int element, const std::string& why) {
  throw AnalysisError("HINGE2JOINT: element " + std::to_string(element + 1) + ": " + why);
}

}  // namespace

std::vector<CreatedJoint> hingeToJoint(Model& model, State& state) {
  state.resize(model.numNodes());
  const StepRule statics{};
  const int ne = model.numElements();

  // 1. Section forces (and end moments) of every element to be rebuilt, at the
  //    current displacements.
  std::vector<char> rebuild(ne, 0);
  std::vector<SectionForces> forces(ne);
  std::vector<ElemVec> endForces(ne, ElemVec::Zero());
  std::map<int, Relative> slaves;  // slave node -> its joint's master and relative state
  for (int e = 0; e < ne; ++e) {
    Element& el = model.element(e);
    if (isReissner(el)) continue;
    rebuild[e] = 1;
    ElemVec r;
    ElemMat k;
    if (auto* je = dynamic_cast<JointedElement*>(&el)) {
      // The relative rates belong to the dynamics so far: keep them; the static
      // evaluation only solves psi_r at the current displacements.
      Relative rel{je->masterNode(), 0, je->relativeVelocity(), je->relativeAcceleration()};
      if (Status st = el.evaluate(gather(el.nodes(), state), statics, false, r, k); !st)
        fail(e, st.why);
      rel.psi = je->relativeRotation();
      slaves[je->slaveNode()] = rel;
    } else if (Status st = el.evaluate(gather(el.nodes(), state), statics, false, r, k); !st) {
      fail(e, st.why);
    }
    forces[e] = el.sectionForces();
    endForces[e] = r;
  }

  // 2. A joint for every active hinge.
  std::vector<CreatedJoint> created;
  std::map<int, int> hingeEnd;  // element -> end that gets the slave
  for (int e = 0; e < ne; ++e) {
    if (!rebuild[e] || dynamic_cast<const JointedElement*>(&model.element(e))) continue;
    const auto* carrier = dynamic_cast<const HingeCarrier*>(&model.element(e));
    if (!carrier) continue;
    const HingeInfo h = carrier->hinge();
    if (!h.active) continue;
    int end = 0;
    if (h.position > 0.5 + kTieTolerance) {
      end = 1;
    } else if (std::abs(h.position - 0.5) <= kTieTolerance) {
      const double m1 = std::abs(endForces[e](2)), m2 = std::abs(endForces[e](5));
      end = m2 > m1 + kTieTolerance * (m1 + m2) ? 1 : 0;
    }
    CreatedJoint cj;
    cj.element = e;
    cj.slaveEnd = end;
    cj.master = model.element(e).nodes()[end];
    const Vec2 x = model.coord(cj.master);  // a copy: addNode reallocates the coordinates
    cj.slave = model.addNode(x);
    cj.position = h.position;
    cj.jump = h.jump;
    cj.relativeRotation = end == 0 ? h.jump : -h.jump;
    slaves[cj.slave] = Relative{cj.master, cj.relativeRotation, 0, 0};
    hingeEnd[e] = end;
    created.push_back(cj);
  }
  state.resize(model.numNodes());

  // 3. Every element rebuilt as an elastic Reissner beam with the old section forces.
  for (int e = 0; e < ne; ++e) {
    if (!rebuild[e]) continue;
    std::unique_ptr<Element> old = std::move(model.elements()[e]);
    if (auto* je = dynamic_cast<JointedElement*>(old.get())) old = je->release();
    std::array<int, 2> nodes = old->nodes();
    if (auto it = hingeEnd.find(e); it != hingeEnd.end()) {
      for (const CreatedJoint& cj : created)
        if (cj.element == e) nodes[it->second] = cj.slave;
    }
    const MaterialSet* source = model.material(old->materialNumber());
    if (!source) fail(e, "material set " + std::to_string(old->materialNumber()) + " is missing");
    MaterialSet mat = *source;
    mat.kinematics = Kinematics::Finite;
    mat.hardening.reset();
    mat.softening.reset();
    auto frame =
        std::make_unique<ReissnerFrame>(mat, nodes, model.coord(nodes[0]), model.coord(nodes[1]));

    // Displacements the new element sees: a slave end moves with its master and
    // rotates by psi_m + psi_r.
    ElemVec d;
    for (int a = 0; a < 2; ++a) {
      int node = nodes[a];
      double extra = 0;
      if (auto it = slaves.find(node); it != slaves.end()) {
        node = it->second.master;
        extra = it->second.psi;
      }
      d.segment<kNodeDofs>(a * kNodeDofs) =
          state.u.segment<kNodeDofs>(static_cast<Eigen::Index>(node) * kNodeDofs);
      d(a * kNodeDofs + 2) += extra;
    }
    const SectionForces& f = forces[e];
    const Vec3 c = frame->sectionStiffness();
    frame->setInitialStrain(frame->strains(d) - Vec3(f.N / c(0), f.V / c(1), f.M / c(2)));
    model.elements()[e] = std::move(frame);
  }
  for (const CreatedJoint& cj : created)
    model.joints().push_back(Joint{cj.master, cj.slave, JointForm::Condensed});

  // 4. Wrap the slave ends, restore the relative states, write the slave nodes.
  installJoints(model);
  for (JointedElement* je : jointedElements(model)) {
    auto it = slaves.find(je->slaveNode());
    if (it == slaves.end()) continue;
    je->setRelativeState(it->second.psi, it->second.vel, it->second.acc);
  }
  syncSlaveNodes(model, state);
  state.un = state.u;
  state.vn = state.v;
  state.an = state.a;
  state.tn = state.t;
  state.propn = state.prop;
  state.arcLambdan = state.arcLambda;

  // 5. Report and history of the new elements at that state.
  for (int e = 0; e < ne; ++e) {
    if (!rebuild[e]) continue;
    Element& el = model.element(e);
    ElemVec r;
    ElemMat k;
    if (auto* je = dynamic_cast<JointedElement*>(&el)) {
      const ElementKinematics kin =
          je->innerKinematics(gather(el.nodes(), state), je->relativeRotation());
      if (Status st = je->inner().evaluate(kin, statics, false, r, k); !st) fail(e, st.why);
      je->inner().commit();
    } else {
      if (Status st = el.evaluate(gather(el.nodes(), state), statics, false, r, k); !st)
        fail(e, st.why);
      el.commit();
    }
  }
  if (std::find(rebuild.begin(), rebuild.end(), 1) != rebuild.end()) model.bumpTopology();
  return created;
}

}  // namespace c2d
