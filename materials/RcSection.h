#pragma once
// A reinforced concrete section (deck: SECTion RECTangular, TEE, CIRCular or
// ANNUlar + REBAr; the concrete's geometry is materials/SectionShape) and
// what the member's laws take from it: stiffnesses, the moment-curvature
// points (cracking, first yield, ultimate) of either sign of the moment at any
// axial force (the interaction diagram), the axial capacities and the rotation
// capacity of a hinge. Pure computation, no units of its own: any consistent
// system (the decks: kN, m, kN/m^2).
//
// Materials (Eurocode 2, EN 1992-1-1):
//  - concrete in compression: the parabola-rectangle of 3.1.7 (fc <= 50 MPa:
//    n = 2, eps_c2 = 0.002, eps_cu2 = 0.0035), sigma = fc (1 - (1 - e/eps_c2)^2)
//    up to eps_c2, fc beyond; no tension in the cracked analyses. fc is used as
//    given (no partial factor, no alpha_cc): give the strength the analysis
//    should see (a mean strength for a collapse).
//  - concrete modulus Ec = 2 fc / eps_c2, the parabola's tangent at zero
//    strain, so that the member's elastic stiffness and the section's
//    moment-curvature come from one law (EC2's secant Ecm of Table 3.1 is
//    within about 10 % of it for C25/30-C40/50, and needs MPa); tensile
//    strength fct = fc / 10 (EC2's fctm / fck is 0.11-0.08 over C20-C50);
//    Poisson ratio 0.2 (3.1.3(4)).
//  - bars: elastic-perfectly plastic, Es and fy (3.2.7(2)b, horizontal top
//    branch), strain limit eu (the fracture strain) in the ultimate state.
//    In axial tension the bars harden to fu at eu (AxialCapacity).
// Bars do not displace concrete (the usual hand calculation).
//
// Geometry and signs: depth z from the top face (0 <= z <= h), strains
// eps(z) = e0 + kappa z positive in tension; N > 0 in tension; the moment about
// the concrete's gross centroid zg (the member axis: mid-depth of rectangles
// and circles), M = int sigma (z - zg) dA, positive when it compresses the top
// face. The negative moments are those of the section turned
// upside down (sign = -1), reported as magnitudes.
#include <array>
#include <optional>

#include "core/MaterialSet.h"
#include "materials/AxialCapacity.h"
#include "materials/HingeLength.h"
#include "materials/MomentCapacity.h"
#include "materials/SectionShape.h"
#include "materials/ShearResistance.h"

namespace c2d {

class RcSection final : public MomentCapacity {
 public:
  static constexpr double kEpsC2 = 0.002, kEpsCu2 = 0.0035;
  static constexpr double kConcretePoisson = 0.2;
  // Hinge: the moment falls linearly from Mu and has lost kUltimateDrop of it
  // over the plastic rotation (kappa_uc - kappa_y) Lpl (1 - 0.5 Lpl/L_V), EN
  // 1998-3 (A.9), (A.10) (materials/HingeLength.h), kappa_uc the ultimate
  // curvature of the confined core (materials/Confinement.h).
  static constexpr double kUltimateDrop = 0.2;

  // Throws std::invalid_argument for a section that is not one (sizes, strengths,
  // bars outside the section or of no area, fu < fy, eu <= fy/Es).
  explicit RcSection(const RcSectionData& data);

  const RcSectionData& data() const { return d_; }
  // The concrete's geometry (area, centroid, widths, shear's bw and d).
  const SectionShape& shape() const { return shape_; }
  double Ec() const { return ec_; }
  double fct() const { return d_.fc / 10; }
  double barArea() const { return as_; }
  // Transformed uncracked section (the concrete's shape, bars (Es/Ec - 1) A):
  // EA, EI about its centroid, GA of the shape's shear area.
  double EA() const { return ec_ * atr_; }
  double EI() const { return ec_ * itr_; }
  double GA() const;
  double centroidDepth() const { return ztr_; }
  // Axial capacities (magnitudes): the bars' yield and ultimate forces in tension,
  // the squash load (concrete at fc, bars at eps_c2, EC2 6.1(5)).
  double tensionYield() const { return as_ * d_.fy; }
  double tensionUltimate() const { return as_ * d_.fu; }
  double squashLoad() const;
  // The member's axial law (materials/AxialCapacity.h).
  AxialCapacity axialCapacity() const {
    return {EA(), d_.Es * as_, tensionYield(), tensionUltimate(), squashLoad(), d_.eu};
  }

  // Resultants of the strain plane (e0 at the top face, curvature kappa) of the
  // section as given (sign +1) or upside down (sign -1).
  struct Forces {
    double N = 0, M = 0;
  };
  // confined: the concrete at the confined core's fcc and eps_c2,c = eps_c2
  // (fcc/fc)^2 (EC2 3.1.9 (3.26)) over the whole section (ultimateConfined).
  Forces forces(double e0, double kappa, int sign, bool confined = false) const;
  // e0 of the plane with curvature kappa and axial force N; none when N is
  // beyond what the section carries at that curvature.
  std::optional<double> topStrain(double N, double kappa, int sign, bool confined = false) const;

