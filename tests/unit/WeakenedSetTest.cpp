// A weakened material set (materials/WeakenedSet) is the original scaled
// exactly (SECTion: stiffnesses, moments at the scaled axial force, axial and
// shear capacities, rotations kept, mass kept; hand-given laws likewise; TEE
// too, CIRCular refused), and a weakened cantilever's curve is the original's
// times the factor. The command's records: WeakenCommandTest.
#include <gtest/gtest.h>

#include <cmath>

#include <sstream>

#include "elements/ElementFactory.h"
#include "elements/ModelCheckpoint.h"
#include "elements/InfillStrut.h"
#include "materials/RcSection.h"
#include "materials/WeakenedSet.h"
#include "tests/unit/MeshBuildSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::cantilever;
using testing::kHand;

const char* kSection =
    "MATE,1 column\n FRAMe\n SECTion RECTangular 0.5 0.5 30e3 500e3 200e6\n"
    " REBAr 0.05 1.2566e-3 0.45 1.2566e-3\n STIRrups 1e-4 0.15\n DENSity,,2.5\n\n";

void expectRel(double got, double want, double rtol, const char* what) {
  EXPECT_NEAR(got, want, rtol * std::max(std::abs(want), 1e-300)) << what;
}

TEST(WeakenedSet, SectionScalesStiffnessAndEveryCapacityExactly) {
  const Model m = testing::buildMesh(cantilever(kSection));
  const MaterialSet& a = *m.material(1);
  const double f = 0.4;
  const MaterialSet w = weakenedSet(a, f, 7);
  EXPECT_EQ(w.number, 7);
  expectRel(w.EA(), f * a.EA(), 1e-12, "EA");
  expectRel(w.GA(), f * a.GA(), 1e-12, "GA");
  expectRel(w.EI(), f * a.EI(), 1e-12, "EI");
  expectRel(w.rhoA(), a.rhoA(), 1e-12, "mass per length");
  ASSERT_TRUE(w.rc && a.rc);
  expectRel(w.rc->squashLoad(), f * a.rc->squashLoad(), 1e-12, "squash load");
  expectRel(w.rc->tensionYield(), f * a.rc->tensionYield(), 1e-12, "tension yield");
  for (int sign : {1, -1}) {
    for (double N : {-3000.0, -500.0, 0.0, 200.0}) {
      // Widths, bars and links times f keep rho_l, sigma_cp and the strut angle.
      expectRel(w.rc->shearCapacity(f * N, sign), f * a.rc->shearCapacity(N, sign), 1e-12, "Vu");
      const MomentLaw lw = w.capacity->at(sign, f * N), la = a.capacity->at(sign, N);
      expectRel(lw.Mc, f * la.Mc, 1e-9, "Mc");
      expectRel(lw.My, f * la.My, 1e-9, "My");
      expectRel(lw.Mu, f * la.Mu, 1e-9, "Mu");
      expectRel(lw.Kh1, f * la.Kh1, 1e-9, "Kh1");
      expectRel(lw.Kh2, f * la.Kh2, 1e-9, "Kh2");
      expectRel(lw.xiF, la.xiF, 1e-9, "failure jump");
    }
  }
  expectRel(*w.softening->thetaR, *a.softening->thetaR, 1e-12, "rupture rotation");
  expectRel(w.softening->pieceLength, a.softening->pieceLength, 1e-12, "shortest piece");
  // The hinge at any shear span: the original member's hinge length.
  for (double lv : {0.7, 2.0, 3.0})
    expectRel(w.capacity->failureJump(1, f * -500, lv), a.capacity->failureJump(1, -500, lv), 1e-9,
              "failure jump at L_V");
  // A restart file keeps the share (the confinement and hinge length read it).
  Model withWeak = testing::buildMesh(cantilever(kSection));
  withWeak.materials()[7] = w;
  std::stringstream file;
  writeModel(file, withWeak);
  const Model back = readModel(file, 0);
  ASSERT_TRUE(back.material(7) && back.material(7)->section && back.material(7)->capacity);
  EXPECT_EQ(back.material(7)->section->kept, f);
  EXPECT_EQ(back.material(7)->capacity->failureJump(1, -200, 3.0),
            w.capacity->failureJump(1, -200, 3.0));
  EXPECT_THROW(weakenedSet(a, 0, 8), std::invalid_argument);
  EXPECT_THROW(weakenedSet(a, 1.2, 8), std::invalid_argument);
}

