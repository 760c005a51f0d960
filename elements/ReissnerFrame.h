#pragma once
// Geometrically exact 2-node Reissner beam (deck: FRAMe + FINIte), total
// Lagrangian, linear interpolation and one-point (midpoint) integration.
//
// The cross-section angle is psi = beta0 + theta with beta0 the reference
// angle of the element axis; theta is the nodal rotation dof, additive and
// unbounded, so rotations far beyond +-pi are fine. With phi the deformed
// position, Lambda(psi) the rotation by psi and e1 = (1, 0):
//   material strains   (Sigma, Gamma) = Lambda(psi)^T phi' - e1,  K = psi'
//   resultants         N = EA Sigma, T = GA Gamma, M = EI K
//   stored energy      W = l/2 (EA Sigma^2 + GA Gamma^2 + EI K^2)
// evaluated at the element midpoint (l is the reference length).
//
// Under Scheme::MidPoint the internal force is the energy and momentum
// conserving/decaying one: resultants from C((1/2+alpha) E_{n+1} + (1/2-alpha) E_n),
// and nodal forces whose work on the increment, the rotations measured by their
// Cayley increments 2 tan(dtheta/2) as the step rule advances them
// (core/StepRule.h), is exactly E_{n+1} - E_n tested with the resultants:
// W_{n+1} - W_n + alpha l dE.C.dE. The forces balance (linear momentum exact) and
// their moments about the mid-point configuration balance too (angular momentum
// exact); see midPointForce.
//
// An initial strain E0 = (Sigma0, Gamma0, K0) shifts the constitutive law:
// resultants C (E - E0), energy W = l/2 (E - E0).C.(E - E0). Under the mid-point
// scheme both E_n and E_{n+1} are shifted, so dE and the identity above are
// unchanged. It carries the section forces of a failure-phase element over to
// the collapse phase without releasing its plastic deformation.
//
// Bending follows materials/HingedBending: elastic (M = EI (K - K0)) unless the
// material set has HARDening (bilinear hardening of the moment) and SOFTening
// (a softening hinge at the midpoint, embedded rotation discontinuity,
// condensed: with one-point integration the jump changes only the curvature,
// K - alpha/l, so the hinge works at any displacement and rotation). Under the
// mid-point scheme the bending moment is the weighted moment
// (1/2 + alpha) M_{n+1} + (1/2 - alpha) M_n for an elastic section (the moment
// of the weighted curvature above), and for an inelastic one the moment of
// HingedBending::midPointMoment, whose work never exceeds the change of the
// stored energy. The hinge opens only when the solver
// asks (core/Hinge.h), as in InelasticFrame.
//
// RC sections (MaterialSet::rc) and laws that follow the axial force: the
// axial resultant comes from materials/AxialCapacity (bars in tension, squash
// load; under the mid-point scheme the inelastic resultant of HingedBending::
// midPointMoment's construction), the bending laws take the material axial
// force N_{n+1}, and the tangent gets the moment's dependence on it. Hinges
// at the element ends (HingeSite::Ends) take the end moments M -+ S/2 of the
// element's equilibrium, S = l (N Gamma - V (1 + Sigma)) the moment of its
// end forces.
//
// DAMPing adds the section's dashpot in dynamics (materials/SectionDamping.h):
// under the mid-point scheme the resultants come from the (alpha + a1/h)-
// weighted strains and the work identity above holds with alpha + a1/h; the
// reported section forces and energy stay the material's.
//
// Rigid end zones (elements/RigidEnds.h): everything above holds for the
// flexible part between the faces (x1_, x2_ and length_ are its own), whose
// displacements are the exact rigid-arm map of the nodal ones; forces and the
// tangent go back by that map (with its geometric term; under the mid-point
// scheme the algorithmic map that keeps the work identity). Mass and
// self-weight stay those of the full length between the nodes, and inertia
// acts on the nodal motion.
#include <array>
#include <cmath>
#include <memory>
#include <limits>
#include <optional>
#include <string>

#include "core/io/Checkpoint.h"
#include "core/Element.h"
#include "core/Hinge.h"
#include "core/MaterialChange.h"
#include "core/MaterialSet.h"
#include "materials/AxialCapacity.h"
#include "materials/HingedBending.h"
#include "materials/SectionDamping.h"
#include "elements/RigidEnds.h"

