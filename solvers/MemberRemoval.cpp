#include "solvers/MemberRemoval.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "elements/Joints.h"
#include "solvers/Analysis.h"

namespace c2d {

double MemberRemoval::tolerance(double dt) { return 1e-9 * std::max(std::abs(dt), 1e-12); }

double MemberRemoval::nextLanding(double t) const {
  const Model& model = an_.model_;
  const double eps = tolerance(an_.state_.dt);
  double next = std::numeric_limits<double>::infinity();
  for (const Blast& b : model.blasts())
    if (!b.done && b.time > t + eps) next = std::min(next, b.time);
  for (const ReleasedForce& f : model.releasedForces())
    if (f.start + f.duration > t + eps) next = std::min(next, f.start + f.duration);
  return next;
}

std::string MemberRemoval::leavesNothing(const std::vector<int>& elements) const {
  const Model& model = an_.model_;
  int left = 0;
  for (int e = 0; e < model.numElements(); ++e) left += model.hasElement(e) ? 1 : 0;
  int removed = 0;
  for (int e : elements) removed += model.hasElement(e) ? 1 : 0;
  if (left == 0 || removed < left) return {};
  return "no element would be left: " +
         std::string(left == 1 ? "the model's last element is"
                               : "every element of the model (" + std::to_string(left) + ") is") +
         " in the list";
}

Status MemberRemoval::afterCommit(bool& changed) {
  Model& model = an_.model_;
  const double t = an_.state_.tn;
  const double eps = tolerance(an_.state_.dt);
  changed = false;
  // Released forces that ended at or before t_n are zero from now on.
  auto& released = model.releasedForces();
  const auto ended = std::remove_if(released.begin(), released.end(), [&](const ReleasedForce& f) {
    return f.start + f.duration <= t + eps;
  });
  if (ended != released.end()) {
    released.erase(ended, released.end());
    changed = true;
  }
  for (std::size_t k = 0; k < model.blasts().size(); ++k) {
    Blast& b = model.blasts()[k];
    if (b.done || b.time > t + eps) continue;
    b.done = true;
    std::vector<int> present, gone;
    for (int e : b.elements)
      (e < model.numElements() && model.hasElement(e) ? present : gone).push_back(e);
    if (const std::string why = leavesNothing(present); !why.empty()) {
      char when[64];
      std::snprintf(when, sizeof when, "the blast at t = %.6e: ", b.time);
      return Status::failure(when + why);
    }
    const double release = b.release;  // b may move: remove() does not touch the blast list
    RemovalEvent ev;
    if (present.empty()) {  // nothing left to blast: the model stays as it is
      ev.time = t;
      ev.release = release;
      ev.scheduled = true;
    } else {
      ev = remove(present, release, true);
      changed = true;
    }
    ev.goneBefore = std::move(gone);
    ev.origin = model.blasts()[k].origin;
    ev.blast = static_cast<int>(k);
    if (onEvent) onEvent(ev);
  }
  return Status::success();
}

Status MemberRemoval::removeNow(const std::vector<int>& elements, double release) {
  const Model& model = an_.model_;
  for (int e : elements)
    if (e < 0 || e >= model.numElements() || !model.hasElement(e))
      return Status::failure("element " + std::to_string(e + 1) + " is not in the model" +
                             (e >= 0 && e < model.numElements() ? " (removed before)" : ""));
  if (const std::string why = leavesNothing(elements); !why.empty()) return Status::failure(why);
  const RemovalEvent ev = remove(elements, release, false);
  if (onEvent) onEvent(ev);
  return Status::success();
}

RemovalEvent MemberRemoval::remove(const std::vector<int>& elements, double release,
                                   bool scheduled) {
  Model& model = an_.model_;
  State& state = an_.state_;
  Assembler& assembler = an_.assembler_;
  RemovalEvent ev;
  ev.time = state.tn;
  ev.release = release;
  ev.scheduled = scheduled;
  if (assembler.patternVersion() != model.topologyVersion()) an_.topologyChanged();
  const Energy before = an_.energy();
  const std::vector<char> usedBefore = [&] {
    std::vector<char> used(model.numNodes(), 0);
    for (int n = 0; n < model.numNodes(); ++n) used[n] = assembler.dofs().used(n);
    return used;
  }();

  // What the removed elements did to the rest: their forces of the last
  // assembly (internal and inertia: the account's forces at t_n), and, for a
  // release over time, their internal forces at the committed displacements
  // with their weight, as a load.
  const Eigen::Index nd = static_cast<Eigen::Index>(model.numNodes()) * kNodeDofs;
  Eigen::VectorXd forcesN = Eigen::VectorXd::Zero(nd);
  const Eigen::VectorXd gravityBefore = assembler.gravityLoad();
  const StepRule statics{};
  for (int e : elements) {
    Element& el = model.element(e);
    const auto nodes = el.nodes();
    const ElemVec& r = assembler.elementForce(e);
    for (int a = 0; a < 2; ++a)
      forcesN.segment<kNodeDofs>(static_cast<Eigen::Index>(nodes[a]) * kNodeDofs) +=
          r.segment<kNodeDofs>(a * kNodeDofs);
    if (release > 0) {
      // At rest at the committed displacements.
      ElementKinematics kin = state.kinematics(nodes);
      kin.d = kin.dn;
      kin.vn.setZero();
      kin.an.setZero();
      // Evaluated there a moment ago under the step's rule: a failure now
      // leaves its forces of that evaluation.
      ElemVec f;
      ElemMat k;
      if (!el.evaluate(kin, statics, false, f, k)) f = r;
      // The constant loads it carried: self-weight and floor loads (QLOAd).
      ElemVec carried = el.bodyLoad(model.gravity());
      for (const ElementLoad& l : model.elementLoads())
        if (l.element == e) {
          const double length = (model.coord(nodes[1]) - model.coord(nodes[0])).norm();
          for (int a = 0; a < 2; ++a) carried.segment<2>(a * kNodeDofs) += 0.5 * length * l.q;
        }
      ReleasedForce rf;
      rf.nodes = nodes;
      rf.force = carried - f;
      rf.start = state.tn;
      rf.duration = release;
      model.releasedForces().push_back(rf);
    }
  }
  for (int e : elements) model.removeElement(e);
  ev.elements = elements;
  ev.jointsDissolved = static_cast<int>(dissolveLooseJoints(model, state).size());
  an_.topologyChanged();
  for (int n = 0; n < model.numNodes(); ++n)
    if (usedBefore[n] && !assembler.dofs().used(n)) ev.nodesLeaving.push_back(n);

  // The account: the stored energy that left, the forces at t_n without the
  // removed elements, the released load from now on.
  const Energy after = an_.energy();
  ev.energy = (before.kinetic + before.strain + before.contact) -
              (after.kinetic + after.strain + after.contact);
  an_.account_.removed(forcesN, gravityBefore - assembler.gravityLoad(), after);
  return ev;
}

}  // namespace c2d
