// JointedElement's local problem under an end hinge's law (materials/EndHinge):
// the joint sticks while its moment stays below the capacity, else its
// relative rotation slips until the moment is the capacity at the slip reached.
#include "elements/JointedElement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace c2d {

double JointedElement::memberAxialForce() const { return member_ ? member_->axialForce() : 0.0; }

// The hinge's slip solve: sigma the sign of the moment the joint cannot
// carry, and at the root psi, the accumulated slip, the joint's moment m,
// dm/dpsi, G_psi and the capacity there.
struct JointedElement::Slip {
  double sigma = 1;
  double psi = 0, slip = 0, m = 0, mPsi = 0, Gpsi = 0;
  EndHinge::Value cv;
};

void JointedElement::setRates(const ElementKinematics& kin, const ElementKinematics& in,
                              const StepRule& rule, double psi) {
  const int k = dof();
  const double masterRate = rule.rotationRate(kin.d(k) - kin.dn(k));
  const double rate = rule.rotationRate(kin.d(k) + psi - in.dn(k)) - masterRate;
  trial_.vel = rule.velocity(rate, committed_.vel, committed_.acc);
  trial_.acc = rule.acceleration(rate, committed_.vel, committed_.acc);
  slaveRotation_ = kin.d(k) + psi;
}

Status JointedElement::solveSlip(const ElementKinematics& kin, const StepRule& rule, double stick,
                                 ElementKinematics& in, ElemVec& residual, ElemMat& kin6,
                                 Slip& s) {
  const int k = dof();
  const double masterRate = rule.rotationRate(kin.d(k) - kin.dn(k));
  const double sigma = s.sigma = stick > 0 ? 1.0 : -1.0;
  const double psiN = committed_.psi;
  // Under the Cayley rule the slave's increment stays inside (-pi, pi).
  const bool bounded = rule.rotationsByCayley() && inner_->mass()(k, k) > 0;
  const double incN = kin.d(k) + psiN - in.dn(k);
  double lo = psiN, hi = psiN;
  const double far = bounded ? std::numbers::pi - 1e-9 : 1e300;
  (sigma > 0 ? hi : lo) = sigma > 0 ? psiN + (far - incN) : psiN - (far + incN);
  double psi = psiN, G = 0;
  bool lastPass = false;
  double lastStep = std::numeric_limits<double>::infinity(), stepBeforeLast = lastStep;
  for (int it = 0; it < kMaxLocalIterations; ++it) {
    turnSlave(in, kin, psi);
    if (it > 0)
      if (Status st = evaluateInner(in, rule, residual, kin6); !st) return st;
    const double inc = kin.d(k) + psi - in.dn(k);
    const double w = rule.rotationRate(inc) - masterRate;
    s.slip = committed_.slip + std::max(0.0, sigma * w);
    s.cv = hinge_->capacity(s.slip, memberAxialForce());
    s.m = sigma * s.cv.C;
    const double nk = member_ ? innerAxialGradient(in.d)(k) : 0.0;
    s.mPsi = s.cv.dXi * rule.rotationRateSlope(inc) + sigma * s.cv.dN * nk;
    G = residual(k) + s.m;
    s.Gpsi = kin6(k, k) + s.mPsi;
    if (lastPass) {
      s.psi = psi;
      return Status::success();
    }
    // Newton's step; a step at round-off is taken and the element evaluated
    // once more (its error is the step's square), else the step stays inside
    // the bracket (bisecting it when Newton's would leave it).
    const double small = kSmallStep * (1.0 + std::abs(psi));
    double step = s.Gpsi != 0 ? -G / s.Gpsi : 0.0;
    if (std::isfinite(step) && std::abs(step) <= small) {
      lastPass = true;
      psi += step;
      continue;
    }
    (G < 0 ? lo : hi) = psi;
    // Newton's steps that do not halve from one to the next but one bounce
    // between the sides of a kink (the wrapped element's own joint turning
    // from stick to slip): the bracket then shrinks by little each time, and
    // bisection takes over (a safeguarded Newton, as rtsafe's).
    const bool finite = std::abs(hi) < 1e299 && std::abs(lo) < 1e299;
    if (!(s.Gpsi > 0) || !(psi + step > lo && psi + step < hi) ||
        (finite && std::abs(step) > 0.5 * stepBeforeLast))
      step = (finite ? 0.5 * (lo + hi) : psi + sigma * 0.1) - psi;
    if (!std::isfinite(step)) break;
    stepBeforeLast = lastStep;
    lastStep = std::abs(step);
    psi += step;
  }
  std::ostringstream msg;
  msg << "hinge at node " << slave_ + 1 << ": its rotation jump did not converge in "
      << kMaxLocalIterations << " iterations (moment " << residual(k) << ")";
  return Status::failure(msg.str());
}

