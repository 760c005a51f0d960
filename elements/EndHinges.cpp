#include "elements/EndHinges.h"

#include <algorithm>
#include <cmath>

#include "elements/ElementFactory.h"
#include "elements/InelasticFrame.h"
#include "elements/JointedElement.h"
#include "elements/Joints.h"
#include "elements/ReissnerFrame.h"
#include "materials/HingeLength.h"
#include "materials/RcSection.h"

namespace c2d {

namespace {

// The member's law and section history (innermost element), if it has them.
struct Member {
  const HingedBending* law = nullptr;
  HingedBendingState section;
  InelasticFrame* small = nullptr;
  ReissnerFrame* finite = nullptr;
  void set(const HingedBendingState& s) const {
    if (small) small->setSection(s);
    if (finite) finite->setSection(s);
  }
};

Member memberOf(Element& e) {
  Member m;
  Element& in = innermost(e);
  if (auto* f = dynamic_cast<InelasticFrame*>(&in)) {
    m.small = f;
    m.law = &f->bendingLaw();
    m.section = f->section();
  } else if (auto* r = dynamic_cast<ReissnerFrame*>(&in)) {
    m.finite = r;
    m.law = &r->bendingLaw();
    m.section = r->section();
  }
  return m;
}

bool due(const Member& m) {
  if (!m.law || m.law->site() != HingeSite::Ends) return false;
  return std::abs(m.section.endHinge[0]) == 1 || std::abs(m.section.endHinge[1]) == 1;
}

// M/V at end a from the element's end moments (linear between its ends: the
// faces of rigid end zones, whose moments they are).
double shearSpanAt(const Model& model, const Element& el, const Member& m, int a) {
  const std::array<int, 2> n = el.nodes();
  const std::array<double, 2> o = rigidOffsets(innermost(el));
  const double L = (model.coord(n[1]) - model.coord(n[0])).norm() - o[0] - o[1];
  return shearSpan(L, m.section.endMoment[a], m.section.endMoment[1 - a]);
}

}  // namespace

bool endHingesDue(const Model& model) {
  for (int e = 0; e < model.numElements(); ++e)
    if (model.hasElement(e) && due(memberOf(const_cast<Model&>(model).element(e)))) return true;
  return false;
}

std::vector<OpenedHinge> openEndHinges(Model& model, State& state) {
  std::vector<OpenedHinge> out;
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.hasElement(e)) continue;
    Element& el = model.element(e);
    Member m = memberOf(el);
    if (!due(m)) continue;
    for (int a = 0; a < 2; ++a) {
      if (std::abs(m.section.endHinge[a]) != 1) continue;
      const int sign = m.section.endHinge[a] > 0 ? 1 : -1;
      OpenedHinge h;
      h.element = e;
      h.end = a;
      h.sign = sign;
      std::array<int, 2> nodes = el.nodes();
      h.master = nodes[a];
      const Vec2 x = model.coord(h.master);  // a copy: addNode reallocates the coordinates
      h.slave = model.addNode(x);
      state.resize(model.numNodes());
      const Eigen::Index ms = static_cast<Eigen::Index>(h.master) * kNodeDofs,
                         ss = static_cast<Eigen::Index>(h.slave) * kNodeDofs;
      for (Eigen::VectorXd* v : {&state.u, &state.v, &state.a, &state.un, &state.vn, &state.an})
        v->segment<kNodeDofs>(ss) = v->segment<kNodeDofs>(ms);
      nodes[a] = h.slave;
      el.setNodes(nodes);
      model.joints().push_back(Joint{h.master, h.slave, JointForm::Condensed});
      h.moment = m.section.endMoment[a];
      h.axialForce = m.section.N;
      const auto& capacity = m.law->capacity();
      if (capacity) {
        h.ultimate = capacity->at(sign, m.section.N).Mu;
        h.failureJump = capacity->failureJump(sign, m.section.N, shearSpanAt(model, el, m, a));
        if (const MaterialSet* mat = model.material(innermost(el).materialNumber()); mat && mat->rc)
          h.shearSpan = boundedShearSpan(shearSpanAt(model, el, m, a), mat->rc->data().h);
      } else {
        h.ultimate = m.law->softening(sign)->Mu();
        h.failureJump = m.law->softening(sign)->failureJump();
      }
      m.section.endHinge[a] = 2 * sign;
      out.push_back(h);
    }
    m.set(m.section);
  }
  if (out.empty()) return out;
  installJoints(model);
  for (const OpenedHinge& h : out)
    for (JointedElement* je : jointedElements(model))
      if (je->slaveNode() == h.slave) {
        const MaterialSet* mat = model.material(innermost(*je).materialNumber());
        const double mr = mat && mat->softening ? std::min(mat->softening->Mr, 0.5 * h.ultimate) : 0.0;
        je->setHinge(EndHinge(memberOf(model.element(h.element)).law->capacity(), h.sign,
                              h.ultimate, h.failureJump, mr));
      }
  model.bumpTopology();
  return out;
}

double endHingeRatio(const Model& model, int* element) {
  double ratio = 0;
  if (element) *element = -1;
  forEachJointed(model, [&](int e, const JointedElement* j) {
    if (!j->hingeLaw()) return;
    // A spent hinge is a joint with friction Mr, not a capacity Mu(N).
    const HingeInfo h = j->hingeInfo();
    if (h.failed || h.ultimate <= 0 || std::abs(h.moment) / h.ultimate <= ratio) return;
    ratio = std::abs(h.moment) / h.ultimate;
    if (element) *element = e;
  });
  return ratio;
}

}  // namespace c2d
