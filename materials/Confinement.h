#pragma once
// The confinement of an RC section's core by its stirrups and the rotation
// capacity the tests give a member of it (EN 1998-3:2005 Annex A, the
// Eurocode's fits to some 1500 tests of RC members, Fardis and Biskinis):
//  - the confinement effectiveness of rectangular hoops at spacing s around a
//    core b0 x h0 (to the hoops' centre lines, taken at the bars' centres:
//    b0 = b - 2 c, h0 = the distance between the outermost bar layers, c the
//    least layer depth), EN 1998-1 5.4.3.2.2(8), used by EN 1998-3 A.3.2.2:
//      alpha = (1 - s/(2 b0)) (1 - s/(2 h0)) (1 - sum bi^2 / (6 b0 h0)),
//    the bi the spacings of the bars the hoop's corners restrain along the
//    perimeter: a perimeter hoop restraining the four corner bars (bi = b0,
//    b0, h0, h0; 1/3 for a square core), no cross-ties counted;
//  - the confined strength and ultimate strain, EN 1998-3 (A.11), (A.12):
//      fcc = fc (1 + 3.7 (alpha rho_sx fyw / fc)^0.86),
//      eps_cu,c = 0.004 + 0.5 alpha rho_sx fyw / fcc,
//    rho_sx = Asw / (b s) the ratio of the links parallel to the loading (the
//    STIRrups' Asw); ratios of stresses only, so the rule needs no unit;
//  - the mean chord rotation at ultimate (the 20 % drop of the resistance)
//    under cyclic loading, EN 1998-3 (A.1) with gamma_el = 1 (the mean; 1.5
//    makes it the verification value), no diagonal bars (rho_d = 0), bars of
//    hot-rolled ductile steel, members detailed for earthquake resistance:
//      theta_um = 0.016 0.3^nu [max(0.01, w')/max(0.01, w) fc]^0.225
//                 (L_V/h)^0.35 25^(alpha rho_sx fyw/fc),
//    nu = N/(b h fc) (compression positive, tension taken as 0), w and w'
//    the mechanical ratios As fy/(b d fc) of the bars in the tension and the
//    compression half of the section, d the depth of the farthest tension
//    bars; fc in MPa there: the deck's stress unit is read from fc's
//    magnitude (stressUnitInMPa). The shear span L_V is the member's, so the
//    section gives theta_um / (L_V/h)^0.35.
// Units: those of the section (any consistent system) except as said.
#include <optional>

#include "core/MaterialSet.h"

namespace c2d {

struct Confinement {
  double b0 = 0, h0 = 0;           // core to the hoops' centre lines
  double alphaS = 0, alphaN = 0;   // spacing and perimeter factors
  double alpha = 0;                // alphaS alphaN
  double rhoSx = 0;                // Asw/(b s)
  double fcc = 0;                  // confined strength (section's unit)
  double epsCu = 0;                // confined ultimate strain (A.12)
};

// None without stirrups (the core then fails at EC2's eps_cu2 = 0.0035).
std::optional<Confinement> confinementOf(const RcSectionData& d);

// MPa per the section's stress unit, read from fc: fc in 5-150 as MPa (N/mm^2:
// 1), in 5e3-1.5e5 as kN/m^2 (1e-3), in 5e6-1.5e8 as Pa (1e-6); none else.
std::optional<double> stressUnitInMPa(double fc);

// EN 1998-3 (A.1) without its (L_V/h)^0.35 at axial force N (tension
// positive) for moments of `sign` (+1 compresses the top face); none when
// fc's unit is not recognised.
std::optional<double> chordRotationFactor(const RcSectionData& d, double N, int sign);

}  // namespace c2d
