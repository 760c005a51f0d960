#include "elements/HingeToJoint.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "core/Brace.h"
#include "core/Hinge.h"
#include "elements/ElementFactory.h"
#include "elements/InelasticFrame.h"
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
  Vec2 shiftVel = Vec2::Zero(), shiftAcc = Vec2::Zero();  // a joint at a rigid zone's face
};

const ReissnerFrame* asReissner(const Element& e) {
  return dynamic_cast<const ReissnerFrame*>(&innermost(e));
}

// The bending section history of an element with a hinge law, if it has one.
std::optional<HingedBendingState> sectionOf(const Element& e) {
  const Element& in = innermost(e);
  if (auto* r = dynamic_cast<const ReissnerFrame*>(&in)) return r->section();
  if (auto* f = dynamic_cast<const InelasticFrame*>(&in)) return f->section();
  return std::nullopt;
}

// The shortest piece Lb of the element's material (SOFTening's; 0: none).
double pieceLength(const Model& model, const Element& e) {
  const MaterialSet* mat = model.material(innermost(e).materialNumber());
  return mat && mat->softening ? mat->softening->pieceLength : 0.0;
}

// A node within the distance lb of a section that carries no moment (in the
// reference configuration: the distance along the material): an intact
// joint's node other than that node itself (a second member may break at a
// connection where one has), or a free end other than one at the node's own
// place (the piece a ruptured joint set free: the members left at the
// connection may still break there). Next to a section with no moment the
// moment grows as V x from zero, so a member that cannot carry more shear
// than Vu cannot open a second hinge nearer than Mu/Vu: the failed hinge
// there lies in that section's zone and stays as it is. A ruptured joint
// leaves a free end where it was: were the failed hinges it kept from
// jointing released then, they would become joints far beyond thetaR and
// rupture at once, each setting free a piece shorter than Lb.
bool nearJoint(const Model& model, const std::vector<int>& attached, int node, double lb) {
  if (!(lb > 0)) return false;
  const Vec2 x = model.coord(node);
  for (const Joint& j : model.joints())
    if (j.master != node && (model.coord(j.master) - x).norm() < lb) return true;
  // attached may predate the joints' nodes made in this pass: none is free.
  return nearFreeEnd(model, attached, node, lb);
}

// Ends of an element that already carry a joint (its wrappers' slave ends).
std::array<bool, 2> jointedEnds(const Element& e) {
  std::array<bool, 2> ends{false, false};
  for (auto* j = asJointed(&e); j; j = asJointed(&j->inner())) ends[j->slaveEnd()] = true;
  return ends;
}

[[noreturn]] void fail(int element, const std::string& why) {
  throw AnalysisError("HINGE2JOINT: element " + std::to_string(element + 1) + ": " + why);
}

// What the joint-making knows of every element before it rebuilds any.
struct Survey {
  std::vector<char> rebuild, joint;  // rebuild: 2 always, 1 for its joint
  std::vector<SectionForces> forces;
  std::vector<std::optional<HingedBendingState>> sections;
  std::vector<ElemVec> endForces;
  std::map<int, Relative> slaves;  // slave node -> its joint's master and relative state
  std::map<int, int> hingeEnd;     // element -> end that gets the slave
};

