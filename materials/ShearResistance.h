#pragma once
// The shear an RC member carries at its axial force, Vu(N), by Eurocode 2
// (EN 1992-1-1 6.2), the code of the section's flexural laws
// (materials/RcSection). Strengths as given (no partial factors: CRd,c = 0.18,
// fcd = fck = fc, fywd = fyw), as for the flexure.
//
//  - Concrete (6.2.2(1), 6.6N): VRd,c = [max(0.18 k (100 rho_l fc)^(1/3),
//    vmin) + k1 sigma_cp] bw d, vmin = 0.035 k^(3/2) fc^(1/2),
//    k = 1 + sqrt(200/d) <= 2 (d in mm), rho_l = Asl/(bw d) <= 0.02,
//    sigma_cp = -N/Ac (compression positive) <= 0.2 fc, k1 = 0.15; a tension
//    lowers it, down to 0. Bounded by 0.5 bw d nu fc (6.5), nu = 0.6 (1 - fc/250).
//  - Stirrups (6.2.3(3), 6.8, 6.9): VRd,s = Asw/s z fyw cot(theta) bounded by
//    the struts' VRd,max = alpha_cw bw z nu fc / (cot + tan), z = 0.9 d, at the
//    strut angle 1 <= cot(theta) <= 2.5 that gives the most (the truss the
//    code lets the member choose); alpha_cw of the compression (Note 3 of
//    6.2.3(3)): 1 + sigma/fc up to 0.25 fc, 1.25 up to 0.5 fc, 2.5 (1 - sigma/fc)
//    beyond, 1 in tension; nu1 = nu (6.6N: the stirrups work at their yield).
//  - The member: Vu = max(VRd,c, VRd,s). EC2 counts the stirrups alone where
//    they are needed (6.2.3(1)): the concrete's share is in the flatter strut
//    (cot(theta) up to 2.5), not added; a member whose stirrups carry less
//    than its concrete alone does not fail before VRd,c (6.2.1(3)).
//
// Units: the decks' kN, m and kN/m^2. 6.2.2's expressions are empirical in MPa
// and mm; the rule converts with kMPaPerStress (1 kN/m^2 = 1e-3 MPa) and
// kMmPerLength (1 m = 1000 mm) and refuses a fc that is surely not in kN/m^2
// (outside [kMinFc, kMaxFc]: 1-250 MPa).
//
// Depth and bars per sign of the moment (sign +1: the top face compressed):
// d = the depth of the bars farthest from the compressed face (0.8 D for
// circles, ACI 318-19 22.5.2.2), Asl = the bars in the half of the section away
// from it, bw the web's width (materials/SectionShape). The member's Vu(N) is the smaller
// of the two signs' (continuous in N, whichever face the moment compresses).
#include <array>
#include <optional>
#include <vector>

namespace c2d {

class SectionShape;
struct RebarLayer;
struct Stirrups;

class ShearResistance {
 public:
  static constexpr double kMPaPerStress = 1e-3, kMmPerLength = 1e3;
  static constexpr double kMinFc = 1e3, kMaxFc = 2.5e5;  // kN/m^2
  static constexpr double kCRdc = 0.18, kK1 = 0.15, kRhoMax = 0.02, kZ = 0.9;
  static constexpr double kCotMin = 1.0, kCotMax = 2.5;

  // One sign's geometry: web width bw, effective depth d, tension bars Asl.
  struct Web {
    double bw = 0, d = 0, asl = 0;
  };
  // Throws std::invalid_argument for a fc outside [kMinFc, kMaxFc] or a web
  // of no width or depth.
  ShearResistance(const std::array<Web, 2>& webs, double area, double fc,
                  const std::optional<Stirrups>& stirrups);
  // The webs of a section shape with its bar layers (depths from the top face):
  // bw = SectionShape::webWidth (a TEE's web, a circle's D, an annulus's 2t),
  // d = SectionShape::effectiveDepth of the farthest bars (0.8 D for circles).
  static std::array<Web, 2> webs(const SectionShape& shape, const std::vector<RebarLayer>& bars);

  // The parts at N (tension positive), sign +1 or -1 (index 0, 1 of the webs).
  struct Parts {
    double concrete = 0;  // VRd,c
    double stirrups = 0;  // VRd,s at cot(theta), bounded by VRd,max
    double cot = 0;       // the strut's cot(theta) (0: no stirrups)
    double vu = 0;        // max(concrete, stirrups)
  };
  Parts parts(double N, int sign) const;
  double capacity(double N, int sign) const { return parts(N, sign).vu; }
  // The member's: the smaller sign's.
  double capacity(double N) const;
  // |V| / Vu(N): 1 when the member fails in shear. Vu is taken no smaller than
  // 1e-9 of Vu(0), so that a tension that leaves no capacity gives a large,
  // finite demand.
  double demand(double V, double N) const;

 private:
  struct Sign {
    Web web;
    double vc = 0;    // max(0.18 k (100 rho fc)^(1/3), vmin) in kN/m^2
    double vcap = 0;  // 0.5 nu fc bw d (6.5)
  };
  std::array<Sign, 2> s_;
  double area_ = 0, fc_ = 0, nu_ = 0;
  double omega_ = 0;  // Asw fyw / s (kN/m); 0 without stirrups
  double floor_ = 0;  // 1e-9 Vu(0)
};

}  // namespace c2d
