#include "materials/InfillPanel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace c2d {

double openingReduction(double open) { return 0.6 * open * open - 1.6 * open + 1.0; }

InfillStruts infillStruts(const InfillWall& wall, const InfillFrame& frame) {
  if (!(wall.t > 0) || !(wall.fm > 0) || !(wall.Em > 0))
    throw std::invalid_argument("the wall needs a positive thickness, strength and modulus");
  if (!(frame.EIcol > 0)) throw std::invalid_argument("the columns have no bending stiffness");
  InfillStruts s;
  s.Linf = frame.bay - frame.columnDepth;
  s.hinf = frame.storey - frame.beamDepth;
  if (!(s.Linf > 0) || !(s.hinf > 0))
    throw std::invalid_argument("the panel has no clear size between the members' faces");
  s.rinf = std::hypot(s.Linf, s.hinf);
  s.theta = std::atan2(s.hinf, s.Linf);
  s.strutLength = std::hypot(frame.bay, frame.storey);
  s.thetaStrut = std::atan2(frame.storey, frame.bay);
  s.lambda1 = std::pow(wall.Em * wall.t * std::sin(2 * s.theta) / (4 * frame.EIcol * s.hinf), 0.25);
  s.width = 0.175 * std::pow(s.lambda1 * frame.storey, -0.4) * s.rinf;
  s.reduction = openingReduction(wall.open);
  const double a = s.reduction * s.width;
  s.stiffness = wall.Em * a * wall.t;
  const double cs = std::cos(s.thetaStrut);
  s.crushing = a * wall.t * wall.fm * cs;
  s.sliding = s.reduction * s.Linf * wall.t * kInfillShearRatio * wall.fm;
  s.strength = std::min(s.crushing, s.sliding) / cs;
  s.mass = wall.rho * wall.t * s.Linf * s.hinf * (1 - wall.open);
  return s;
}

}  // namespace c2d
