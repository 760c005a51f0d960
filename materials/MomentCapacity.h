#pragma once
// Bending laws that follow the member's axial force N (moment-axial
// interaction): for each sign of the moment and each N, the parameters of the
// bilinear hardening law (BilinearHardening: Mc, My, Kh1, Kh2), the ultimate
// moment Mu of the softening hinge and the hinge's failure jump xiF (the
// rotation jump over which its moment falls from Mu to zero), with their
// derivatives with respect to N (for consistent tangents).
//
// Sign conventions: N > 0 in tension; sign = +1 for positive moments (the top
// face compressed, see core/MaterialSet.h RcSectionData), -1 for negative
// ones, whose values are given as magnitudes. Units: those of the deck
// (moments kN m, N kN, moduli kN m^2 in the decks' system).
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "materials/MonotoneCubic.h"

namespace c2d {

// The law of one sign at one axial force. All moments are magnitudes.
struct MomentLaw {
  double Mc = 0, My = 0, Kh1 = 0, Kh2 = 0, Mu = 0, xiF = 0;
  // d/dN at the same N (xiF is taken at a hinge's opening and kept: no derivative).
  double dMc = 0, dMy = 0, dKh1 = 0, dKh2 = 0, dMu = 0;
};

class MomentCapacity {
 public:
  virtual ~MomentCapacity() = default;
  // sign: +1 or -1 (the sign of the moment).
  virtual MomentLaw at(int sign, double N) const = 0;
  // The failure jump of a hinge opening at N in a member whose shear span
  // (M/V at the hinge) is Lv: the law's xiF unless the capacity knows how the
  // hinge's length follows the shear span (RcSection).
  virtual double failureJump(int sign, double N, double /*Lv*/) const { return at(sign, N).xiF; }
};

// Hand-given laws (HARDening, SOFTening) scaled by an interaction curve given
// as pairs (N, Mu): every moment and modulus of the law of either sign is
// multiplied by f(N) = Mu(N) / Mu(0) (the curve interpolated by a monotone
// cubic, constant beyond its ends), so the law keeps its shape in the
// hardening and softening variables: the plastic curvature at My and the
// failure jump Mu/|Ks| do not change with N.
class ScaledCapacity final : public MomentCapacity {
 public:
  // laws[0]: positive moments, laws[1]: negative; curve: (N, Mu) pairs with
  // increasing N and Mu > 0 (at least two). Throws std::invalid_argument.
  ScaledCapacity(const std::array<MomentLaw, 2>& laws, const std::vector<std::pair<double, double>>& curve);
  MomentLaw at(int sign, double N) const override;
  double factor(double N) const;

 private:
  std::array<MomentLaw, 2> laws_;
  MonotoneCubic curve_;
  double mu0_ = 1;
};

}  // namespace c2d
