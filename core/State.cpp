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
