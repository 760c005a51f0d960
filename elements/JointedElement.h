#pragma once
// An element attached to the slave node of a revolute joint (paper eqs 39-43,
// 55, 66-68), by the master-slave relative-motion approach: the slave node
// shares the master's position and rotates by psi_s = psi_m + psi_r, with the
// relative rotation psi_r an unknown of this element alone.
//
// The decorator reports the MASTER node at the slave end, so the global system
// never sees the slave. Inside, the wrapped element sees at that end the
// master's translations and the rotation psi_m + psi_r. Because the joint
// transmits no moment, psi_r solves the local equation
//   r_k(d + psi_r e_k) = 0,   k = the wrapped element's rotation dof at the slave end,
// by a local Newton iteration to round-off, and is condensed statically:
//   K = K_oo - K_or K_rr^-1 K_ro   (eq 68; K_rr = dr_k/dpsi_r).
// The condensed tangent is the exact derivative of the returned residual (row k
// and column k of K are the wrapped element's, minus their projection; row k
// vanishes: the element puts no moment on the master's rotation).
//
// psi_r has its own velocity and inertia acceleration history, advanced with
// the step rule's affine formulas exactly like a nodal dof; the wrapped element
// gets the sum (master + relative) for the slave rotation's d, d_n, v_n, a_n, so
// its inertia and the mid-point algorithmic forces act on the true slave motion.
// Hence the element works unchanged under Static, Newmark and MidPoint rules,
// and the energy identities of the wrapped element hold for the jointed one.
//
// A hinge at the member's end (HingeSite::Ends, materials/EndHinge): the joint
// made where the hinge opened carries its softening law. It is rigid (psi_r as
// committed, the moment passed to the master) while the moment it must carry
// is within the capacity C(xi, N), and slips beyond: the local equation is
// r_k + sigma C(xi_n + sigma w, N) = 0, w the step's relative rate measure
// (as the friction's), sigma the direction of the slip; the capacity's
// dependence on the member's axial force N enters the condensed tangent. Once
// the capacity is spent the joint is free. The slip's work sigma C w >= 0 is
// the hinge's dissipation.
//
// Rigid end zones (elements/RigidEnds.h) of the wrapped element at the slave
// end, arm a: the joint is at the FACE. The arm belongs to the member the
// joint's master is part of and turns with psi_m; the flexible part's end
// section turns with psi_m + psi_r:
//   face translation  u_f = u_m + phi(psi_m),  phi(t) = (R(t) - I) a
//   (t W a, the linear part, for elements of SMALl kinematics, whose arms are linear).
// The wrapped element applies its own arm with the rotation it is given, so
// its slave node gets the translation u_f - phi(psi_m + psi_r) = u_m + s,
//   s = phi(psi_m) - phi(psi_m + psi_r)   (the shift),
// which lands its face where it must. Internally the local problem is posed in
// face coordinates z (u_f, psi_s at the slave end): the wrapped element's
// residual and tangent come to z through the face-to-node map (RigidEnds with
// arm -a, its transpose, geometric term and, under the mid-point scheme, the
// algorithmic transpose that keeps the work identity), psi_r is condensed there
// exactly as above (its local equation is the face moment's), and the result
// goes to the master through the node-to-face map (arm a). Both maps preserve
// the work of the forces on the step's increments, so the energy identities of
// the wrapped element hold for the jointed one. The shift has its own velocity
// and acceleration history (advanced with the step rule's affine formulas, as
// psi_r's), added to the master's for the wrapped element's slave node: its
// inertia, kinetic energy and momentum are those of the wrapped element's mass
// (the full length's, lumped at its nodes) with the slave end's translational
// mass carried by the point u_m + s, rigidly attached to the flexible part's
// end section at the arm's distance from the face (the node itself while
// psi_r = 0). Links (joints at both ends) with arms are solved by the nested
// iteration.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <typeinfo>

#include "core/io/Checkpoint.h"
#include "core/Element.h"
#include "core/Hinge.h"
#include "core/MaterialChange.h"
#include "elements/JointArm.h"
#include "materials/EndHinge.h"

