#pragma once
// MATErial 1 for the tests and benchmarks that build models by hand: a FRAMe
// of resultant stiffnesses EA, GA, EI and the given kinematics, whose mass is
// that of a section of area A and inertia I of the given density.
#include "core/MaterialSet.h"

namespace c2d::test {

inline MaterialSet resultantFrame(Kinematics kin, double EA, double GA, double EI, double density,
                                  double A, double I) {
  MaterialSet m;
  m.number = 1;
  m.elementType = "FRAMe";
  m.kinematics = kin;
  m.resEA = EA;
  m.resGA = GA;
  m.resEI = EI;
  m.density = density;
  m.A = A;
  m.I = I;
  return m;
}

}  // namespace c2d::test
