// The deck records of the SECTion shapes and REBAr RING: what they bind (the
// ring's bars as layers, one per depth), the errors at their fields, the log's
// echo, and the restart file's round trip of the shape's data.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "macro/deck/DeckParser.h"
#include "macro/mesh/MeshBinder.h"
#include "materials/RcSection.h"
#include "solvers/Analysis.h"
#include "solvers/RestartFile.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/MeshBuildSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;
using testing::expectDeckError;

Model build(const std::string& mesh, std::ostream* echo = nullptr) {
  return testing::buildMesh(mesh, echo);
}

// The material is on lines 3 (MATE), 4 (FRAMe), 5 (SECTion), 6 (REBAr) ...
void expectError(const std::string& records, int line, int col, const std::string& msg) {
  expectDeckError([&] { build("MATE,1\n FRAMe\n" + records + "\n"); }, "mesh.inp", line, col, msg);
}

TEST(RcShapeRecords, ShapesAndRingBind) {
  std::ostringstream echo;
  const Model m = build(
      "MATE,1\n FRAMe\n SECTion ANNUlar 4 0.25 30e3 500e3\n REBAr RING 60 3.1416e-4 0.06\n\n"
      "MATE,2\n FRAMe\n SECTion TEE 0.3 0.6 1.2 0.15 30e3 500e3 200e6 540e3 0.06\n"
      " REBAr 0.04 6.8e-4 0.55 2.95e-3\n\n"
      "MATE,3\n FRAMe\n SECTion CIRCular 0.6 30e3 500e3\n REBAr RING 7 3.1416e-4 0.06\n"
      " REBAr 0.3 1e-4\n\n",
      &echo);
  const RcSectionData& a = *m.material(1)->section;
  EXPECT_EQ(a.shape, SectionShapeKind::Annulus);
  EXPECT_EQ(a.h, 4.0);
  EXPECT_EQ(a.wall, 0.25);
  // 60 bars: the top and bottom ones alone, 29 pairs at +-theta.
  ASSERT_EQ(a.bars.size(), 31u);
  double total = 0;
  for (const RebarLayer& l : a.bars) total += l.area;
  EXPECT_NEAR(total, 60 * 3.1416e-4, 1e-12);
  EXPECT_NEAR(a.bars.front().depth, 0.06, 1e-14);
  EXPECT_NEAR(a.bars.back().depth, 3.94, 1e-14);
  EXPECT_NEAR(m.material(1)->A, M_PI * (16 - 3.5 * 3.5) / 4, 1e-12);
  const RcSectionData& t = *m.material(2)->section;
  EXPECT_EQ(t.shape, SectionShapeKind::Tee);
  EXPECT_EQ(t.flangeWidth, 1.2);
  EXPECT_EQ(t.flangeDepth, 0.15);
  EXPECT_EQ(t.eu, 0.06);
  EXPECT_NEAR(m.material(2)->A, 1.2 * 0.15 + 0.3 * 0.45, 1e-14);
  // The flange on the top face: sagging (positive) is the strong sign.
  EXPECT_GT(m.material(2)->softening->Mu, 1.5 * m.material(2)->softening->negative->first);
  // 7 bars (odd): the top one, three pairs; plus the layer given as such.
  const RcSectionData& c = *m.material(3)->section;
  EXPECT_EQ(c.shape, SectionShapeKind::Circle);
  ASSERT_EQ(c.bars.size(), 5u);
  EXPECT_NEAR(c.bars[0].depth, 0.3, 1e-14);  // the layer record's, then the ring's
  EXPECT_NEAR(c.bars[1].depth, 0.06, 1e-14);
  EXPECT_NEAR(c.bars[4].depth, 0.3 + 0.24 * std::cos(M_PI / 7), 1e-14);
  EXPECT_NEAR(c.bars[4].area, 2 * 3.1416e-4, 1e-16);
  for (const char* s : {"Annular section", "Wall t", "T-section", "Flange width beff",
                        "Circular section", "Diameter D", "Concrete area", "Web width bw"})
    EXPECT_NE(echo.str().find(s), std::string::npos) << s;
}

