#pragma once
// The laws a material set derives from its section data (pure computation,
// called by the deck binder and when a restart file is read):
//  - SECTion + REBAr: the RC section (materials/RcSection) gives the resultant
//    stiffnesses EA, GA, EI (transformed uncracked section), the shape's
//    gross A and I (mass, rotary inertia, contact radius), the hardening and
//    softening laws of either sign at N = 0, the joint's rupture rotation
//    thetaR, hinges at the element ends, and the laws' dependence on N;
//  - INTEraction pairs with hand-given laws: their scaling with N
//    (materials/MomentCapacity.h ScaledCapacity).
// Throws std::invalid_argument for data from which no law follows.
#include "core/MaterialSet.h"

namespace c2d {

void deriveSectionLaws(MaterialSet& mat);

}  // namespace c2d