void JointedElement::storeSlip(const ElementKinematics& kin, const StepRule& rule,
                               const ElementKinematics& in, const ElemMat& kin6, const Slip& s,
                               bool wantTangent, ElemMat& tangent) {
  const int k = dof();
  const double psi = s.psi, sigma = s.sigma;
  const EndHinge::Value& cv = s.cv;
  trial_.psi = psi;
  trial_.slip = s.slip;
  trial_.moment = s.m;
  setRates(kin, in, rule, psi);
  guessValid_ = false;
  // dG/dd: the inner row, the slip rate's dependence on the master's increment,
  // the capacity's on the member's axial force.
  ElemVec gd = kin6.row(k).transpose();
  gd(k) -= cv.dXi * rule.rotationRateSlope(kin.d(k) - kin.dn(k));
  ElemVec md = ElemVec::Zero();  // dm/dd at fixed psi
  md(k) = cv.dXi * (rule.rotationRateSlope(kin.d(k) + psi - in.dn(k)) -
                    rule.rotationRateSlope(kin.d(k) - kin.dn(k)));
  if (member_) {
    const ElemVec g = innerAxialGradient(in.d);
    md += sigma * cv.dN * g;
    gd = kin6.row(k).transpose() + md;
    axialGradient_ = g - (g(k) / s.Gpsi) * gd;
  } else {
    gd = kin6.row(k).transpose() + md;
  }
  if (wantTangent) {
    // R_k = -m(psi(d), d): dR_k/dd = -m_d - m_psi dpsi/dd, dpsi/dd = -G_d/G_psi.
    ElemVec rpsi = kin6.col(k);
    rpsi(k) = -s.mPsi;
    tangent = kin6;
    tangent.row(k) = -md.transpose();
    tangent -= rpsi * gd.transpose() / s.Gpsi;
  }
}

Status JointedElement::evaluateHinge(const ElementKinematics& kin, const StepRule& rule,
                                     bool wantTangent, ElemVec& residual, ElemMat& tangent) {
  const int k = dof();
  ElementKinematics in = fromFace(kin, committed_.psi);
  ElemMat kin6;
  // Stick: the relative rotation as committed; the joint carries -r_k. A
  // moment at the capacity to round-off (relative 1e-8) slips with a zero
  // increment, as LinearSoftening's hinge: a hinge at its capacity is taken to
  // go on softening (its tangent at the state it opened in is the softening one).
  turnSlave(in, kin, committed_.psi);
  if (Status st = evaluateInner(in, rule, residual, kin6); !st) return st;
  const double stick = -residual(k);
  const EndHinge::Value c0 = hinge_->capacity(committed_.slip, memberAxialForce());
  if (std::abs(stick) < c0.C * (1 - 1e-8)) {
    trial_.psi = committed_.psi;
    trial_.slip = committed_.slip;
    trial_.moment = stick;
    setRates(kin, in, rule, committed_.psi);
    if (member_) axialGradient_ = innerAxialGradient(in.d);
    if (wantTangent) tangent = kin6;
    return Status::success();
  }
  // Slip in the direction of the moment the joint cannot carry: G(psi) =
  // r_k + sigma C(xi_n + sigma w, N) = 0 on sigma w >= 0 (a spent capacity
  // leaves r_k = 0), solved by Newton's method kept in a bracket of the root.
  Slip s;
  if (Status st = solveSlip(kin, rule, stick, in, residual, kin6, s); !st) return st;
  storeSlip(kin, rule, in, kin6, s, wantTangent, tangent);
  return Status::success();
}

}  // namespace c2d
