#pragma once
// Geometrically linear 2-node Timoshenko frame element for the failure phase
// (paper section 2): linear interpolation of u, v, theta, one integration point
// at the midpoint, axial and shear elastic, bending elastoplastic with bilinear
// hardening (BilinearHardening), plus an embedded rotation discontinuity
// (softening plastic hinge, LinearSoftening) at the midpoint.
//
// Enhanced kinematics (eqs 20-24) with Gbar = -1/l_e: in the element frame
//   eps = (u2 - u1)/l,  gamma = (v2 - v1)/l - (theta1 + theta2)/2,
//   kappa = (theta2 - theta1)/l - alpha/l.
// Bending, the hinge and its condensation are materials/HingedBending (shared
// with the finite-rotation ReissnerFrame), so the residual depends on d alone
// and the tangent is its exact derivative.
//
// The hinge never activates by itself: the solver asks hingeDemand() and calls
// activateHinge() on one element at a time. Activate at a state where the demand
// is 1 or just above (cut the step back to it): the hinge is then at its
// capacity and takes the softening tangent, and the other elements, on their
// yield surface, the elastic one, which are the branches of the solution (their
// moment cannot exceed the hinge's). Below Mu the freeze of the bulk plastic
// curvature lowers the moment by EI/Kh times the gap, which can leave the hinge
// rigid (EI/Kh2 is about 285 for the paper's data), and Newton's method then
// cycles between sets of branches none of which holds the solution.
//
// An RC section (MaterialSet::rc) adds the axial law of materials/AxialCapacity
// (the bars in tension, the squash load in compression) and bending laws that
// follow the axial force (moment-axial interaction: the moment's derivative
// with respect to N couples bending and stretching in the tangent); its hinges
// open at the element ends (HingedBending, HingeSite::Ends): the end moments
// M1 = M + V l/2, M2 = M - V l/2 of the element's equilibrium are passed to the
// law, and the hinge is a joint made at that end after the commit. The bars'
// fracture (axial strain eu) and the shear failure (|V| at Vu(N),
// materials/ShearResistance) are located like hinge events.
//
// The element is always a Timoshenko beam (SHEAr OFF is not honoured here: the
// one-point element is free of shear locking). Dynamics as in LinearFrame:
// residual f_int + M a_eff, consistent (linear) or lumped mass; under the
// mid-point scheme the resultants are weighted between the committed and the
// trial state with (1/2 - alpha, 1/2 + alpha). DAMPing adds the section's
// dashpot in dynamics (materials/SectionDamping.h).
//
// Rigid end zones (elements/RigidEnds.h): the strains are those of the flexible
// length between the faces (its end moments, where end hinges open, are the
// faces'), mapped from the nodes by the linear map G; mass and self-weight stay
// those of the full length between the nodes.
#include <array>
#include <cmath>
#include <memory>
#include <optional>

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

