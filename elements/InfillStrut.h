#pragma once
// One equivalent diagonal compression strut of an infill panel (INFIll; the
// panel's properties: materials/InfillPanel.h; its law: materials/StrutLaw.h).
//
// A truss between two corner nodes of the panel: translations only, no moment
// (it holds no rotation), axial force N = N(eps) of the strut law. Kinematics
// as the bounding columns': SMALl, eps = e0 . (u2 - u1) / L (e0 the reference
// direction); FINIte, geometrically exact with the Green strain
// eps = (l^2 - L^2) / (2 L^2) of the current length l (for the strains a
// strut reaches, eps differs from (l - L)/L by eps^2/2).
//
// Residual r = L N(eps_w) B(x_c) + M a_eff, with B = dEps/dd. Statics and
// Newmark: at the end of the step (eps_w = eps_n+1, x_c = x_n+1). Mid-point:
// eps_w = (1/2 + alpha) eps_n+1 + (1/2 - alpha) eps_n and B at the mid-point
// configuration, which the Green strain makes exact (eps_n+1 - eps_n =
// B(x_mid) . (d_n+1 - d_n)): an elastic strut conserves energy, alpha > 0
// dissipates. Mass: its share of the wall's, lumped at its two nodes'
// translations (the wall's weight on the frame).
#include <array>
#include <string>

#include "core/Brace.h"
#include "core/Element.h"
#include "core/io/Checkpoint.h"
#include "materials/StrutLaw.h"

namespace c2d {

struct InfillStrutData {
  std::array<int, 2> nodes{-1, -1};  // 0-based
  Vec2 x1 = Vec2::Zero(), x2 = Vec2::Zero();  // reference coordinates
  StrutLaw law;
  double nodeMass = 0;   // translational mass at each of its two nodes
  bool finite = false;   // geometrically exact
  int panel = 0;         // 1-based panel number (INFIll records, in order)
  int partner = -1;      // 0-based element number of the panel's other strut
};

class InfillStrut final : public Element, public Brace, public Checkpoint {
 public:
  InfillStrut() = default;  // for restart files: readState() gives it everything
  explicit InfillStrut(const InfillStrutData& data);

  std::array<int, 2> nodes() const override { return d_.nodes; }
  bool holdsRotation(int) const override { return false; }
  void setNodes(const std::array<int, 2>& n) override { d_.nodes = n; }
  int materialNumber() const override { return 0; }  // no material set of the deck
  std::string typeName() const override { return "infill-strut"; }

  Status evaluate(const ElementKinematics& kin, const StepRule& rule, bool wantTangent,
                  ElemVec& residual, ElemMat& tangent) override;
  ElemMat mass() const override;
  ElemVec bodyLoad(const Vec2& g) const override;
  void commit() override { committed_ = trial_; }
  void revert() override { trial_ = committed_; }
  double strainEnergy() const override { return energy_; }
  SectionForces sectionForces() const override { return {force_, 0, 0}; }

  const InfillStrutData& data() const { return d_; }
  double length() const { return length_; }
  const StrutLawState& committedState() const { return committed_; }
  bool gone() const { return committed_.gone; }
  // Its panel crushed: the strut goes once it carries nothing (StrutLaw).
  void doom() { committed_.doomed = trial_.doomed = true; }
  // Keeps the share f of its stiffness and strength (WEAKen).
  void weaken(double f) { d_.law.scale(f); }

  void writeState(std::ostream& out) const override;
  void readState(std::istream& in) override;

 private:
  // Strain and B (dEps/d of the four translations) at displacements d.
  double strain(const ElemVec& d, Eigen::Vector4d* b) const;

  InfillStrutData d_;
  double length_ = 1;
  Vec2 e0_ = Vec2::UnitX();
  StrutLawState committed_, trial_;
  double force_ = 0, energy_ = 0;  // at the last evaluated state
};

}  // namespace c2d
