// The mesh command INFIll (macro/commands/InfillCommand): two struts per panel
// numbered after the elements, generated panels, its errors, an opening of
// one making no wall, the panels' debris mass at the nodes, and a restart
// round trip.
#include <gtest/gtest.h>

#include <sstream>

#include "core/Brace.h"
#include "macro/output/Debris.h"
#include "elements/InfillStrut.h"
#include "elements/ModelCheckpoint.h"
#include "materials/InfillPanel.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/MeshBuildSupport.h"

namespace c2d {
namespace {

const char* kFrame =
    "COOR\n 1 0 0 0\n 2 0 5 0\n 3 0 5 3\n 4 0 0 3\n 5 0 10 0\n 6 0 10 3\n\n"
    "ELEM\n 1 1 1 1 4\n 2 1 1 2 3\n 3 1 2 4 3\n 4 1 1 5 6\n 5 1 2 3 6\n\n"
    "MATE,1\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.16 2.133333333333e-3\n\n"
    "MATE,2\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.15 3.125e-3\n\n";

Model build(const std::string& mesh, std::ostream* echo = nullptr,
            const std::string& control = "0 0 0 2 3 2") {
  return testing::buildMesh(mesh, echo, control);
}

void expectBuildError(const std::string& mesh, int line, int col, const std::string& msg) {
  testing::expectMeshError(mesh, line, col, msg);
}

TEST(InfillCommand, TwoStrutsPerPanelNumberedAfterTheElements) {
  std::ostringstream echo;
  const Model m = build(std::string(kFrame) + "INFIll,,0.2,4000\n 1 2 3 4\n 2 5 6 3\n\n", &echo);
  ASSERT_EQ(m.numElements(), 9);
  const auto* s6 = dynamic_cast<const InfillStrut*>(&m.element(5));
  const auto* s7 = dynamic_cast<const InfillStrut*>(&m.element(6));
  const auto* s9 = dynamic_cast<const InfillStrut*>(&m.element(8));
  ASSERT_TRUE(s6 && s7 && s9);
  EXPECT_EQ(s6->nodes(), (std::array<int, 2>{0, 2}));  // n1-n3
  EXPECT_EQ(s7->nodes(), (std::array<int, 2>{1, 3}));  // n2-n4
  EXPECT_EQ(s9->nodes(), (std::array<int, 2>{4, 2}));  // panel 2's n2-n4: 5-3
  EXPECT_EQ(s6->data().partner, 6);
  EXPECT_EQ(s7->data().partner, 5);
  EXPECT_EQ(s6->data().panel, 1);
  EXPECT_EQ(s9->data().panel, 2);
  EXPECT_NE(echo.str().find("element 6 (nodes 1-3), element 7 (nodes 2-4)"), std::string::npos)
      << echo.str();
  // The wall's mass at the corners: clear L_inf = 5 - 0.4 (columns
  // sqrt(12 I/A) = 0.4 deep), h_inf = 3 - (0.5 + 0)/2 (the beam 0.5 deep, no
  // beam at the base): 1.8 0.2 4.6 2.75 / 4 per node and strut.
  EXPECT_NEAR(s6->data().nodeMass, 1.8 * 0.2 * 4.6 * 2.75 / 4, 1e-9);
  EXPECT_FALSE(s6->data().finite);
}

TEST(InfillCommand, GeneratedPanelsAndNumel) {
  // Two storeys of one bay; the second panel generated with dn = 2. With
  // numel = 6 the struts follow element 6.
  const std::string mesh =
      "COOR\n 1 0 0 0\n 2 0 5 0\n 3 0 0 3\n 4 0 5 3\n 5 0 0 6\n 6 0 5 6\n\n"
      "ELEM\n 1 1 1 1 3\n 2 1 1 3 5\n 3 1 1 2 4\n 4 1 1 4 6\n 5 1 2 3 4\n 6 1 2 5 6\n"
      "\n"
      "MATE,1\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.16 2.133333333333e-3\n"
      " FINIte\n\n"
      "MATE,2\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.15 3.125e-3\n FINIte\n\n"
      "INFIll,,0.2,4000\n 1 2 4 3 1 2\n\n";
  const Model m = build(mesh, nullptr, "6 6 2 2 3 2");
  ASSERT_EQ(m.numElements(), 10);
  for (int e = 6; e < 10; ++e) EXPECT_TRUE(isBrace(m.element(e))) << e;
  const auto& top = dynamic_cast<const InfillStrut&>(m.element(8));
  EXPECT_EQ(top.data().panel, 2);
  EXPECT_EQ(top.nodes(), (std::array<int, 2>{2, 5}));  // 3-6
  EXPECT_TRUE(top.data().finite);  // the columns' kinematics
  // Both beams 0.5 deep: h_inf = 2.5.
  EXPECT_NEAR(top.data().nodeMass, 1.8 * 0.2 * 4.6 * 2.5 / 4, 1e-9);
}

TEST(InfillCommand, Errors) {
  const std::string f(kFrame);
  const int l = 28;  // the line of the INFIll record after kFrame
  // corners not forming a panel (clockwise)
  expectBuildError(f + "INFIll,,0.2,4000\n 1 4 3 2\n\n", l + 1, 2, "do not form a panel");
  // a bay without columns: no member along the right edge 2-3
  expectBuildError(
      "COOR\n 1 0 0 0\n 2 0 5 0\n 3 0 5 3\n 4 0 0 3\n\nELEM\n 1 1 1 1 4\n 2 1 2 4 3\n\n"
      "MATE,1\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.16 2.1e-3\n\n"
      "MATE,2\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.15 3.1e-3\n\n"
      "INFIll,,0.2,4000\n 1 2 3 4\n\n",
      24, 4, "has no column");
  expectBuildError(f + "INFIll,,0.2,4000,,,1.2\n 1 2 3 4\n\n", l, 20,
                   "opening ratio must lie in [0, 1]");
  expectBuildError(f + "INFIll,,0.2,4000,,,-0.1\n 1 2 3 4\n\n", l, 20,
                   "opening ratio must lie in [0, 1]");
  expectBuildError(f + "INFIll,,0,4000\n 1 2 3 4\n\n", l, 9, "positive wall thickness");
  expectBuildError(f + "INFIll,,0.2\n 1 2 3 4\n\n", l, 12, "compressive strength");
  expectBuildError(f + "INFIll,X,0.2,4000\n 1 2 3 4\n\n", l, 8, "no option word");
  expectBuildError(f + "INFIll,,0.2,4000\n 1 2 3 4 1 0\n\n", l + 1, 12, "nonzero node increment");
  expectBuildError(f + "INFIll,,0.2,4000\n\n", l, 1, "needs data records");
  expectBuildError(f + "INFIll,,0.2,4000\n 1 2 3 9\n\n", l + 1, 8, "has no coordinates");
}

TEST(InfillCommand, OpeningOfOneIsNoWall) {
  const Model m = build(std::string(kFrame) + "INFIll,,0.2,4000,,,1\n 1 2 3 4\n\n");
  EXPECT_EQ(m.numElements(), 5);
}

TEST(InfillCommand, DebrisMassAtTheNodesAndNoPieceJoined) {
  const Model m = build(std::string(kFrame) + "INFIll,,0.2,4000\n 1 2 3 4\n\n");
  const State s = [&] {
    State st;
    st.resize(m.numNodes());
    return st;
  }();
  double strutMass = 0;
  for (int e : {5, 6}) strutMass += 2 * dynamic_cast<const InfillStrut&>(m.element(e)).data().nodeMass;
  double pointMass = 0;
  for (const MassPiece& p : massPieces(m, s))
    if (p.x1 == p.x0) pointMass += p.mass;
  EXPECT_NEAR(pointMass, strutMass, 1e-12);
}

TEST(InfillCommand, RestartRoundTrip) {
  Model m = build(std::string(kFrame) + "INFIll,,0.2,4000\n 1 2 3 4\n\n");
  auto& strut = dynamic_cast<InfillStrut&>(m.element(6));
  ElementKinematics kin;
  kin.d = ElemVec::Zero();
  kin.d(3) = 0.01;  // node 4 moved right: strut 2-4 shortens past its peak
  kin.dn = kin.vn = kin.an = ElemVec::Zero();
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(strut.evaluate(kin, StepRule{}, true, r, k).ok);
  strut.commit();
  std::stringstream buf;
  writeElement(buf, strut);
  const std::unique_ptr<Element> back = readElement(buf, m);
  const auto& b = dynamic_cast<const InfillStrut&>(*back);
  EXPECT_EQ(b.nodes(), strut.nodes());
  EXPECT_EQ(b.committedState().kappa, strut.committedState().kappa);
  EXPECT_EQ(b.data().law.strength(), strut.data().law.strength());
  EXPECT_EQ(b.data().partner, strut.data().partner);
  ElemVec r2;
  ElemMat k2;
  auto& bm = const_cast<InfillStrut&>(b);
  ASSERT_TRUE(bm.evaluate(kin, StepRule{}, true, r2, k2).ok);
  EXPECT_EQ(r2, r);
}

}  // namespace
}  // namespace c2d
