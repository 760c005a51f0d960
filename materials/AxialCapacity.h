#pragma once
// The axial force of an RC member bounded by its section (materials/RcSection):
// in tension by its bars, yielding at Nt = As fy and hardening linearly to
// Ntu = As fu, reached when the member's axial strain is the bars' fracture
// strain eu; in compression by the squash load Nc (perfectly plastic).
// Elastic between, with the uncracked section's EA in compression and the
// cracked tie's, the bars' Es As, in tension (no tension in the concrete, as
// in the section's cracked analyses):
//   N = EA(s) (eps - ep), s = sign(eps - ep),  -Nc <= N <= Nt + Ht xi,
//   Ht = (Ntu - Nt) / (eu - Ntu/(Es As)),
// xi the accumulated tensile plastic strain. The member's axial strain in
// tension eps = N/(Es As) + ep is then its bars' strain: they yield at fy/Es
// and fracture when eps reaches eu (fractureDemand 1). A one-dimensional
// plasticity with a bimodular elastic law: the stored energy N^2/(2 EA(s)) is
// convex, the return map closed form. Units: forces kN, EA kN (the decks'
// system), strains dimensionless.
#include "materials/SectionDamping.h"

namespace c2d {

struct AxialState {
  double ep = 0;  // plastic axial strain
  double xi = 0;  // accumulated tensile plastic strain (hardening variable)
};

struct AxialResponse {
  double N = 0;        // axial force (tension positive)
  double tangent = 0;  // dN/deps
  AxialState state;    // trial history
  bool plastic = false;
};

class AxialCapacity {
 public:
  // Requires EAc, EAt, Nt, Nc > 0, Ntu >= Nt and eu > Ntu/EAt; throws std::invalid_argument.
  AxialCapacity(double EAc, double EAt, double Nt, double Ntu, double Nc, double eu);

  // The elastic stiffness of the sign of N (compression: EAc, tension: EAt).
  double stiffness(double N) const { return N <= 0 ? eac_ : eat_; }
  double tensionYield() const { return nt_; }
  double tensionUltimate() const { return ntu_; }
  double squashLoad() const { return nc_; }
  double fractureStrain() const { return eu_; }
  double hardening() const { return ht_; }

  AxialResponse returnMap(const AxialState& committed, double eps) const;
  // The elastic stored energy per unit length, N^2/(2 EA(sign N)).
  double energyDensity(double N) const { return 0.5 * N * N / stiffness(N); }
  // The total axial strain of a state (N, ep).
  double strain(double N, const AxialState& s) const { return N / stiffness(N) + s.ep; }
  // The axial force of the mid-point scheme (weight w = 1/2 + alpha) for the
  // step from (eps0, N0) to (eps1, N1), dN1/deps1 = kt1, plastic strain change
  // dEp, and its derivative with respect to eps1. Plastic steps: N1 - (1 - w) r dN,
  // r = 1 - dEp/dE, as HingedBending::midPointMoment (|r| at most ratioBound);
  // elastic steps on one branch: w N1 + (1 - w) N0; across N = 0 (two
  // stiffnesses) the discrete gradient of the stored energy (W1 - W0)/dE plus
  // (w - 1/2) dN, whose work is the energy's change plus (w - 1/2) dN dE >= 0.
  struct MidPoint {
    double n = 0, tangent = 0;
  };
  MidPoint midPoint(double N0, double N1, double eps0, double eps1, double kt1, double dEp,
                    double w, double ratioBound) const;
  // The section's dashpot on the elastic axial strain's change dE - dEp over a
  // step (materials/SectionDamping.h, factor f = a1/h) from N0 to N1, with
  // kt1 = dN1/deps1: SectionDamping::bending with the stiffness of the
  // committed force's branch, EA(N0), fixed over the step (the branch of N1
  // would make the force jump where N1 changes sign, EA / Es As = 5-20 in
  // RC members, and Newton's iterates chatter there).
  SectionDamping::Bending damping(double f, double N0, double N1, double dE, double dEp,
                                  double kt1) const {
    const double ea = stiffness(N0);
    return SectionDamping::bending(f, ea, ea * (dE - dEp), dE, ea * kt1 / stiffness(N1));
  }
  // strain / eu: 1 when the bars reach their fracture strain (0 in compression).
  double fractureDemand(double eps) const { return eps > 0 ? eps / eu_ : 0.0; }

 private:
  double eac_, eat_, nt_, ntu_, nc_, eu_, ht_;
};

}  // namespace c2d