// 1. Section forces (and end moments) of every element to be rebuilt, at the
//    current displacements.
Survey surveyElements(Model& model, const State& state,
                      const std::function<bool(const Element&, const HingeInfo&)>& wantsJoint,
                      const std::function<bool(const Element&)>& rebuildAlways) {
  const StepRule statics{};
  const int ne = model.numElements();
  Survey s;
  s.rebuild.assign(ne, 0);
  s.joint.assign(ne, 0);
  s.forces.resize(ne);
  s.sections.resize(ne);
  s.endForces.assign(ne, ElemVec::Zero());
  for (int e = 0; e < ne; ++e) {
    if (!model.hasElement(e) || isBrace(model.element(e))) continue;  // struts stay as they are
    Element& el = model.element(e);
    const auto* carrier = dynamic_cast<const HingeCarrier*>(&innermost(el));
    s.joint[e] = carrier && wantsJoint(el, carrier->hinge());
    s.rebuild[e] = rebuildAlways(el) ? 2 : s.joint[e];
    if (!s.rebuild[e]) continue;
    // The innermost element at the joints' relative rotations and rates as
    // committed (the call comes after a commit: trial and committed agree):
    // they belong to the motion so far (a static solve of the joints would
    // move them, and change the stored energy at the switch). Its end moments
    // choose the joint's end; a joint's own end carries none.
    ElemVec r;
    ElemMat k;
    Element& in = innermost(el);
    if (Status st = in.evaluate(innermostKinematics(el, state), statics, false, r, k); !st)
      fail(e, st.why);
    for (auto* je = asJointed(&el); je; je = asJointed(&je->inner()))
      s.slaves[je->slaveNode()] =
          Relative{je->masterNode(), je->committedRelativeRotation(),
                   je->committedRelativeVelocity(), je->committedRelativeAcceleration(),
                   je->committedShiftVelocity(), je->committedShiftAcceleration()};
    s.forces[e] = in.sectionForces();
    s.sections[e] = sectionOf(el);
    s.endForces[e] = r;
  }
  return s;
}

// The end of element e whose section the hinge lies nearer (a tie: the end
// with the larger moment).
int hingeSide(const HingeInfo& h, const ElemVec& endForces) {
  int end = 0;
  if (h.position > 0.5 + kTieTolerance) {
    end = 1;
  } else if (std::abs(h.position - 0.5) <= kTieTolerance) {
    const double m1 = std::abs(endForces(2)), m2 = std::abs(endForces(5));
    end = m2 > m1 + kTieTolerance * (m1 + m2) ? 1 : 0;
  }
  return end;
}

// 2. A joint for every hinge that asks for one.
std::vector<CreatedJoint> placeJoints(Model& model, Survey& s) {
  std::vector<CreatedJoint> created;
  const std::vector<int> attached = nodeAttachments(model);
  for (int e = 0; e < static_cast<int>(s.joint.size()); ++e) {
    if (!s.joint[e]) continue;
    const HingeInfo h = dynamic_cast<const HingeCarrier&>(innermost(model.element(e))).hinge();
    int end = hingeSide(h, s.endForces[e]);
    const std::array<bool, 2> taken = jointedEnds(model.element(e));
    const std::array<int, 2> ends = model.element(e).nodes();
    // A member breaks where it carries a moment to the rest, never at a free
    // end (elements/Joints.h). With no other end the hinge stays as it is (a
    // failed one carries no moment).
    const double shortest = pieceLength(model, model.element(e));
    auto breaks = [&](int a) {
      return !taken[a] && !freeEnd(model, ends[a], attached[ends[a]]) &&
             !nearJoint(model, attached, ends[a], shortest);
    };
    if (!breaks(end)) end = 1 - end;
    if (!breaks(end)) {
      s.joint[e] = 0;
      if (s.rebuild[e] == 1) s.rebuild[e] = 0;  // nothing to rebuild it for
      continue;
    }
    CreatedJoint cj;
    cj.element = e;
    cj.slaveEnd = end;
    cj.master = ends[end];
    const Vec2 x = model.coord(cj.master);  // a copy: addNode reallocates the coordinates
    cj.slave = model.addNode(x);
    cj.position = h.position;
    cj.jump = h.jump;
    cj.relativeRotation = end == 0 ? h.jump : -h.jump;
    s.slaves[cj.slave] = Relative{cj.master, cj.relativeRotation, 0, 0, Vec2::Zero(), Vec2::Zero()};
    s.hingeEnd[e] = end;
    created.push_back(cj);
  }
  return created;
}

