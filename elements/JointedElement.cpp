#include "elements/JointedElement.h"

#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "elements/InelasticFrame.h"
#include "elements/ReissnerFrame.h"

namespace c2d {

namespace {

// The largest first-order change of psi_r taken as the local iteration's
// start (radians).
constexpr double kGuessRange = 0.05;

// The element inside any wrappers.
const Element& innermostOf(const Element& e) {
  const Element* in = &e;
  while (const JointedElement* j = asJointed(in)) in = &j->inner();
  return *in;
}

}  // namespace

JointedElement::JointedElement(std::unique_ptr<Element> inner, int slaveEnd, int master)
    : inner_(std::move(inner)), slaveEnd_(slaveEnd) {
  assert(inner_ && (slaveEnd == 0 || slaveEnd == 1));
  nodes_ = inner_->nodes();
  slave_ = nodes_[slaveEnd_];
  nodes_[slaveEnd_] = master;
  findMember();
  arm_ = JointArm(innermostOf(*inner_), slaveEnd_);
}

std::shared_ptr<const MomentCapacity> memberCapacity(const Element& member) {
  const Element* e = &innermostOf(member);
  if (const auto* f = dynamic_cast<const InelasticFrame*>(e)) return f->bendingLaw().capacity();
  if (const auto* f = dynamic_cast<const ReissnerFrame*>(e)) return f->bendingLaw().capacity();
  return nullptr;
}

void JointedElement::findMember() {
  member_ = dynamic_cast<const RcMember*>(&innermostOf(*inner_));
  if (member_ && !member_->followsAxialForce()) member_ = nullptr;
}

ElemVec JointedElement::innerAxialGradient(const ElemVec& d) const {
  const JointedElement* j = asJointed(inner_.get());
  const ElemVec g = j ? j->axialGradient_ : member_->axialForceGradient();
  return arm_.any() ? arm_.faceGradient(g, d) : g;
}

ElementKinematics JointedElement::faceKinematics(const ElementKinematics& outer) const {
  ElementKinematics face = outer;
  if (arm_.any()) arm_.toFace(face);
  return face;
}

ElementKinematics JointedElement::fromFace(const ElementKinematics& face, double psi) const {
  ElementKinematics in = face;
  const int k = dof();
  in.d(k) += psi;
  in.dn(k) += committed_.psi;
  in.vn(k) += committed_.vel;
  in.an(k) += committed_.acc;
  if (arm_.any()) {
    const int t = kNodeDofs * slaveEnd_;
    arm_.toNode(in, true);
    in.vn.segment<2>(t) += committed_.shiftVel;
    in.an.segment<2>(t) += committed_.shiftAcc;
  }
  return in;
}

ElementKinematics JointedElement::innerKinematics(const ElementKinematics& outer,
                                                  double psi) const {
  return fromFace(faceKinematics(outer), psi);
}

void JointedElement::turnSlave(ElementKinematics& in, const ElementKinematics& face,
                               double psi) const {
  const int k = dof();
  in.d(k) = face.d(k) + psi;
  if (arm_.any()) {
    const int t = kNodeDofs * slaveEnd_;
    in.d.segment<2>(t) = face.d.segment<2>(t);
    arm_.toNode(in, false);
  }
}

Status JointedElement::evaluateInner(const ElementKinematics& in, const StepRule& rule,
                                     ElemVec& residual, ElemMat& tangent) {
  if (Status st = inner_->evaluate(in, rule, true, residual, tangent); !st) return st;
  if (arm_.any()) arm_.faceForces(in, rule, residual, &tangent);
  return Status::success();
}

bool JointedElement::evaluateLink(JointedElement& j, const ElementKinematics& kin,
                                  const StepRule& rule, bool wantTangent, ElemVec& residual,
                                  ElemMat& tangent) {
  const int ko = dof(), ki = j.dof();
  if (ko == ki || arm_.any() || j.arm_.any()) return false;
  Element& core = *j.inner_;
  // Starts as the nested iteration's: each relative rotation's first-order
  // change with the kinematics its own wrapper sees.
  double po = trial_.psi, pi = j.trial_.psi;
  if (guessValid_) {
    const double change = guessSlope_.dot(kin.d - guessD_);
    if (std::abs(change) <= kGuessRange) po += change;
  }
  ElementKinematics mid = innerKinematics(kin, po);  // what the inner wrapper sees
  if (j.guessValid_) {
    const double change = j.guessSlope_.dot(mid.d - j.guessD_);
    if (std::abs(change) <= kGuessRange) pi += change;
  }
  ElementKinematics in = j.innerKinematics(mid, pi);
  const bool cayley = rule.rotationsByCayley();
  const ElemMat mass = core.mass();
  auto inWindow = [&](int k, double p) {
    return !(cayley && mass(k, k) > 0) || std::abs(kin.d(k) + p - in.dn(k)) < std::numbers::pi;
  };
  ElemMat K;
  bool lastPass = false, converged = false;
  for (int it = 0; it < kMaxLocalIterations && inWindow(ko, po) && inWindow(ki, pi); ++it) {
    in.d(ko) = kin.d(ko) + po;
    in.d(ki) = kin.d(ki) + pi;
    if (!core.evaluate(in, rule, true, residual, K)) return false;
    const double scale = 1e-13 * K.cwiseAbs().maxCoeff();
    const double det = K(ko, ko) * K(ki, ki) - K(ko, ki) * K(ki, ko);
    if (!(std::abs(K(ki, ki)) > scale) || !(std::abs(det) > scale * std::abs(K(ki, ki))))
      return false;
    if (lastPass) {
      converged = true;
      break;
    }
    const double so = -(K(ki, ki) * residual(ko) - K(ko, ki) * residual(ki)) / det;
    const double si = -(K(ko, ko) * residual(ki) - K(ki, ko) * residual(ko)) / det;
    if (!std::isfinite(so) || !std::isfinite(si)) return false;
    lastPass = std::abs(so) <= kSmallStep * (1.0 + std::abs(po)) &&
               std::abs(si) <= kSmallStep * (1.0 + std::abs(pi));
    po += so;
    pi += si;
  }
  if (!converged) return false;

  // The inner wrapper as its own evaluation would leave it: condensed over
  // its relative rotation.
  const ElemMat Ki = K - K.col(ki) * K.row(ki) / K(ki, ki);
  mid.d(ko) = kin.d(ko) + po;
  j.trial_.psi = pi;
  j.guessD_ = mid.d;
  j.guessSlope_ = -K.row(ki).transpose() / K(ki, ki);
  j.guessValid_ = true;
  const double rateI =
      rule.rotationRate(in.d(ki) - in.dn(ki)) - rule.rotationRate(mid.d(ki) - mid.dn(ki));
  j.trial_.vel = rule.velocity(rateI, j.committed_.vel, j.committed_.acc);
  j.trial_.acc = rule.acceleration(rateI, j.committed_.vel, j.committed_.acc);
  j.slaveRotation_ = in.d(ki);
  // This wrapper: condensed over its own relative rotation too.
  trial_.psi = po;
  guessD_ = kin.d;
  guessSlope_ = -Ki.row(ko).transpose() / Ki(ko, ko);
  guessValid_ = true;
  const double rateO =
      rule.rotationRate(mid.d(ko) - mid.dn(ko)) - rule.rotationRate(kin.d(ko) - kin.dn(ko));
  trial_.vel = rule.velocity(rateO, committed_.vel, committed_.acc);
  trial_.acc = rule.acceleration(rateO, committed_.vel, committed_.acc);
  slaveRotation_ = mid.d(ko);
  if (wantTangent) tangent = Ki - Ki.col(ko) * Ki.row(ko) / Ki(ko, ko);
  return true;
}

Status JointedElement::evaluate(const ElementKinematics& kin, const StepRule& rule,
                                bool wantTangent, ElemVec& residual, ElemMat& tangent) {
  if (!arm_.any()) return evaluateAtFace(kin, rule, wantTangent, residual, tangent);
  const ElementKinematics face = faceKinematics(kin);
  if (Status st = evaluateAtFace(face, rule, wantTangent, residual, tangent); !st) return st;
  // From the face to the master node (the arm turning with psi_m).
  arm_.nodeForces(kin, rule, residual, wantTangent ? &tangent : nullptr);
  if (member_) axialGradient_ = arm_.nodeGradient(axialGradient_, kin.d);
  // The shift's rates over the step.
  const int k = dof();
  const Vec2 ds = arm_.shift(kin.d(k), trial_.psi) - arm_.shift(kin.dn(k), committed_.psi);
  trial_.shiftVel = rule.velocity(ds, committed_.shiftVel, committed_.shiftAcc);
  trial_.shiftAcc = rule.acceleration(ds, committed_.shiftVel, committed_.shiftAcc);
  return Status::success();
}

double JointedElement::frictionAt(const ElementKinematics& kin, const ElementKinematics& in,
                                  const StepRule& rule, double p, double& slope) const {
  if (friction_ <= 0) return slope = 0.0;
  const int k = dof();
  const double masterRate = rule.rotationRate(kin.d(k) - kin.dn(k));
  const double w = rule.rotationRate(kin.d(k) + p - in.dn(k)) - masterRate;
  const double s2 = w * w + frictionEps_ * frictionEps_, s = std::sqrt(s2);
  slope = friction_ * frictionEps_ * frictionEps_ / (s2 * s);
  return friction_ * w / s;
}

Status JointedElement::solveRelative(const ElementKinematics& kin, const StepRule& rule,
                                     double& psi, ElementKinematics& in, ElemVec& residual,
                                     ElemMat& kin6, double& krr) {
  const int k = dof();
  bool lastPass = false, converged = false;
  // Under the Cayley rule (core/StepRule.h) the slave section's rotation
  // increment lies in (-pi, pi), where the rate of its inertia, 2 tan(inc/2),
  // sweeps every value: the residual goes from -inf to +inf there. Newton's step
  // is kept inside a bracket of the root and bisects when it would leave it.
  const bool bounded = rule.rotationsByCayley() && inner_->mass()(k, k) > 0;
  double lo = -std::numbers::pi, hi = std::numbers::pi;
  auto increment = [&](double p) { return kin.d(k) + p - in.dn(k); };
  if (bounded && !(std::abs(increment(psi)) < hi)) psi = in.dn(k) - kin.d(k);
  for (int it = 0; it < kMaxLocalIterations; ++it) {
    turnSlave(in, kin, psi);
    if (Status st = evaluateInner(in, rule, residual, kin6); !st) return st;
    double dm = 0;
    const double m = frictionAt(kin, in, rule, psi, dm);
    const double slaveSlope = friction_ > 0 ? rule.rotationRateSlope(increment(psi)) : 0.0;
    // Condensation needs a nonzero pivot only: a compressed member in large
    // motion can make the relative rotation's stiffness negative.
    krr = kin6(k, k) + dm * slaveSlope;
    if (!(std::abs(krr) > 1e-13 * kin6.cwiseAbs().maxCoeff())) {
      std::ostringstream msg;
      msg << "joint at node " << slave_ + 1 << ": relative rotation stiffness " << krr
          << " is singular";
      return Status::failure(msg.str());
    }
    if (lastPass) {
      converged = true;
      break;
    }
    const double local = residual(k) + m;
    double step = -local / krr;
    const double small = kSmallStep * (1.0 + std::abs(psi));
    bool bisected = false;
    if (bounded) {
      const double inc = increment(psi);
      (local > 0 ? hi : lo) = inc;
      if (std::abs(step) > small && !(inc + step >= lo && inc + step <= hi)) {
        step = 0.5 * (lo + hi) - inc;
        bisected = true;
      }
    }
    if (!std::isfinite(step)) break;
    // Only a Newton step this small has converged (its error is its square).
    lastPass = !bisected && std::abs(step) <= small;
    psi += step;
  }
  if (!converged) {
    std::ostringstream msg;
    msg << "joint at node " << slave_ + 1 << ": relative rotation did not converge in "
        << kMaxLocalIterations << " iterations (moment " << residual(k) << ")";
    return Status::failure(msg.str());
  }
  return Status::success();
}

ElemMat JointedElement::frictionTangent(const ElementKinematics& kin, const ElementKinematics& in,
                                        const StepRule& rule, double psi,
                                        const ElemMat& kin6) const {
  // psi_r(d) from G = r_k(d + psi_r e_k) + m(w) = 0, w = c(slave inc) -
  // c(master inc): dG/dpsi = K_kk + a, dG/dd_k = K_kk + b, with a = m' c'_s and
  // b = m' (c'_s - c'_m); the outer row k is -m(w).
  const int k = dof();
  double dm = 0;
  frictionAt(kin, in, rule, psi, dm);
  const double a = dm * rule.rotationRateSlope(in.d(k) - in.dn(k));
  const double b = a - dm * rule.rotationRateSlope(kin.d(k) - kin.dn(k));
  ElemVec gd = kin6.row(k).transpose();
  gd(k) += b;  // dG/dd
  ElemVec rpsi = kin6.col(k);
  rpsi(k) = -a;  // dR/dpsi
  ElemMat tangent = kin6;
  tangent.row(k).setZero();
  tangent(k, k) = -b;
  tangent -= rpsi * gd.transpose() / (kin6(k, k) + a);
  return tangent;
}

Status JointedElement::evaluateAtFace(const ElementKinematics& kin, const StepRule& rule,
                                      bool wantTangent, ElemVec& residual, ElemMat& tangent) {
  if (JointedElement* j = asJointed(inner_.get());
      j && freeJoint() && j->freeJoint() &&
      evaluateLink(*j, kin, rule, wantTangent, residual, tangent))
    return Status::success();
  if (hinge_ && !hinge_->failed(committed_.slip))
    return evaluateHinge(kin, rule, wantTangent, residual, tangent);
  const int k = dof();
  double psi = trial_.psi;
  // A first-order start only for a small change: the local equation's roots
  // recur with the turns of the slave section, and a start far off may find
  // another one.
  if (guessValid_) {
    const double change = guessSlope_.dot(kin.d - guessD_);
    if (std::abs(change) <= kGuessRange) psi += change;
  }
  ElementKinematics in = fromFace(kin, psi);
  ElemMat kin6;
  double krr = 0;
  if (Status st = solveRelative(kin, rule, psi, in, residual, kin6, krr); !st) return st;

  trial_.psi = psi;
  trial_.slip = committed_.slip;
  guessD_ = kin.d;
  guessSlope_ = -kin6.row(k).transpose() / krr;
  guessValid_ = true;
  // The slave's rate measure less the master's (equal to dpsi unless the
  // rotations advance by the Cayley rule).
  const double rate = rule.rotationRate(in.d(k) - in.dn(k)) - rule.rotationRate(kin.d(k) - kin.dn(k));
  trial_.vel = rule.velocity(rate, committed_.vel, committed_.acc);
  trial_.acc = rule.acceleration(rate, committed_.vel, committed_.acc);
  slaveRotation_ = in.d(k);

  trial_.moment = -residual(k);
  if (member_) {  // the member's axial force with psi_r(d): dpsi_r/dd = -G_d/G_psi
    const ElemVec g = innerAxialGradient(in.d);
    ElemVec gd = kin6.row(k).transpose();
    double gpsi = kin6(k, k);
    if (friction_ > 0) {
      double dm = 0;
      frictionAt(kin, in, rule, psi, dm);
      const double a = dm * rule.rotationRateSlope(in.d(k) - in.dn(k));
      gd(k) += a - dm * rule.rotationRateSlope(kin.d(k) - kin.dn(k));
      gpsi += a;
    }
    axialGradient_ = g - (g(k) / gpsi) * gd;
  }
  // The outer row k is the moment on the master: the friction's reaction -m,
  // which the converged local equation r_k + m = 0 leaves in residual(k).
  if (wantTangent && friction_ <= 0) {
    // psi_r(d) from r_k(d + psi_r e_k) = 0: dpsi_r/dd = -K_k./K_kk.
    tangent = kin6 - kin6.col(k) * kin6.row(k) / kin6(k, k);
  } else if (wantTangent) {
    tangent = frictionTangent(kin, in, rule, psi, kin6);
  }
  return Status::success();
}

HingeInfo JointedElement::hingeInfo() const {
  HingeInfo h;
  if (!hinge_) return h;
  h.active = true;
  h.count = 1;
  h.failed = hinge_->failed(trial_.slip);
  h.position = slaveEnd_;
  h.jump = trial_.psi;
  h.softening = trial_.slip;
  // The section moment at the slave end: the moment on the slave section at end 1, its reaction at end 2.
  h.moment = slaveEnd_ == 0 ? trial_.moment : -trial_.moment;
  h.ultimate = hinge_->ultimate(member_ ? member_->axialForce() : 0.0);
  return h;
}

void JointedElement::setHinge(const EndHinge& law, double slip) {
  hinge_ = law;
  trial_.slip = committed_.slip = slip;
}

void JointedElement::setFriction(double Mr, double eps) {
  friction_ = Mr;
  frictionEps_ = eps;
}

ElemVec JointedElement::bodyLoad(const Vec2& g) const {
  ElemVec f = inner_->bodyLoad(g);
  f(dof()) = 0;
  return f;
}

void JointedElement::commit() {
  inner_->commit();
  committed_ = trial_;
  guessValid_ = false;
}

void JointedElement::revert() {
  inner_->revert();
  trial_ = committed_;
  guessValid_ = false;
}

double JointedElement::kineticEnergy(const ElemVec& v) const {
  ElemVec vin = v;
  vin(dof()) += trial_.vel;
  if (arm_.any()) vin.segment<2>(kNodeDofs * slaveEnd_) += trial_.shiftVel;
  return inner_->kineticEnergy(vin);
}

ElemVec JointedElement::momentum(const ElemVec& v) const {
  ElemVec vin = v;
  vin(dof()) += trial_.vel;
  if (arm_.any()) vin.segment<2>(kNodeDofs * slaveEnd_) += trial_.shiftVel;
  return inner_->momentum(vin);
}

void JointedElement::setRelativeState(double psi, double vel, double acc, const Vec2& shiftVel,
                                      const Vec2& shiftAcc) {
  trial_ = committed_ =
      Relative{psi, vel, acc, committed_.slip, committed_.moment, shiftVel, shiftAcc};
  guessValid_ = false;
}

std::unique_ptr<Element> JointedElement::release() {
  std::array<int, 2> n = nodes_;
  n[slaveEnd_] = slave_;
  inner_->setNodes(n);
  return std::move(inner_);
}

void JointedElement::replaceInner(std::unique_ptr<Element> inner) {
  const int master = nodes_[slaveEnd_];
  inner_ = std::move(inner);
  nodes_ = inner_->nodes();
  nodes_[slaveEnd_] = master;
  findMember();
  arm_ = JointArm(innermostOf(*inner_), slaveEnd_);
}

// ------------------------------------------------------------ restart files

void JointedElement::writeState(std::ostream& out) const {
  using namespace checkpoint;
  put(out, slaveEnd_);
  put(out, slave_);
  for (int n : nodes_) put(out, n);
  for (const Relative* r : {&trial_, &committed_})
    for (double x : {r->psi, r->vel, r->acc, r->slip, r->moment}) put(out, x);
  for (const Relative* r : {&trial_, &committed_})
    for (const Vec2* x : {&r->shiftVel, &r->shiftAcc}) putFixed(out, *x);
  put(out, slaveRotation_);
  put(out, friction_);
  put(out, frictionEps_);
  putBool(out, hinge_.has_value());
  if (hinge_) {
    put(out, hinge_->sign());
    put(out, hinge_->givenUltimate());
    put(out, hinge_->failureJump());
    put(out, hinge_->residual());
  }
  putFixed(out, axialGradient_);
}

void JointedElement::readState(std::istream& in) {
  using namespace checkpoint;
  const int end = get<int>(in);
  if (end != slaveEnd_) throw CheckpointError("jointed element: slave end does not match");
  slave_ = get<int>(in);
  for (int& n : nodes_) n = get<int>(in);
  for (Relative* r : {&trial_, &committed_})
    for (double* x : {&r->psi, &r->vel, &r->acc, &r->slip, &r->moment}) *x = get<double>(in);
  for (Relative* r : {&trial_, &committed_})
    for (Vec2* x : {&r->shiftVel, &r->shiftAcc}) getFixed(in, *x);
  slaveRotation_ = get<double>(in);
  friction_ = get<double>(in);
  frictionEps_ = get<double>(in);
  hinge_.reset();
  if (getBool(in)) {
    const int sign = get<int>(in);
    const double mu = get<double>(in), xiF = get<double>(in), mr = get<double>(in);
    try {
      hinge_.emplace(memberCapacity(*inner_), sign, mu, xiF, mr);
    } catch (const std::invalid_argument& e) {
      throw CheckpointError(std::string("jointed element: ") + e.what());
    }
  }
  getFixed(in, axialGradient_);
}

Status JointedElement::setMaterial(const MaterialSet& mat, const ElemVec& d) {
  auto* inner = dynamic_cast<MaterialChange*>(inner_.get());
  if (!inner)
    return Status::failure("element type '" + inner_->typeName() + "' keeps its material");
  ElementKinematics outer;
  outer.d = outer.dn = d;
  outer.vn.setZero();
  outer.an.setZero();
  return inner->setMaterial(mat, innerKinematics(outer, committed_.psi).d);
}

}  // namespace c2d
