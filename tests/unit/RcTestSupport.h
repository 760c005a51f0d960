#pragma once
// Shared by the RC tests: the C30/B500 materials, the column section of
// verification.md V20 (with or without links), the T-beam of the decks, and a 0.3 x 0.5 m section
// with the given bar layers (depth from the top face, area; kN, m), its laws derived.
#include <cmath>
#include <vector>

#include "core/MaterialSet.h"
#include "materials/SectionLaws.h"

namespace c2d::test {

// C30 concrete and B500 steel (fy 500 MPa, Es 200 GPa, hardening to 540 MPa at
// 5 %), kN and m: the materials of every RC test section.
inline RcSectionData c30b500() {
  RcSectionData d;
  d.fc = 30e3;
  d.fy = 500e3;
  d.Es = 200e6;
  d.fu = 540e3;
  d.eu = 0.05;
  return d;
}

// The T-beam of decks/rc/tee_beam.inp: bw 0.3, h 0.6, beff 1.2, hf 0.15; 6 bars
// of 25 mm at 0.55, 10 of 16 mm in the slab at 0.04; C30, B500.
inline RcSectionData teeBeam() {
  const double a25 = M_PI * 0.0125 * 0.0125, a16 = M_PI * 0.008 * 0.008;
  RcSectionData d = c30b500();
  d.shape = SectionShapeKind::Tee;
  d.b = 0.3;
  d.h = 0.6;
  d.flangeWidth = 1.2;
  d.flangeDepth = 0.15;
  d.bars = {{0.04, 10 * a16}, {0.55, 6 * a25}};
  return d;
}

// The section of verification.md V20: 0.5 x 0.5 m, 4 bars of 20 mm at 0.05 m
// from each face, C30, B500; links of two legs of 10 mm at spacing s (none for
// s = 0).
inline RcSectionData v20(double s = 0) {
  RcSectionData d = c30b500();
  d.b = d.h = 0.5;
  const double a20 = M_PI * 0.01 * 0.01;
  d.bars = {{0.05, 4 * a20}, {0.45, 4 * a20}};
  if (s > 0) d.stirrups = Stirrups{2 * M_PI * 0.005 * 0.005, s, 500e3};
  return d;
}

inline MaterialSet rcSectionMaterial(Kinematics kin, std::vector<RebarLayer> bars) {
  MaterialSet m;
  m.number = 1;
  m.elementType = "FRAMe";
  m.kinematics = kin;
  m.density = 2.5;
  RcSectionData d = c30b500();
  d.b = 0.3;
  d.h = 0.5;
  d.bars = std::move(bars);
  m.section = d;
  deriveSectionLaws(m);
  return m;
}

}  // namespace c2d::test