TEST(WeakenedSet, HandGivenLawsScaleExactly) {
  const Model m = testing::buildMesh(cantilever(kHand));
  const MaterialSet& a = *m.material(1);
  const double f = 0.25;
  const MaterialSet w = weakenedSet(a, f, 2);
  expectRel(w.EA(), f * a.EA(), 1e-14, "EA");
  expectRel(w.GA(), f * a.GA(), 1e-14, "GA");
  expectRel(w.EI(), f * a.EI(), 1e-14, "EI");
  expectRel(w.rhoA(), a.rhoA(), 1e-14, "mass");
  expectRel(w.hardening->My, f * a.hardening->My, 1e-14, "My");
  expectRel(w.softening->Mu, f * a.softening->Mu, 1e-14, "Mu");
  expectRel(w.softening->Ks, f * a.softening->Ks, 1e-14, "Ks");
  expectRel(w.softening->Mr, f * a.softening->Mr, 1e-14, "Mr");
  expectRel(*w.softening->thetaR, *a.softening->thetaR, 1e-14, "thetaR");
  for (double N : {-1500.0, 0.0, 300.0})
    expectRel(w.capacity->at(1, f * N).Mu, f * a.capacity->at(1, N).Mu, 1e-12, "Mu(N)");
}

// A cantilever pushed at its tip past its base hinge's peak, with and without
// WEAKen 0.5: the base moment of the weakened one is half the other's at
// every step (elastic, hardening, the hinge and its softening).
TEST(WeakenDeck, WeakenedCantileverCurveIsTheOriginalsTimesTheFactor) {
  auto deck = [](const std::string& weaken) {
    return std::string("FEAP * * cantilever\n 0 0 0 2 3 2\n") + cantilever(kSection) + weaken +
           "BOUN\n 1 0 1 1 1\n 4 0 1 0 0\n\nDISP\n 4 0 1 0 0\n\nEND\nBATCh\n PROP,,1\n TPLOt\n"
           " DT,,0.001\n LOOP,,60\n TIME\n LOOP,,30\n TANG,,1\n NEXT\n NEXT\nEND\n\n"
           "reac,1,3\n\nSTOP\n";
  };
  testing::DeckTempDir d1, d2;
  const auto a = testing::runDeckText(d1, "a.inp", deck(""));
  const auto b = testing::runDeckText(d2, "b.inp", deck("WEAKen\n 0.5 1 3\n\n"));
  ASSERT_EQ(a.outcome.exitCode, 0) << a.outcome.message;
  ASSERT_EQ(b.outcome.exitCode, 0) << b.outcome.message;
  const auto ma = testing::readCsv(a.out / "a_tplot.csv").column("reac_1_3");
  const auto mb = testing::readCsv(b.out / "b_tplot.csv").column("reac_1_3");
  ASSERT_EQ(ma.size(), mb.size());
  ASSERT_GT(ma.size(), 50u);
  double peak = 0;
  for (std::size_t i = 0; i < ma.size(); ++i) {
    peak = std::max(peak, std::abs(ma[i]));
    EXPECT_NEAR(mb[i], 0.5 * ma[i], 1e-6 * std::abs(ma[i]) + 1e-9) << "step " << i;
  }
  EXPECT_GT(peak, 0.95 * 269.128);  // past Mu(0) of the section (decks/rc/column_capacity.inp)
  EXPECT_NE(b.log.find("set 1 -> set 2"), std::string::npos);
}

TEST(WeakenedSet, TeeSectionScalesExactlyAndCirclesAreRefused) {
  const Model m = testing::buildMesh(cantilever(
      "MATE,1 beam with its slab\n FRAMe\n SECTion TEE 0.3 0.6 1.2 0.15 30e3 500e3 200e6\n"
      " REBAr 0.04 8e-4 0.55 1.5e-3\n STIRrups 1e-4 0.15\n DENSity,,2.5\n\n"));
  const MaterialSet& a = *m.material(1);
  const double f = 0.6;
  const MaterialSet w = weakenedSet(a, f, 5);
  ASSERT_TRUE(w.rc && a.rc);
  expectRel(w.EI(), f * a.EI(), 1e-12, "EI");
  for (int sign : {1, -1})
    for (double N : {-2000.0, 0.0, 100.0}) {
      expectRel(w.capacity->at(sign, f * N).Mu, f * a.capacity->at(sign, N).Mu, 1e-9, "Mu");
      expectRel(w.capacity->at(sign, f * N).My, f * a.capacity->at(sign, N).My, 1e-9, "My");
    }
  const Model c = testing::buildMesh(cantilever(
      "MATE,1 column\n FRAMe\n SECTion CIRCular 0.6 30e3 500e3\n REBAr RING 8 3.1416e-4 0.06\n"
      " DENSity,,2.5\n\n"));
  EXPECT_THROW(weakenedSet(*c.material(1), 0.5, 5), std::invalid_argument);
}

}  // namespace
}  // namespace c2d
