#pragma once
// Shared by the RC member tests: a 0.3 x 0.5 m C30 section (fy 500 MPa, Es
// 200 GPa, bars hardening to 540 MPa at 5 %) with the given bar layers (depth
// from the top face, area; kN, m), its laws derived.
#include <vector>

#include "core/MaterialSet.h"
#include "materials/SectionLaws.h"

namespace c2d::test {

inline MaterialSet rcSectionMaterial(Kinematics kin, std::vector<RebarLayer> bars) {
  MaterialSet m;
  m.number = 1;
  m.elementType = "FRAMe";
  m.kinematics = kin;
  m.density = 2.5;
  RcSectionData d;
  d.b = 0.3;
  d.h = 0.5;
  d.fc = 30e3;
  d.fy = 500e3;
  d.Es = 200e6;
  d.fu = 540e3;
  d.eu = 0.05;
  d.bars = std::move(bars);
  m.section = d;
  deriveSectionLaws(m);
  return m;
}

}  // namespace c2d::test
