#include "materials/SectionLaws.h"

#include <stdexcept>

#include "materials/RcSection.h"

namespace c2d {

namespace {

// The hand-given laws of one sign at N = 0 (the hardening law elastic when none).
MomentLaw givenLaw(const MaterialSet& mat, int index) {
  MomentLaw l;
  if (mat.hardening) {
    const HardeningValues& h =
        index == 1 && mat.hardening->negative ? *mat.hardening->negative : *mat.hardening;
    l.Mc = h.Mc;
    l.My = h.My;
    l.Kh1 = h.Kh1;
    l.Kh2 = h.Kh2;
  }
  if (mat.softening) {
    double mu = mat.softening->Mu, ks = mat.softening->Ks;
    if (index == 1 && mat.softening->negative) {
      mu = mat.softening->negative->first;
      ks = mat.softening->negative->second;
    }
    l.Mu = mu;
    l.xiF = mu / -ks;
  }
  return l;
}

}  // namespace

void deriveSectionLaws(MaterialSet& mat) {
  mat.rc.reset();
  mat.capacity.reset();
  if (mat.section) {
    auto rc = std::make_shared<const RcSection>(*mat.section);
    mat.resEA = rc->EA();
    mat.resGA = rc->GA();
    mat.resEI = rc->EI();
    mat.A = rc->shape().area();
    mat.I = rc->shape().secondMoment();
    HardeningData hard;
    SofteningData soft;
    for (int k = 0; k < 2; ++k) {
      const MomentLaw l = rc->at(k == 0 ? 1 : -1, 0.0);
      const HardeningValues h{l.Mc, l.My, l.Kh1, l.Kh2};
      if (k == 0) {
        static_cast<HardeningValues&>(hard) = h;
        soft.Mu = l.Mu;
        soft.Ks = -l.Mu / l.xiF;
      } else {
        hard.negative = h;
        soft.negative = std::make_pair(l.Mu, -l.Mu / l.xiF);
      }
    }
    soft.thetaR = rc->ruptureRotation();
    soft.pieceLength = rc->shortestPiece();
    mat.hardening = hard;
    mat.softening = soft;
    mat.hingeSite = HingeSite::Ends;
    mat.rc = rc;
    mat.capacity = rc;
    return;
  }
  if (!mat.interaction.empty()) {
    if (!mat.softening)
      throw std::invalid_argument("an interaction curve scales the SOFTening law: give one");
    mat.capacity =
        std::make_shared<const ScaledCapacity>(std::array<MomentLaw, 2>{givenLaw(mat, 0), givenLaw(mat, 1)},
                                               mat.interaction);
  }
}

}  // namespace c2d