namespace c2d {

class JointedElement final : public Element, public Checkpoint, public MaterialChange {
 public:
  // inner: the element as built on its own nodes (its node at slaveEnd is the
  // slave); master: the joint's master node, which replaces the slave in nodes().
  JointedElement(std::unique_ptr<Element> inner, int slaveEnd, int master);

  // Outer nodes: the wrapped element's, with the master at slaveEnd.
  std::array<int, 2> nodes() const override { return nodes_; }
  // Not at the joint: the relative rotation takes up whatever the master's is.
  bool holdsRotation(int end) const override {
    return end != slaveEnd_ && inner_->holdsRotation(end);
  }
  // Sets the outer nodes (the node at slaveEnd must be the master).
  void setNodes(const std::array<int, 2>& n) override { nodes_ = n; }
  int materialNumber() const override { return inner_->materialNumber(); }
  std::string typeName() const override { return inner_->typeName() + "+joint"; }

  Status evaluate(const ElementKinematics& kin, const StepRule& rule, bool wantTangent,
                  ElemVec& residual, ElemMat& tangent) override;

  // The wrapped element's mass, for reporting (the slave rotation's inertia
  // appears on the master's rotation; the dynamics use the true slave motion).
  ElemMat mass() const override { return inner_->mass(); }
  // The wrapped element's body load without its moment at the slave end: the
  // joint cannot pass a moment to the master (frame elements with
  // shear deformation have none anyway).
  ElemVec bodyLoad(const Vec2& g) const override;

  void commit() override;
  void revert() override;

  double strainEnergy() const override { return inner_->strainEnergy(); }
  // Kinetic energy with the slave rotation's velocity v_m + psi_r'.
  double kineticEnergy(const ElemVec& v) const override;
  // Momentum with the slave rotation's velocity v_m + psi_r' (the slave
  // section's angular momentum at the slave end).
  ElemVec momentum(const ElemVec& v) const override;
  SectionForces sectionForces() const override { return inner_->sectionForces(); }

  // --- joint data ---
  int slaveEnd() const { return slaveEnd_; }
  int slaveNode() const { return slave_; }
  int masterNode() const { return nodes_[slaveEnd_]; }
  // Relative rotation psi_r, its velocity and inertia acceleration: trial (last
  // evaluated) and committed values.
  double relativeRotation() const { return trial_.psi; }
  double relativeVelocity() const { return trial_.vel; }
  double relativeAcceleration() const { return trial_.acc; }
  double committedRelativeRotation() const { return committed_.psi; }
  double committedRelativeVelocity() const { return committed_.vel; }
  double committedRelativeAcceleration() const { return committed_.acc; }
  // Sets psi_r and its rates (and the shift's, rigid end zones) in both the
  // trial and the committed state (the start of a phase).
  void setRelativeState(double psi, double vel = 0, double acc = 0,
                        const Vec2& shiftVel = Vec2::Zero(), const Vec2& shiftAcc = Vec2::Zero());
  // Rigid end zone at the slave end (see above): its reference arm (zero: none),
  // the shift s of the wrapped element's slave node for the master's rotation
  // psiM and the relative rotation psiR, and the shift's rates.
  const Vec2& arm() const { return arm_.arm(); }
  bool hasArm() const { return arm_.any(); }
  Vec2 shiftAt(double psiM, double psiR) const { return arm_.shift(psiM, psiR); }
  const Vec2& shiftVelocity() const { return trial_.shiftVel; }
  const Vec2& shiftAcceleration() const { return trial_.shiftAcc; }
  const Vec2& committedShiftVelocity() const { return committed_.shiftVel; }
  const Vec2& committedShiftAcceleration() const { return committed_.shiftAcc; }
  // Rotation of the slave node, psi_m + psi_r, at the last evaluated state.
  double slaveRotation() const { return slaveRotation_; }

  // Friction of the joint: a moment of magnitude Mr opposing the relative
  // rotation, regularised over the step's relative rotation w (the slave's
  // rate measure less the master's, core/StepRule.h):
  //   m = Mr w / sqrt(w^2 + eps^2),  eps = Mr l / EI of the wrapped element
  // (the elastic rotation of the member under Mr), so that a sticking joint is
  // about as stiff as the member. Its work m w >= 0 is dissipated. Mr = 0: a
  // free joint.
  void setFriction(double Mr, double eps);
  double frictionMoment() const { return friction_; }

