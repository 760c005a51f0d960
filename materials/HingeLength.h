#pragma once
// The length over which an RC hinge's plastic curvature is spread, EN
// 1998-3:2005 A.3.2.2(5)-(6), the curvature route to the chord rotation at
// ultimate beside the fit (A.1):
//   theta_um = theta_y + (phi_u - phi_y) Lpl (1 - 0.5 Lpl/L_V)        (A.9)
//   Lpl = L_V/30 + 0.2 h + 0.11 dbL fy/sqrt(fc)   (fy, fc in MPa)    (A.10)
// with phi_u from the confined core (fcc, eps_cu,c: (A.11), (A.12),
// materials/Confinement.h; RcSection::ultimateConfined) and gamma_el = 1 (the
// mean; the code's 2.0 makes it a verification value). The hinge's plastic
// rotation is so (phi_u - phi_y) times rotationLength(L_V) = Lpl (1 - 0.5
// Lpl/L_V), Lpl taken at most L_V (a hinge longer than its shear span would
// turn backwards).
//
// The shear span L_V = M/V is the member's at the hinge: the distance from
// the hinge's section to the point of zero moment. The program takes it where
// the hinge opens, from the element's end moments (shearSpan below): the
// moment is linear along an element without load between its nodes, so L_V =
// L |M_a| / |M_a - M_b| for end a; a cantilever's base gets its length, a
// member in double curvature with equal end moments L/2, a beam under
// gravity's end moments L/6. It is bounded to [h, 10 h] (the members of the
// tests behind Annex A: shear spans from about h, and the L_V/30 term would
// grow without bound as V vanishes, e.g. a member in single curvature under
// equal end moments). Where no moment diagram is at hand (a midpoint hinge,
// the echo, the section's own failure jump) the reference L_V = 4 h is taken
// (a member of 8 h in double curvature), and the joint's rupture rotation
// thetaR, one per material, takes the bound 10 h, so that no hinge's failure
// jump passes it.
//
// dbL, the mean diameter of the tension bars, is not in the deck (REBAr gives
// a layer's area): it is estimated from the bar layer farthest from the
// compressed face. A layer of a rectangle or a TEE holds its two corner bars
// and bars at most 0.15 m apart across the width (EN 1998-1 5.4.3.2.2(11)'s
// spacing of restrained bars): n = max(2, 1 + ceil((w - 2c)/0.15)), w the
// width at the layer, c its cover; a circle's layer nearest a face is one bar
// (REBAr RING). Lengths in m (the SECTion's unit); fc and fy in the deck's
// stress unit, read from fc's magnitude (materials/Confinement.h
// stressUnitInMPa); when it is not recognised the strain penetration term
// 0.11 dbL fy/sqrt(fc) is left out.
#include <optional>

#include "core/MaterialSet.h"
#include "materials/SectionShape.h"

namespace c2d {

// The bounds and the reference of the shear span, in section depths h.
constexpr double kShearSpanMin = 1, kShearSpanMax = 10, kShearSpanReference = 4;

// The estimated diameter of the tension bars for moments of `sign`.
double tensionBarDiameter(const RcSectionData& d, const SectionShape& shape, int sign);
// 0.11 dbL fy/sqrt(fc) (A.10) in the section's length unit; none when fc's unit
// is not recognised.
std::optional<double> strainPenetration(const RcSectionData& d, const SectionShape& shape,
                                        int sign);
// The part of Lpl that does not follow the shear span: 0.2 h + the strain
// penetration (0 when unknown).
double hingeLengthBase(const RcSectionData& d, const SectionShape& shape, int sign);
// Lpl = Lv/30 + base and Lpl (1 - 0.5 Lpl/Lv) with Lpl <= Lv: the plastic
// rotation per unit of plastic curvature.
double plasticHingeLength(double base, double Lv);
double rotationLength(double base, double Lv);
// L_V of end a of an element of length L with end moments Ma (at a) and Mb
// (infinite when they are equal), and L_V bounded to [kShearSpanMin h,
// kShearSpanMax h].
double shearSpan(double L, double Ma, double Mb);
double boundedShearSpan(double Lv, double h);

}  // namespace c2d
