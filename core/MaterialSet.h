#pragma once
// A material set of the deck (MATErial,m): the element type and its section data.
// Pure data: the element factory (elements/) turns it into elements.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace c2d {

enum class Kinematics { Small, Finite };  // SMALl: geometrically linear; FINIte: Reissner
enum class MassType { Consistent, Lumped };

// HARDening BILInear Mc My Kh1 Kh2: bending elastic to Mc, modulus Kh1 to My, Kh2 beyond;
// HARDening NEGAtive Mc My Kh1 Kh2: other values for negative moments (magnitudes).
struct HardeningValues {
  double Mc = 0, My = 0, Kh1 = 0, Kh2 = 0;
};
struct HardeningData : HardeningValues {
  std::optional<HardeningValues> negative = std::nullopt;
};

// SOFTening LINEar Mu Ks [thetaR [Mr [Lb]]]: hinge opens when |M| reaches Mu; t = Mu + Ks*xi,
// Ks < 0, down to 0; a joint made of the hinge ruptures when its relative rotation exceeds
// thetaR (rad); Lb (m): the shortest piece the member breaks into (elements/HingeToJoint.h).
// SOFTening NEGAtive Mu Ks: other values for negative moments (Mu a magnitude).
struct SofteningData {
  double Mu = 0, Ks = 0;
  std::optional<double> thetaR;
  double Mr = 0;  // friction moment of the joint the fully softened hinge becomes
  // No joint forms at a node within this distance (m) of an intact joint's node: next to a
  // broken section the moment grows as V x, and Lb ~ Mu/Vu (Vu the shear the member can
  // carry) is the nearest a second hinge can open; 0: anywhere (a mesh's node spacing).
  double pieceLength = 0;
  std::optional<std::pair<double, double>> negative = std::nullopt;  // Mu, Ks of negative moments
};

// SECTion RECTangular b h fc fy [Es [fu eu]] with REBAr d1 A1 [d2 A2 ...]: a
// rectangular reinforced concrete section b x h (m) (or TEE, CIRCular,
// ANNUlar: SectionShapeKind; REBAr RING bars become layers), concrete strength fc and
// bar yield stress fy, modulus Es, ultimate stress fu and fracture strain eu of
// the bars (stresses in kN/m^2 with kN and m); bar layers at their depth from
// the top face (m) with their area (m^2). The top face is the face on the
// element's left looking from its first node to its second (the local +y side):
// a positive moment compresses it. The derivation is materials/RcSection.
struct RebarLayer {
  double depth = 0, area = 0;
};
// STIRrups Asw s [fyw]: the links of a SECTion, area Asw of their legs (m^2) at
// spacing s (m) along the member, yield stress fyw (fy when not given): with
// the concrete they set the shear the member carries, Vu(N), and from it the
// shortest piece it breaks into (materials/ShearResistance, RcSection::shortestPiece).
struct Stirrups {
  double area = 0, spacing = 0, fy = 0;
};
// The concrete's shape (materials/SectionShape): RECTangular b x h; TEE bw h
// beff hf (web width b, total depth h, flange beff x hf at the top face);
// CIRCular D and ANNUlar D t (b = h = D, wall thickness t).
enum class SectionShapeKind { Rectangle, Tee, Circle, Annulus };
struct RcSectionData {
  SectionShapeKind shape = SectionShapeKind::Rectangle;
  double b = 0, h = 0, fc = 0, fy = 0, Es = 0, fu = 0, eu = 0;
  double flangeWidth = 0, flangeDepth = 0;  // TEE: beff, hf
  double wall = 0;                          // ANNUlar: t
  std::vector<RebarLayer> bars;
  std::optional<Stirrups> stirrups;
  // The share of a WEAKened member's widths and areas (materials/WeakenedSet):
  // the confinement and the hinge length stay the original member's.
  double kept = 1;
};

// Where a softening hinge opens: at the one-point element's midpoint when its
// moment reaches Mu (the paper's element), or at the element end whose end
// moment (from the element's equilibrium) first reaches Mu, as a joint that
// carries the softening law (HINGes ENDS; SECTion's default).
enum class HingeSite { Midpoint, Ends };

class MomentCapacity;
class RcSection;

struct MaterialSet {
  int number = 0;
  std::string label;        // free text after MATErial,m
  std::string elementType;  // "FRAMe" (the only type for now)
  // ELAStic ISOTropic E nu; CROSs SECTion A Ixx Iyy Ixy J kappa (FEAPpv's record; kappa 0: 5/6)
  double E = 0, nu = 0, A = 0, I = 0, kappa = 5.0 / 6.0;
  // RESUltant STIFfness EA GA EI (overrides ELAS + CROS when given)
  std::optional<double> resEA, resGA, resEI;
  bool shear = true;  // SHEAr ON (Timoshenko) / OFF (Euler-Bernoulli)
  Kinematics kinematics = Kinematics::Small;
  double density = 0;  // mass per unit volume
  // RADIus,,r: the member's contact radius (m) in place of its section's
  // sqrt(3 I/A); 0: the section's (core/contact/ContactSearch.h sectionRadius).
  double contactRadius = 0;
  MassType mass = MassType::Consistent;
  // DAMPing RAYLeigh 0 a1 / DAMPing RATIo zeta f: stiffness-proportional
  // damping of the section's strain rates, a1 in time units (s); 0: none
  // (materials/SectionDamping.h).
  double dampingA1 = 0;
  std::optional<HardeningData> hardening;
  std::optional<SofteningData> softening;
  HingeSite hingeSite = HingeSite::Midpoint;
  // INTEraction CURVe N1 Mu1 N2 Mu2 ...: the hand-given laws scaled with the
  // axial force (materials/MomentCapacity.h ScaledCapacity).
  std::vector<std::pair<double, double>> interaction;
  // SECTion + REBAr: the section; its derivation (set with it: resultant
  // stiffnesses, A, I, the laws at N = 0 in hardening and softening, Ends).
  std::optional<RcSectionData> section;
  std::shared_ptr<const RcSection> rc;
  // The laws' dependence on the axial force: the section's, or the scaled
  // hand-given laws'; null: laws that do not follow N.
  std::shared_ptr<const MomentCapacity> capacity;

  double EA() const { return resEA ? *resEA : E * A; }
  double GA() const { return resGA ? *resGA : kappa * E / (2.0 * (1.0 + nu)) * A; }
  double EI() const { return resEI ? *resEI : E * I; }
  double rhoA() const { return density * A; }  // mass per unit length
  double rhoI() const { return density * I; }  // rotary inertia per unit length
};

}  // namespace c2d