  // The hinge this joint is (see above), with its accumulated slip.
  void setHinge(const EndHinge& law, double slip = 0);
  const std::optional<EndHinge>& hingeLaw() const { return hinge_; }
  double hingeSlip() const { return trial_.slip; }
  double committedHingeSlip() const { return committed_.slip; }
  // The hinge as core/Hinge.h reports one: jump = the relative rotation, moment
  // = the section moment at the joint (positive compressing the top face),
  // softening = the slip, ultimate = Mu at the member's axial force.
  HingeInfo hingeInfo() const;
  // dN/dd of the wrapped member's axial force with psi_r condensed (laws that
  // follow N); valid after an evaluation.
  const ElemVec& axialForceGradient() const { return axialGradient_; }

  Element& inner() { return *inner_; }
  const Element& inner() const { return *inner_; }
  // Hands the wrapped element back (its node at slaveEnd set to the slave).
  std::unique_ptr<Element> release();
  // Replaces the wrapped element (one with the same nodes, or a wrapper whose
  // joint was removed); the master stays at slaveEnd.
  void replaceInner(std::unique_ptr<Element> inner);
  std::unique_ptr<Element> takeInner() { return std::move(inner_); }

  // Kinematics the wrapped element sees for the given outer kinematics and psi_r
  // (committed psi_r history for d_n, v_n, a_n).
  ElementKinematics innerKinematics(const ElementKinematics& outer, double psi) const;

  // Forwarded to the wrapped element at the displacements it sees (the slave
  // end rotated by the committed psi_r); the relative rotation is kept.
  Status setMaterial(const MaterialSet& mat, const ElemVec& d) override;

  // Restart files: the joint's own data (outer nodes, slave, relative rotation
  // and rates, trial and committed); the wrapped element is written separately
  // (elements/ModelCheckpoint).
  void writeState(std::ostream& out) const override;
  void readState(std::istream& in) override;

 private:
  struct Relative {
    double psi = 0, vel = 0, acc = 0;
    double slip = 0;    // the hinge's accumulated |slip| (rad)
    double moment = 0;  // the joint's moment on the slave section (hinge, friction)
    Vec2 shiftVel = Vec2::Zero(), shiftAcc = Vec2::Zero();  // the shift's rates (rigid end zone)
  };

  // Local Newton iteration: once the update is below kSmallStep relative to
  // 1 + |psi_r| (radians, unbounded: many turns are fine), it is applied and
  // the element evaluated once more, which leaves an error of the order of
  // the squared update, far below round-off. Stopping without that last
  // evaluation would leave a moment K_rr*step at the joint, always of the
  // same sign, and the energy of a long run would drift.
  static constexpr int kMaxLocalIterations = 60;
  static constexpr double kSmallStep = 1e-9;

  int dof() const { return kNodeDofs * slaveEnd_ + 2; }
  // The whole evaluation in face coordinates (no arm: the outer ones).
  Status evaluateAtFace(const ElementKinematics& face, const StepRule& rule, bool wantTangent,
                        ElemVec& residual, ElemMat& tangent);
  // Face coordinates of the outer kinematics (translations at the slave end
  // moved by phi(psi_m)); the wrapped element's kinematics from them and psi_r.
  ElementKinematics faceKinematics(const ElementKinematics& outer) const;
  ElementKinematics fromFace(const ElementKinematics& face, double psi) const;
  // The slave end of the wrapped element's kinematics `in` at relative rotation psi.
  void turnSlave(ElementKinematics& in, const ElementKinematics& face, double psi) const;
  // The wrapped element's residual and tangent at `in`, in face coordinates.
  Status evaluateInner(const ElementKinematics& in, const StepRule& rule, ElemVec& residual,
                       ElemMat& tangent);

