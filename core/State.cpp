#include "core/State.h"

#include "core/Types.h"

namespace c2d {

void State::resize(int numNodes) {
  const Eigen::Index n = static_cast<Eigen::Index>(numNodes) * kNodeDofs;
  for (Eigen::VectorXd* x : {&u, &v, &a, &un, &vn, &an}) {
    const Eigen::Index old = x->size();
    x->conservativeResize(n);
    if (n > old) x->tail(n - old).setZero();
  }
  for (Eigen::VectorXd* x : {&crush, &owed, &stretch}) {
    const Eigen::Index old = x->size();
    x->conservativeResize(numNodes);
    if (numNodes > old) x->tail(numNodes - old).setZero();
  }
}

ElementKinematics State::kinematics(const std::array<int, 2>& nodes) const {
  ElementKinematics kin;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Index base = static_cast<Eigen::Index>(nodes[k]) * kNodeDofs;
    kin.d.segment<kNodeDofs>(k * kNodeDofs) = u.segment<kNodeDofs>(base);
    kin.dn.segment<kNodeDofs>(k * kNodeDofs) = un.segment<kNodeDofs>(base);
    kin.vn.segment<kNodeDofs>(k * kNodeDofs) = vn.segment<kNodeDofs>(base);
    kin.an.segment<kNodeDofs>(k * kNodeDofs) = an.segment<kNodeDofs>(base);
  }
  return kin;
}

ElemVec State::velocities(const std::array<int, 2>& nodes) const {
  ElemVec out;
  for (int k = 0; k < 2; ++k)
    out.segment<kNodeDofs>(k * kNodeDofs) =
        v.segment<kNodeDofs>(static_cast<Eigen::Index>(nodes[k]) * kNodeDofs);
  return out;
}

void State::commit() {
  un = u;
  vn = v;
  an = a;
  tn = t;
  propn = prop;
  arcLambdan = arcLambda;
  ++step;
}

void State::revert() {
  u = un;
  v = vn;
  a = an;
  t = tn;
  prop = propn;
  arcLambda = arcLambdan;
}

}  // namespace c2d
