#pragma once
// An infill panel's equivalent diagonal struts from the wall and its frame
// (INFIll; docs/design/infill.md). Units: m, kN, t (stresses kN/m^2).
//
// Width (FEMA 356 eqs 7-14, 7-15; ASCE 41-17 eqs 11-1, 11-2, Mainstone):
//   lambda1 = [Em t sin(2 theta) / (4 EIcol h_inf)]^(1/4),
//   a = 0.175 (lambda1 h_col)^(-0.4) r_inf,
// h_col the storey height between the beams' axes, h_inf and L_inf the clear
// panel (between the faces of the beams and columns), r_inf its diagonal,
// theta = atan(h_inf / L_inf), EIcol the columns' bending stiffness.
// Opening (area ratio o): a and both strengths times Al-Chaar's (ERDC/CERL
// TR-02-1, 2002) R1 = 0.6 o^2 - 1.6 o + 1, which falls from 1 to 0 on [0, 1].
// Strength, as the storey shear the panel carries, the lesser of
//   crushing of the strut:  V_c = R1 a t fm cos(theta_s),
//   sliding shear (FEMA 356 eq 7-16, ASCE 41 eq 11-4): V_s = R1 L_inf t f_vie,
//     f_vie = 0.03 fm (FEMA 356 Table 7-1: default masonry shear strength
//     27 psi over compressive strength 900 psi, good condition),
// theta_s the angle of the strut between the corner nodes; the strut's axial
// strength Pu = min(V_c, V_s) / cos(theta_s), its axial stiffness K = Em R1 a t
// (force per unit strain). Mass of the wall: rho t L_inf h_inf (1 - o).
namespace c2d {

struct InfillWall {
  double t = 0, fm = 0, Em = 0, rho = 0, open = 0;
};

// The frame around a panel.
struct InfillFrame {
  double bay = 0, storey = 0;            // centreline width and height (m)
  double columnDepth = 0, beamDepth = 0;  // mean depth of the two columns, of the two beams
  double EIcol = 0;                       // mean bending stiffness of the two columns
};

struct InfillStruts {
  double Linf = 0, hinf = 0, rinf = 0, theta = 0;  // clear panel
  double thetaStrut = 0, strutLength = 0;          // the struts between the corner nodes
  double lambda1 = 0, width = 0, reduction = 1;    // a (before R1), R1
  double stiffness = 0;                            // K = Em R1 a t
  double crushing = 0, sliding = 0;                // V_c, V_s (storey shear)
  double strength = 0;                             // Pu, axial
  double mass = 0;                                 // the wall's
  bool crushingGoverns() const { return crushing <= sliding; }
};

inline constexpr double kInfillShearRatio = 0.03;  // f_vie / fm

// R1 of an opening ratio o in [0, 1].
double openingReduction(double open);
// Throws std::invalid_argument (with the reason) for a panel without clear
// size or a wall or frame without positive data.
InfillStruts infillStruts(const InfillWall& wall, const InfillFrame& frame);

}  // namespace c2d