  // No moment law acts: no friction, no hinge or a spent one.
  bool freeJoint() const {
    return friction_ <= 0 && (!hinge_ || hinge_->failed(committed_.slip));
  }
  // evaluateAtFace's parts with friction or none: the joint's friction
  // moment m(w) on the slave section at relative rotation p (w the relative
  // rate measure over the step) and dm/dpsi; the local Newton solve of
  // r_k + m = 0 for psi (from psi, with `in` at it: the wrapped element's
  // residual, tangent kin6 and pivot krr at the root); the condensed tangent
  // with friction.
  double frictionAt(const ElementKinematics& kin, const ElementKinematics& in,
                    const StepRule& rule, double p, double& slope) const;
  Status solveRelative(const ElementKinematics& kin, const StepRule& rule, double& psi,
                       ElementKinematics& in, ElemVec& residual, ElemMat& kin6, double& krr);
  ElemMat frictionTangent(const ElementKinematics& kin, const ElementKinematics& in,
                          const StepRule& rule, double psi, const ElemMat& kin6) const;
  // The local problem with the hinge law (stick or slip; elements/JointHinge.cpp).
  Status evaluateHinge(const ElementKinematics& kin, const StepRule& rule, bool wantTangent,
                       ElemVec& residual, ElemMat& tangent);
  // Its parts: the relative rotation's rates and the slave's rotation at psi;
  // the slip solve from the stick moment (`in`, residual and kin6 left at the
  // root); the slipping joint's trial state, axial gradient and tangent.
  struct Slip;
  void setRates(const ElementKinematics& kin, const ElementKinematics& in, const StepRule& rule,
                double psi);
  Status solveSlip(const ElementKinematics& kin, const StepRule& rule, double stick,
                   ElementKinematics& in, ElemVec& residual, ElemMat& kin6, Slip& s);
  void storeSlip(const ElementKinematics& kin, const StepRule& rule, const ElementKinematics& in,
                 const ElemMat& kin6, const Slip& s, bool wantTangent, ElemMat& tangent);
  // The member's axial force (0: none).
  double memberAxialForce() const;
  // The wrapped element's axial force gradient (through an inner wrapper's),
  // in face coordinates at its kinematics d.
  ElemVec innerAxialGradient(const ElemVec& d) const;
  void findMember();
  // A link (this wrapper around another, joints at both ends, neither with
  // friction): both relative rotations by one Newton iteration on the
  // innermost element, two evaluations of it where the nested iterations
  // take four. False (nothing changed but trial states that the nested
  // iteration sets again) where that iteration leaves the Cayley rule's
  // window of a slave section's increment, meets a singular pivot or does not
  // converge: the nested iteration, with its bracket, takes over.
  bool evaluateLink(JointedElement& inner, const ElementKinematics& kin, const StepRule& rule,
                    bool wantTangent, ElemVec& residual, ElemMat& tangent);

  std::unique_ptr<Element> inner_;
  int slaveEnd_;
  int slave_;
  std::array<int, 2> nodes_;
  Relative trial_, committed_;
  double slaveRotation_ = 0;
  double friction_ = 0, frictionEps_ = 1;
  // The slave end's rigid arm (the innermost element's zone there; none: a
  // joint at the node).
  JointArm arm_;
  std::optional<EndHinge> hinge_;
  // The innermost element's axial force and laws (null: none that follow N).
  const RcMember* member_ = nullptr;
  ElemVec axialGradient_ = ElemVec::Zero();
  // Within a step: the outer d of the last evaluation and dpsi_r/dd there
  // (-K_k./K_kk, the condensation's), so that the local iteration starts from
  // psi_r's first-order change with d; dropped at a commit or a revert.
  ElemVec guessD_ = ElemVec::Zero(), guessSlope_ = ElemVec::Zero();
  bool guessValid_ = false;
};

// The moment-axial capacity of a member's laws (through its joint wrappers), or null.
std::shared_ptr<const MomentCapacity> memberCapacity(const Element& member);

// The element as a joint wrapper, or null. A type check (the class is final)
// instead of a dynamic_cast through its three bases: the loops over every
// element at every commit (joint events, slave nodes) made the casts 4 % of
// the ten-storey demolition decks.
inline JointedElement* asJointed(Element* e) {
  return e && typeid(*e) == typeid(JointedElement) ? static_cast<JointedElement*>(e) : nullptr;
}
inline const JointedElement* asJointed(const Element* e) {
  return e && typeid(*e) == typeid(JointedElement) ? static_cast<const JointedElement*>(e)
                                                    : nullptr;
}

}  // namespace c2d
