#pragma once
// A material set of the deck (MATErial,m): the element type and its section data.
// Pure data: the element factory (elements/) turns it into elements.
#include <optional>
#include <string>

namespace c2d {

enum class Kinematics { Small, Finite };     // SMALl: geometrically linear; FINIte: Reissner
enum class MassType { Consistent, Lumped };

// HARDening BILInear Mc My Kh1 Kh2: bending elastic to Mc, modulus Kh1 to My, Kh2 beyond.
struct HardeningData {
  double Mc = 0, My = 0, Kh1 = 0, Kh2 = 0;
};

// SOFTening LINEar Mu Ks [thetaR]: hinge opens when |M| reaches Mu; t = Mu + Ks*xi, Ks < 0,
// down to 0; a joint made of the hinge ruptures when its relative rotation exceeds thetaR (rad).
struct SofteningData {
  double Mu = 0, Ks = 0;
  std::optional<double> thetaR;
  double Mr = 0;  // friction moment of the joint the fully softened hinge becomes
};

struct MaterialSet {
  int number = 0;
  std::string label;           // free text after MATErial,m
  std::string elementType;     // "FRAMe" (the only type for now)
  // ELAStic ISOTropic E nu; CROSs SECTion A Ixx Iyy Ixy J kappa (FEAPpv's record; kappa 0: 5/6)
  double E = 0, nu = 0, A = 0, I = 0, kappa = 5.0 / 6.0;
  // RESUltant STIFfness EA GA EI (overrides ELAS + CROS when given)
  std::optional<double> resEA, resGA, resEI;
  bool shear = true;                       // SHEAr ON (Timoshenko) / OFF (Euler-Bernoulli)
  Kinematics kinematics = Kinematics::Small;
  double density = 0;                      // mass per unit volume
  MassType mass = MassType::Consistent;
  // DAMPing RAYLeigh 0 a1 / DAMPing RATIo zeta f: stiffness-proportional
  // damping of the section's strain rates, a1 in time units (s); 0: none
  // (materials/SectionDamping.h).
  double dampingA1 = 0;
  std::optional<HardeningData> hardening;
  std::optional<SofteningData> softening;

  double EA() const { return resEA ? *resEA : E * A; }
  double GA() const { return resGA ? *resGA : kappa * E / (2.0 * (1.0 + nu)) * A; }
  double EI() const { return resEI ? *resEI : E * I; }
  double rhoA() const { return density * A; }  // mass per unit length
  double rhoI() const { return density * I; }  // rotary inertia per unit length
};

}  // namespace c2d
