#pragma once
// A material set weakened to the share f (0 < f <= 1) of its strength and
// stiffness (WEAKen: walls cut, cores opened, bars cut before a blast). The
// result is itself a material set, so a weakened member is exactly a member
// of a weaker set:
//  - SECTion RECTangular: b, the bars' areas and the stirrups' area times f.
//    Every integral over a rectangle with bar layers is linear in (b, As) at
//    a given depth h, so EA, GA, EI, every moment of either sign at the axial
//    force f N, the squash and tension loads and the shear Vu(f N) are f times
//    the original's at N, at the same strains and curvatures; the density is
//    divided by f, so that the mass (rho b h) stays; the confinement and the
//    hinge length (materials/Confinement.h, HingeLength.h) read the original
//    widths and bars (RcSectionData::kept), so the rotations stay;
//  - hand-given laws: E (or the RESUltant stiffnesses EA, GA, EI), every
//    moment and modulus of HARDening and SOFTening (Mc, My, Kh1, Kh2, Mu, Ks,
//    Mr, both signs) and the INTEraction curve's (N, Mu) pairs times f; the
//    rotations (thetaR, the failure jump Mu/|Ks|) and lengths stay; the mass
//    stays (A and the density are kept).
// Throws std::invalid_argument for a factor outside (0, 1] or a set whose
// laws cannot be rescaled exactly.
#include "core/MaterialSet.h"

namespace c2d {

MaterialSet weakenedSet(const MaterialSet& mat, double f, int number);

}  // namespace c2d