// The material of the rebuilt element: finite kinematics, and with elastic
// member laws none of the inelastic ones.
MaterialSet rebuiltMaterial(const Model& model, const Element& old, int e, MemberLaws laws) {
  const MaterialSet* source = model.material(old.materialNumber());
  if (!source) fail(e, "material set " + std::to_string(old.materialNumber()) + " is missing");
  MaterialSet mat = *source;
  mat.kinematics = Kinematics::Finite;
  if (laws == MemberLaws::Elastic) {
    mat.hardening.reset();
    mat.softening.reset();
    mat.section.reset();
    mat.rc.reset();
    mat.capacity.reset();
  }
  return mat;
}

// Displacements the new element sees: a slave end moves with its master and
// rotates by psi_m + psi_r; with a rigid end zone its face moves with the
// master's arm (the slave node shifted, elements/JointedElement.h).
ElemVec rebuiltDisplacements(const State& state, const ReissnerFrame& frame,
                             const std::array<int, 2>& nodes,
                             const std::map<int, Relative>& slaves) {
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
    const double psiM = d(a * kNodeDofs + 2);
    d(a * kNodeDofs + 2) += extra;
    const RigidEnds& rigid = frame.rigidEnds();
    d.segment<2>(a * kNodeDofs) += rigid.armMotion(a, psiM) - rigid.armMotion(a, psiM + extra);
  }
  return d;
}

// 3. Element e rebuilt as a Reissner beam with the old section forces.
void rebuildElement(Model& model, const State& state, int e, MemberLaws laws, const Survey& s,
                    const std::vector<CreatedJoint>& created) {
  std::unique_ptr<Element> old = std::move(model.elements()[e]);
  while (auto* je = asJointed(old.get())) old = je->release();
  std::array<int, 2> nodes = old->nodes();
  if (auto it = s.hingeEnd.find(e); it != s.hingeEnd.end()) {
    for (const CreatedJoint& cj : created)
      if (cj.element == e) nodes[it->second] = cj.slave;
  }
  const MaterialSet mat = rebuiltMaterial(model, *old, e, laws);
  auto frame = std::make_unique<ReissnerFrame>(mat, nodes, model.coord(nodes[0]),
                                               model.coord(nodes[1]), rigidOffsets(*old));
  const ElemVec d = rebuiltDisplacements(state, *frame, nodes, s.slaves);
  const SectionForces& f = s.forces[e];
  const Vec3 c = frame->sectionStiffness();
  double kp = 0;
  if (!frame->bendingLaw().isElastic()) {
    HingedBendingState section = s.sections[e].value_or(HingedBendingState{});
    if (s.joint[e]) {  // the jump went into the joint: the section closes, capacity fresh
      section.jump = SofteningState{};
      section.hingeActive = section.hingeFailed = false;
    }
    section.M = f.M;
    // A hinge kept (no end to break at) keeps its jump in the bulk curvature.
    kp = section.bulk.kp + section.jump.alpha / frame->length();
    frame->setSection(section);
  }
  frame->setInitialStrain(frame->strains(d) - Vec3(f.N / c(0), f.V / c(1), kp + f.M / c(2)));
  model.elements()[e] = std::move(frame);
}

// 4. Wrap the slave ends, restore the relative states, write the slave nodes.
void restoreJoints(Model& model, State& state, const std::map<int, Relative>& slaves) {
  installJoints(model);
  for (JointedElement* je : jointedElements(model)) {
    auto it = slaves.find(je->slaveNode());
    if (it == slaves.end()) continue;
    je->setRelativeState(it->second.psi, it->second.vel, it->second.acc, it->second.shiftVel,
                         it->second.shiftAcc);
  }
  syncSlaveNodes(model, state);
  state.un = state.u;
  state.vn = state.v;
  state.an = state.a;
  state.tn = state.t;
  state.propn = state.prop;
  state.arcLambdan = state.arcLambda;
}