TEST(RcShapeRecords, ErrorsAtTheirFields) {
  const std::string bars = " REBAr 0.05 1e-3 0.55 1e-3\n";
  expectError(" SECTion OVAL 0.3 0.6 30e3 500e3\n" + bars, 5, 10, "unknown shape 'OVAL'");
  // TEE: beff below bw (field 4), hf not below h (field 5).
  expectError(" SECTion TEE 0.3 0.6 0.2 0.15 30e3 500e3\n" + bars, 5, 22, "flange width beff");
  expectError(" SECTion TEE 0.3 0.6 1.2 0.6 30e3 500e3\n" + bars, 5, 26, "flange thickness hf");
  expectError(" SECTion TEE 0.3 0.6 1.2 0.15 30e3\n" + bars, 5, 35, "SECTion needs 6 values");
  expectError(" SECTion TEE 0.3 0.6 1.2 0.15 0 500e3\n" + bars, 5, 31, "strength fc");
  // ANNUlar: t not below D/2 (field 3).
  expectError(" SECTion ANNUlar 4 2 30e3 500e3\n REBAr RING 8 3e-4 0.06\n", 5, 20,
              "wall thickness t = 2 is not below D/2");
  expectError(" SECTion CIRCular 0 30e3 500e3\n REBAr RING 8 3e-4 0.06\n", 5, 19,
              "diameter D must be positive");
  // RING: its values, bars outside the concrete (field 4), on a rectangle.
  expectError(" SECTion CIRCular 0.6 30e3 500e3\n REBAr RING 8.5 3e-4 0.06\n", 6, 13,
              "whole number");
  expectError(" SECTion CIRCular 0.6 30e3 500e3\n REBAr RING 8 0 0.06\n", 6, 15, "area A");
  expectError(" SECTion CIRCular 0.6 30e3 500e3\n REBAr RING 8 3e-4\n", 6, 19, "needs n, A and c");
  expectError(" SECTion CIRCular 0.6 30e3 500e3\n REBAr RING 8 3e-4 0.3\n", 6, 20,
              "outside the concrete");
  expectError(" SECTion ANNUlar 4 0.25 30e3 500e3\n REBAr RING 8 3e-4 0.3\n", 6, 20,
              "outside the concrete (wall t = 0.25)");
  expectError(" SECTion RECT 0.3 0.6 30e3 500e3\n REBAr RING 8 3e-4 0.05\n", 6, 8,
              "needs SECTion CIRCular or ANNUlar");
  expectError(" ELAS ISOT 1e6 0.2\n CROS SECT 1 1\n REBAr RING 8 3e-4 0.05\n", 7, 2,
              "REBAr without SECTion");
  // Layers outside the depth of a circle.
  expectError(" SECTion CIRCular 0.6 30e3 500e3\n REBAr 0.05 1e-3 0.65 1e-3\n", 6, 18,
              "lies outside the section (h = 0.6)");
}

// The shape's data in the restart file: a column of annular section under
// axial force pushed at its tip, saved, read back.
TEST(RcShapeRecords, RestartFileHoldsTheShape) {
  DeckTempDir dir;
  const std::string deck = R"(FEAP * * annular column
  0 0 0 2 3 2

COORdinates
  1 1 0 0
  5 0 0 8

ELEMents
  1 1 1 1 2
  4 0 1 4 5

MATErial,1 shaft
  FRAMe
    SECTion ANNUlar 1.5 0.2 30e3 500e3
    REBAr RING 24 3.1416e-4 0.05
    STIRrups 2e-4 0.2
    DENSity,,2.5
    FINIte

BOUNdary
  1 0 1 1 1

FORCe
  5 0 100 -2000 0

END
BATCh
  PROP,,1
  DT,,0.5
  LOOP,,2
    TIME
    LOOP,,20
      TANG,,1
    NEXT
  NEXT
  SAVE,ann
END
2
  0 0 1e6 1e6

STOP
)";
  const testing::DeckResult r = testing::runDeckText(dir, "ann.inp", deck);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message << r.console << r.log;
  Model model;
  Analysis analysis(model);
  loadRestart(r.out / "ann.rst", model, analysis);
  const MaterialSet& m = *model.material(1);
  ASSERT_TRUE(m.section && m.rc);
  EXPECT_EQ(m.section->shape, SectionShapeKind::Annulus);
  EXPECT_EQ(m.section->wall, 0.2);
  EXPECT_EQ(m.section->h, 1.5);
  EXPECT_EQ(m.section->bars.size(), 13u);
  EXPECT_NEAR(m.rc->shape().area(), M_PI * (1.5 * 1.5 - 1.1 * 1.1) / 4, 1e-14);
  // EC2 6.8 on the web 2t = 0.4 m at d = 0.8 D: the links' Asw/s fyw z cot(theta)
  // at the flattest strut cot = 2.5 (the struts' 6.9 bound, 2360 kN, is not
  // reached), above the concrete's VRd,c (about 350 kN).
  EXPECT_NEAR(m.rc->shearCapacity(0.0, 1), 2e-4 / 0.2 * 500e3 * 0.9 * 0.8 * 1.5 * 2.5, 1e-9);
  EXPECT_NEAR(m.rc->shear().parts(0.0, 1).cot, 2.5, 1e-15);
  EXPECT_NE(r.log.find("Annular section"), std::string::npos);
}

}  // namespace
}  // namespace c2d
