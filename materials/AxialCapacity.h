#pragma once
// The axial force of an RC member bounded by its section (materials/RcSection):
// in tension by its bars, yielding at Nt = As fy and hardening linearly to
// Ntu = As fu, reached when the member's axial strain is the bars' fracture
// strain eu; in compression by the squash load Nc (perfectly plastic). Elastic
// with EA between (one-dimensional plasticity, return map in closed form):
//   N = EA (eps - ep),  -Nc <= N <= Nt + Ht xi,  Ht = (Ntu - Nt) / (eu - Ntu/EA),
// xi the accumulated tensile plastic strain. The member's axial strain
// eps = N/EA + ep stands for its bars' strain once they carry it alone (a
// cracked tie); the bars fracture when eps reaches eu (fractureDemand 1).
// Units: forces kN, EA kN (the decks' system), strains dimensionless.
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
  // Requires EA, Nt, Nc > 0, Ntu >= Nt and eu > Ntu/EA; throws std::invalid_argument.
  AxialCapacity(double EA, double Nt, double Ntu, double Nc, double eu);

  double EA() const { return ea_; }
  double tensionYield() const { return nt_; }
  double tensionUltimate() const { return ntu_; }
  double squashLoad() const { return nc_; }
  double fractureStrain() const { return eu_; }
  double hardening() const { return ht_; }

  AxialResponse returnMap(const AxialState& committed, double eps) const;
  // eps / eu: 1 when the bars reach their fracture strain (0 in compression).
  double fractureDemand(double eps) const { return eps > 0 ? eps / eu_ : 0.0; }

 private:
  double ea_, nt_, ntu_, nc_, eu_, ht_;
};

}  // namespace c2d