// 5. Report and history of the new elements at that state.
void commitRebuilt(Model& model, const State& state, const std::vector<char>& rebuild) {
  const StepRule statics{};
  for (int e = 0; e < static_cast<int>(rebuild.size()); ++e) {
    if (!rebuild[e]) continue;
    Element& el = model.element(e);
    ElemVec r;
    ElemMat k;
    Element& in = innermost(el);
    if (Status st = in.evaluate(innermostKinematics(el, state), statics, false, r, k); !st)
      fail(e, st.why);
    in.commit();
  }
}

// The joint-making shared by HINGE2JOINT and the joints of failed hinges:
// elements for which wantsJoint() holds get a joint, elements for which
// rebuild() holds (and those) are rebuilt as Reissner beams.
std::vector<CreatedJoint> convert(
    Model& model, State& state, MemberLaws laws,
    const std::function<bool(const Element&, const HingeInfo&)>& wantsJoint,
    const std::function<bool(const Element&)>& rebuildAlways) {
  state.resize(model.numNodes());
  Survey s = surveyElements(model, state, wantsJoint, rebuildAlways);
  std::vector<CreatedJoint> created = placeJoints(model, s);
  state.resize(model.numNodes());
  for (int e = 0; e < static_cast<int>(s.rebuild.size()); ++e)
    if (s.rebuild[e]) rebuildElement(model, state, e, laws, s, created);
  for (const CreatedJoint& cj : created)
    model.joints().push_back(Joint{cj.master, cj.slave, JointForm::Condensed});
  restoreJoints(model, state, s.slaves);
  commitRebuilt(model, state, s.rebuild);
  if (std::any_of(s.rebuild.begin(), s.rebuild.end(), [](char r) { return r != 0; }))
    model.bumpTopology();
  return created;
}

}  // namespace

std::vector<CreatedJoint> hingeToJoint(Model& model, State& state, MemberLaws laws) {
  const auto active = [](const Element&, const HingeInfo& h) { return h.active; };
  const auto rebuild = [laws](const Element& e) {
    const ReissnerFrame* r = asReissner(e);
    return !r || (laws == MemberLaws::Elastic && !r->bendingLaw().isElastic());
  };
  return convert(model, state, laws, active, rebuild);
}

bool jointsWhenFailed(const Model& model, const std::vector<int>& attached, const Element& e) {
  if (!asReissner(e)) return false;
  const std::array<bool, 2> taken = jointedEnds(e);
  const std::array<int, 2> ends = e.nodes();
  const double shortest = pieceLength(model, e);
  for (int a = 0; a < 2; ++a)
    if (!taken[a] && !freeEnd(model, ends[a], attached[ends[a]]) &&
        !nearJoint(model, attached, ends[a], shortest))
      return true;
  return false;
}

std::vector<CreatedJoint> jointFailedHinges(Model& model, State& state) {
  // Only geometrically exact elements: the failure phase keeps its embedded
  // hinges. An element that already carries a joint at one end gets the new
  // one at its other end (the end of the larger moment: the joint's moment is
  // zero): the member, failed twice, becomes a link pinned at both ends. An
  // element with no end left to break at (free ends, joints) keeps its
  // failed hinge.
  const std::vector<int> attached = nodeAttachments(model);
  const auto failed = [&](const Element& e, const HingeInfo& h) {
    return h.active && h.failed && jointsWhenFailed(model, attached, e);
  };
  bool any = false;
  for (int e = 0; e < model.numElements() && !any; ++e)
    if (!model.hasElement(e))
      continue;
    else if (auto* c = dynamic_cast<const HingeCarrier*>(&innermost(model.element(e))))
      any = failed(model.element(e), c->hinge());
  if (!any) return {};
  return convert(model, state, MemberLaws::Inelastic, failed, [](const Element&) { return false; });
}

}  // namespace c2d