class InelasticFrame final : public Element,
                             public HingeCarrier,
                             public Checkpoint,
                             public MaterialChange,
                             public RcMember {
 public:
  // x1, x2: reference coordinates of the nodes. Bending uses the HARDening data
  // when given (elastic otherwise); the hinge exists only with SOFTening data.
  // offsets: the rigid end zones at the first and second node (m).
  InelasticFrame(const MaterialSet& mat, const std::array<int, 2>& nodes, const Vec2& x1,
                 const Vec2& x2, const std::array<double, 2>& offsets = {0.0, 0.0});

  std::array<int, 2> nodes() const override { return nodes_; }
  void setNodes(const std::array<int, 2>& n) override { nodes_ = n; }
  int materialNumber() const override { return material_; }
  std::string typeName() const override { return "frame-timoshenko-inelastic"; }

  Status evaluate(const ElementKinematics& kin, const StepRule& rule, bool wantTangent,
                  ElemVec& residual, ElemMat& tangent) override;
  ElemMat mass() const override { return mass_; }
  ElemVec bodyLoad(const Vec2& g) const override;
  void commit() override { committed_ = trial_; }
  void revert() override { trial_ = committed_; }
  // Elastic stored energy of the last evaluated state: l/2 (N^2/EA + V^2/GA + M^2/EI).
  // Plastically dissipated and hardening energies are not included.
  double strainEnergy() const override;
  SectionForces sectionForces() const override;

  double hingeDemand() const override;
  void activateHinge() override;
  HingeInfo hinge() const override;
  // End moments carry the shear's round-off (M -+ V l/2): 1e-10.
  double demandBand() const override { return law_.site() == HingeSite::Ends ? 1e-10 : 1e-12; }
  int earlyEnd() const override;
  void activateHingeAt(int end) override;

  double axialForce() const override { return trial_.forces.N; }
  bool followsAxialForce() const override { return axial_ || law_.capacity(); }
  ElemVec axialForceGradient() const override;
  bool fractureDue() const override {
    return committed_.fracture == Parting::BarsFractured || committed_.fracture == Parting::Sheared;
  }
  void fractureDone() override { committed_.fracture = trial_.fracture = Parting::Separated; }
  Parting parting() const override { return committed_.fracture; }
  double shearForce() const override { return std::abs(trial_.forces.V); }
  double shearCapacity() const override;

  double length() const { return length_; }  // the flexible length
  const RigidEnds& rigidEnds() const { return rigid_; }
  double fullLength() const { return length_ + rigid_.offset(0) + rigid_.offset(1); }
  const HingedBending& bendingLaw() const { return law_; }
  // Section history at the last evaluated state (committed after commit()).
  const HingedBendingState& section() const { return trial_.section; }
  // Sets the trial and the committed history (after a commit: the hinges at
  // the ends made into joints, elements/EndHinges).
  void setSection(const HingedBendingState& s) { trial_.section = committed_.section = s; }

  // Restart files: every member after the construction data except the
  // material laws' parameters, which the constructor rebuilds from the
  // material set.
  void writeState(std::ostream& out) const override;
  void readState(std::istream& in) override;

 private:
  // History of the integration point: value type, committed and trial copies.
  // A hinge activated in the trial state (activateHinge) opens in the next
  // evaluation with the sign recorded in trial_.section.hingeSign.
  struct PointState {
    HingedBendingState section;
    SectionForces forces;  // at the state's displacements (element frame)
    AxialState axial;      // RC sections: plastic axial strain
    Parting fracture = Parting::Whole;  // bars fractured or sheared: separation due, then done
  };
  // The bars' strain / eu at the trial state (RC sections; 0 once fractured).
  double fractureDemand() const;
  // |V| / Vu(N) at the trial state (RC sections; 0 once parted).
  double shearDemand() const;
  // evaluate()'s steps: the trial section at the flexible part's
  // displacements dl (axial force, then the bending law: trial_ and
  // axialTangent_ set); the resultants of the step's scheme with the section
  // dashpot's; their tangent in the element frame (coupled: the moment
  // follows N).
  struct Resultants;
  Status trialSection(const ElemVec& dl, HingedBendingResponse& bend);
  Resultants schemeResultants(const ElemVec& dl, const ElemVec& dln, const StepRule& rule,
                              const HingedBendingResponse& bend) const;
  ElemMat localTangent(const Resultants& s, const HingedBendingResponse& bend, bool coupled) const;

  std::array<int, 2> nodes_;
  int material_;
  double length_;
  double EA_, GA_;
  double rhoA_;  // mass per unit length
  HingedBending law_;
  std::optional<AxialCapacity> axial_;  // RC sections
  std::shared_ptr<const RcSection> rc_;  // RC sections: the shear capacity
  double axialTangent_ = 0;             // dN/deps of the last evaluation
  SectionDamping damping_;  // DAMPing: the section's dashpot in dynamics
  ElemMat rotation_;  // global -> element frame, block diagonal
  RigidEnds rigid_;
  ElemMat toLocal_;   // nodal dofs -> the flexible part's, element frame: rotation_ G
  ElemMat mass_;
  PointState committed_, trial_;

 public:
  // New stiffness, density, mass type, HARDening and SOFTening data; section
  // forces at d and the history kept (core/MaterialChange.h), through a
  // stress-free local displacement. Refused: FINIte kinematics; removing the
  // SOFTening law of an active hinge; a law under which the committed state is
  // not admissible (|M| above the new yield radius, or above the new Mu of an
  // inactive hinge, or above the new capacity of an active one); capacity given
  // back to a fully softened hinge.
  Status setMaterial(const MaterialSet& mat, const ElemVec& d) override;

 private:
  ElemVec dl0_ = ElemVec::Zero();  // stress-free displacement (element frame); zero unless changed
};

}  // namespace c2d