  // A state of the moment-curvature at constant N.
  struct State {
    bool exists = false;  // false: none at this N (the axial force alone reaches it)
    double M = 0, kappa = 0;
    double e0 = 0;     // strain of the compressed face
    double depth = 0;  // neutral axis depth from the compressed face (inf: none)
  };
  // Cracking of the transformed uncracked section: the tension face at fct.
  State cracking(double N, int sign) const;
  // First yield: the most strained bar at fy/Es in tension, or the compressed
  // face at eps_c2, whichever comes first.
  State firstYield(double N, int sign) const;
  // Ultimate (EC2 6.1(5), Fig. 6.1): the compressed face at eps_cu2, or eps_c2 at
  // 3h/7 from it when the whole section is compressed, or a bar at eu.
  State ultimate(double N, int sign) const;
  // The ultimate curvature of the hinge's rotation capacity: as ultimate() with
  // the compressed face at the confined core's eps_cu,c and the concrete at
  // fcc, eps_c2,c (EN 1998-3 (A.11), (A.12), materials/Confinement.h) when the
  // section has stirrups. The cover is kept (no spalling: the section's
  // concrete is one law).
  State ultimateConfined(double N, int sign) const;
  // The compressed face's strain limit of ultimateConfined and the strength.
  double confinedStrain() const { return epsCuc_; }
  double confinedStrength() const { return fcc_; }
  // Balance point: the compressed face at eps_cu2 as the extreme tension bar
  // reaches fy/Es (its N and M).
  State balance(int sign) const;
  // The hinge's plastic rotation capacity (kappa_uc - kappa_y) Lpl (1 - 0.5
  // Lpl/Lv) at N and shear span Lv (materials/HingeLength.h); the failure jump
  // xiF = that / kUltimateDrop. The law's xiF (at(), the table) is the one at
  // the reference shear span; failureJump scales it to a hinge's own.
  double referenceSpan() const { return kShearSpanReference * d_.h; }
  double hingeLengthBase(int sign) const { return lplBase_[sign > 0 ? 0 : 1]; }
  double rotationLength(int sign, double Lv) const;
  double plasticRotation(double N, int sign, double Lv) const;
  double failureJump(int sign, double N, double Lv) const override;
  // Rupture rotation of a joint made of this section's failed hinge: xiF at
  // N = 0 (the larger sign's) at the largest shear span (kShearSpanMax h: no
  // hinge's failure jump passes it) plus acos(1/(1 + eu)), the turn of a tie
  // pinned there whose bars the turn stretches to eu (see README).
  double ruptureRotation() const;
  // The shear the member carries at the axial force N (materials/ShearResistance:
  // EC2 6.2.2 and 6.2.3, the larger of the concrete's VRd,c and the stirrups'
  // VRd,s), of one sign of the moment or the member's (the smaller sign's).
  const ShearResistance& shear() const { return *shear_; }
  double shearCapacity(double N, int sign) const { return shear_->capacity(N, sign); }
  double shearCapacity(double N) const { return shear_->capacity(N); }
  // The shortest piece a member of this section breaks into: next to a
  // section carrying no moment (a joint broken, a free end) the moment grows
  // as V x, so with the shear bounded by Vu a hinge cannot open nearer than
  // Mu/Vu: Lb = the larger of Mu(0)/Vu(0) of the two signs (the mesh's node
  // spacing may be longer: elements/Joints.h).
  double shortestPiece() const;

  // The bending law at N (tabulated on [-squash, tension yield], monotone cubic
  // in N, constant beyond), with the moment-curvature points kept apart by
  // floors: Mu >= Mu(0)/100, then My, Mc below it, plastic curvatures positive
  // and increasing.
  MomentLaw at(int sign, double N) const override;
  // The law's points at N: plastic curvatures at My and Mu.
  struct Points {
    double Mc = 0, My = 0, Mu = 0, xiY = 0, xiU = 0, xiF = 0;
  };
  Points rawPoints(double N, int sign) const;  // direct (not tabulated), before the floors

 private:
  Points floored(const Points& p, int sign) const;

  RcSectionData d_;
  SectionShape shape_;
  std::array<std::vector<RebarLayer>, 2> bars_;  // as given, upside down
  double ec_ = 0, as_ = 0, atr_ = 0, ztr_ = 0, itr_ = 0;
  std::optional<ShearResistance> shear_;  // set once the data are checked
  double epsCuc_ = kEpsCu2;  // the confined core's ultimate strain
  double fcc_ = 0, epsC2c_ = kEpsC2;  // its strength and the parabola's strain
  std::array<double, 2> lplBase_{0, 0};  // Lpl - L_V/30 per sign
  std::array<Points, 2> zero_;  // raw points at N = 0 (floors' references)
  // Tabulated laws per sign: Mc, My, Mu, xiY, xiU, xiF.
  std::array<std::array<MonotoneCubic, 6>, 2> table_;
};

}  // namespace c2d