namespace c2d {

class ReissnerFrame final : public Element,
                            public HingeCarrier,
                            public Checkpoint,
                            public MaterialChange,
                            public RcMember {
 public:
  // x1, x2: the nodes' reference coordinates; offsets: the rigid end zones at
  // the first and second node (m).
  ReissnerFrame(const MaterialSet& mat, const std::array<int, 2>& nodes, const Vec2& x1,
                const Vec2& x2, const std::array<double, 2>& offsets = {0.0, 0.0});

  std::array<int, 2> nodes() const override { return nodes_; }
  void setNodes(const std::array<int, 2>& n) override { nodes_ = n; }
  int materialNumber() const override { return materialNumber_; }
  std::string typeName() const override { return "frame-reissner"; }

  Status evaluate(const ElementKinematics& kin, const StepRule& rule, bool wantTangent,
                  ElemVec& residual, ElemMat& tangent) override;

  ElemMat mass() const override { return mass_; }
  ElemVec bodyLoad(const Vec2& g) const override;

  void commit() override { committed_ = trial_; }
  void revert() override { trial_ = committed_; }

  // W at the last evaluated d_{n+1}.
  double strainEnergy() const override { return trial_.energy; }
  // Material resultants N, T (as V), M at the midpoint of the last evaluated
  // d_{n+1}, for every scheme (not the mid-point algorithmic averages).
  SectionForces sectionForces() const override { return trial_.forces; }

  double hingeDemand() const override;
  void activateHinge() override;
  HingeInfo hinge() const override;
  // End moments carry the shear's round-off (M -+ V l/2): 1e-10.
  double demandBand() const override { return law_.site() == HingeSite::Ends ? 1e-10 : 1e-12; }
  int earlyEnd() const override;
  void activateHingeAt(int end) override;

  double axialForce() const override { return trial_.forces.N; }
  bool followsAxialForce() const override { return axial_ || law_.capacity(); }
  ElemVec axialForceGradient() const override { return axialGradient_; }
  bool fractureDue() const override {
    return committed_.fracture == Parting::BarsFractured || committed_.fracture == Parting::Sheared;
  }
  void fractureDone() override { committed_.fracture = trial_.fracture = Parting::Separated; }
  Parting parting() const override { return committed_.fracture; }
  double shearForce() const override { return std::abs(trial_.forces.V); }
  double shearCapacity() const override;

  // In the localization zone of another element's open hinge, of a joint or of
  // a free end (elements/LocalizationZones.h): no hinge of its own opens, and its moment is held at
  // Mu (HingedBending::respond). Set by the solver from the committed state.
  void setHeld(bool held) { held_ = held; }
  bool held() const { return held_; }

  double length() const { return length_; }  // the flexible length
  const RigidEnds& rigidEnds() const { return rigid_; }
  double fullLength() const { return length_ + rigid_.offset(0) + rigid_.offset(1); }
  const HingedBending& bendingLaw() const { return law_; }
  // Section history at the last evaluated state; setSection() sets both the
  // trial and the committed history (the start of a phase).
  const HingedBendingState& section() const { return trial_.section; }
  void setSection(const HingedBendingState& s);
  double referenceAngle() const { return beta0_; }
  // Initial strain (axial, shear, curvature); zero unless set.
  void setInitialStrain(const Vec3& e0) { e0_ = e0; }
  const Vec3& initialStrain() const { return e0_; }
  // Section stiffness diagonal (EA, GA, EI).
  Vec3 sectionStiffness() const { return {ea_, ga_, ei_}; }
  // Total material strains (Sigma, Gamma, K) at the midpoint for nodal
  // displacements d (the initial strain is not subtracted).
  Vec3 strains(const ElemVec& d) const;
  // The same for the flexible part's face displacements.
  Vec3 faceStrains(const ElemVec& dFace) const;
  // Stored energy W(d) = l/2 (E(d) - E0).C.(E(d) - E0).
  double energy(const ElemVec& d) const;

  // Restart files: every member after the construction data (the initial strain included).
  void writeState(std::ostream& out) const override;
  void readState(std::istream& in) override;

 private:
  struct Report {
    double energy = 0;
    SectionForces forces;
    HingedBendingState section;
    AxialState axial;  // RC sections: plastic axial strain
    Parting fracture = Parting::Whole;  // bars fractured or sheared: separation due, then done
  };

  // For laws that follow N: the axial resultant the force functions use
  // instead of EA (Sigma - Sigma0) and its derivative with respect to
  // Sigma_{n+1} (divided by the scheme's weight under the mid-point scheme),
  // and the moment's derivative with respect to d at fixed curvature.
  struct Coupling {
    bool axial = false;
    double n = 0, ea = 0;
    bool moment = false;
    ElemVec dm = ElemVec::Zero();
  };
  // The section's dashpot in a Newmark step: f = a1/h and the strains at d_n;
  // it adds f C (E(d) - eN) to the axial and shear resultants.
  struct Damper {
    double f = 0;
    Vec3 eN = Vec3::Zero();
  };
  // Internal force and tangent; both return the strains E(d).
  Vec3 staticForce(const ElemVec& d, double m, double kt, const Damper& damper, bool wantTangent,
                   ElemVec& f, ElemMat& k, const Coupling* cp = nullptr) const;
  // halfTan: tan of the nodal rotation increments' halves (the Cayley rate of
  // the inertia), found from the sines and cosines the force needs.
  Vec3 midPointForce(const ElemVec& d, const ElemVec& dn, double alpha, double m, double kt,
                     bool wantTangent, ElemVec& f, ElemMat& k, std::array<double, 2>& halfTan,
                     const Coupling* cp = nullptr) const;
  // dSigma/dd at d.
  ElemVec axialStrainGradient(const ElemVec& d) const;
  // evaluate()'s steps: N_{n+1} for the laws that follow it (axialTangent_,
  // axialGradient_ and the axial state set), the bending law's response and
  // the section dashpot's parts, the resultants under the mid-point rule or
  // a static/Newmark step (both return the strains E(d)), the trial report.
  struct StepResponse;
  double axialResponse(const ElementKinematics& fk);
  Status bendingResponse(const ElementKinematics& fk, const StepRule& rule, double openSign,
                         StepResponse& sr) const;
  Vec3 midPointResultants(const ElementKinematics& fk, const StepRule& rule,
                          const StepResponse& sr, bool wantTangent, ElemVec& residual,
                          ElemMat& tangent, std::array<double, 2>& halfTan) const;
  Vec3 staticResultants(const ElementKinematics& fk, const StepResponse& sr, bool wantTangent,
                        ElemVec& residual, ElemMat& tangent) const;
  void storeTrial(const Vec3& strain, const StepResponse& sr, const std::array<double, 2>& ends);
  double fractureDemand() const;
  double shearDemand() const;  // |V| / Vu(N) (RC sections; 0 once parted)
  double bendingDemand() const;  // the hinge's |M|/Mu; 0 when held

  std::array<int, 2> nodes_;
  int materialNumber_ = 0;
  RigidEnds rigid_;
  Vec2 x1_, x2_;  // the faces' reference coordinates (the nodes' without rigid zones)
  double length_ = 0;
  double beta0_ = 0;
  double ea_ = 0, ga_ = 0, ei_ = 0, rhoA_ = 0;
  Vec3 e0_ = Vec3::Zero();
  HingedBending law_;
  std::optional<AxialCapacity> axial_;  // RC sections
  std::shared_ptr<const RcSection> rc_;  // RC sections: the shear capacity
  bool held_ = false;                   // in a localization zone
  double axialTangent_ = 0;             // dN/dSigma of the last evaluation
  ElemVec axialGradient_ = ElemVec::Zero();  // dN/dd of the last evaluation
  SectionDamping damping_;  // DAMPing: the section's dashpot in dynamics
  ElemMat mass_;  // global frame
  Report trial_, committed_;
  // The mean rotation at d_n (fixed over a step) and the angle it belongs to:
  // the mid-point force needs it at every iteration.
  mutable double meanAngleN_ = std::numeric_limits<double>::quiet_NaN();
  mutable Eigen::Matrix2d lamN_ = Eigen::Matrix2d::Identity();

 public:
  // New EA, GA, EI, density and mass type; the section forces at d are kept by
  // a new initial strain E0 = E(d) - C_new^-1 C_old (E(d) - E0_old)
  // (core/MaterialChange.h). Either kinematics keyword is accepted: after
  // HINGe2joint the elements of a SMALl set are Reissner beams. HARDening and
  // SOFTening data are not used by this elastic element.
  Status setMaterial(const MaterialSet& mat, const ElemVec& d) override;
};

}  // namespace c2d
