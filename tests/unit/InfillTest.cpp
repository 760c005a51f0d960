// Infill panels (INFIll): the equivalent struts' width, stiffness and strength
// against FEMA 356's relations computed by hand for two panels, the strut law
// (compression only, crushing, residual, gone), the strut element's tangent by
// finite differences and its energy under the mid-point rule, the mesh
// command's numbering and its errors, a restart round trip, and the infilled
// frame pushed sideways against the frame-plus-strut closed form
// (decks/infill/infilled_frame.inp).
#include <gtest/gtest.h>

#include <cmath>
#include <Eigen/Geometry>
#include <random>
#include <sstream>

#include "core/Brace.h"
#include "core/Debris.h"
#include "elements/InfillStrut.h"
#include "elements/ModelCheckpoint.h"
#include "materials/InfillPanel.h"
#include "materials/StrutLaw.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/ElementTestSupport.h"
#include "tests/unit/MeshBuildSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

// ---------------------------------------------------------------------------
// FEMA 356 7.5.2 by hand

// Panel A: bay 5 m x storey 3 m, columns 0.4 m deep (EIcol = 30e6 0.4^4/12 =
// 64000 kN m^2), beams 0.5 m deep; wall t = 0.2 m, fm = 4000 kN/m^2,
// Em = 550 fm = 2.2e6, rho = 1.8, solid.
//   L_inf = 4.6, h_inf = 2.5, r_inf = sqrt(4.6^2 + 2.5^2) = 5.235456,
//   sin(2 theta) = 2 L h / r^2 = 23/27.41 = 0.839110,
//   lambda1 = (2.2e6 0.2 0.839110 / (4 64000 2.5))^(1/4) = 0.576888^(1/4) = 0.871511,
//   a = 0.175 (0.871511 3)^-0.4 5.235456 = 0.623785 m,
//   K = Em a t = 274465 kN; theta_s = atan(3/5), cos = 0.857493;
//   crushing V_c = a t fm cos = 427.91 kN, sliding V_s = 4.6 0.2 0.03 4000 = 110.40 kN,
//   Pu = 110.40 / 0.857493 = 128.747 kN; mass 1.8 0.2 4.6 2.5 = 4.14 t.
TEST(InfillPanel, SolidPanelAgainstFema356ByHand) {
  const InfillWall wall{0.2, 4000, 2.2e6, 1.8, 0};
  InfillFrame frame;
  frame.bay = 5;
  frame.storey = 3;
  frame.columnDepth = 0.4;
  frame.beamDepth = 0.5;
  frame.EIcol = 30e6 * std::pow(0.4, 4) / 12;
  const InfillStruts s = infillStruts(wall, frame);
  EXPECT_NEAR(s.rinf, 5.235456, 1e-6);
  EXPECT_NEAR(s.lambda1, 0.871511, 1e-6);
  EXPECT_NEAR(s.width, 0.623785, 1e-6);
  EXPECT_NEAR(s.stiffness, 274465.4, 0.1);
  EXPECT_NEAR(s.crushing, 427.913, 1e-3);
  EXPECT_NEAR(s.sliding, 110.400, 1e-9);
  EXPECT_FALSE(s.crushingGoverns());
  EXPECT_NEAR(s.strength, 128.7474, 1e-4);
  EXPECT_NEAR(s.mass, 4.14, 1e-12);
}

// Panel B: bay 4 m x storey 3.2 m, columns 0.3 m deep (EIcol = 20250), no
// beam depth; wall t = 0.12, fm = 2500, Em = 1.5e6, rho = 1.6, open = 0.3.
//   L_inf = 3.7, h_inf = 3.2, r_inf = 4.891830, sin(2 theta) = 23.68/23.93 = 0.989553,
//   lambda1 = (1.5e6 0.12 0.989553 / (4 20250 3.2))^(1/4) = 0.910477,
//   a = 0.175 (0.910477 3.2)^-0.4 4.891830 = 0.558138 m,
//   R1 = 0.6 0.09 - 1.6 0.3 + 1 = 0.574 (Al-Chaar 2002),
//   K = Em R1 a t = 57666.8 kN; cos(theta_s) = 4/sqrt(26.24) = 0.780869;
//   V_c = R1 a t fm cos = 75.050 kN, V_s = R1 3.7 0.12 0.03 2500 = 19.1142 kN,
//   Pu = 19.1142 / 0.780869 = 24.4781 kN; mass 1.6 0.12 3.7 3.2 0.7 = 1.591296 t.
TEST(InfillPanel, PanelWithAnOpeningAgainstFema356AndAlChaarByHand) {
  const InfillWall wall{0.12, 2500, 1.5e6, 1.6, 0.3};
  InfillFrame frame;
  frame.bay = 4;
  frame.storey = 3.2;
  frame.columnDepth = 0.3;
  frame.EIcol = 30e6 * std::pow(0.3, 4) / 12;
  const InfillStruts s = infillStruts(wall, frame);
  EXPECT_NEAR(s.lambda1, 0.910477, 1e-6);
  EXPECT_NEAR(s.width, 0.558138, 1e-6);
  EXPECT_NEAR(s.reduction, 0.574, 1e-12);
  EXPECT_NEAR(s.stiffness, 57666.84, 0.01);
  EXPECT_NEAR(s.crushing, 75.0504, 1e-4);
  EXPECT_NEAR(s.sliding, 19.1142, 1e-9);
  EXPECT_NEAR(s.strength, 24.47812, 1e-5);
  EXPECT_NEAR(s.mass, 1.591296, 1e-9);
  // The opening's reduction falls from 1 (solid) to 0 (no wall).
  EXPECT_DOUBLE_EQ(openingReduction(0), 1.0);
  EXPECT_NEAR(openingReduction(1), 0.0, 1e-15);
}

TEST(InfillPanel, CrushingGovernsANarrowStrut) {
  // The lesser of the two: with a strut narrower than 0.03 L_inf / cos the
  // crushing governs (here the columns make lambda1 h large).
  const InfillWall wall{0.2, 4000, 2.2e6, 1.8, 0};
  InfillFrame frame{30, 3, 0, 0, 1e-6};
  const InfillStruts s = infillStruts(wall, frame);
  ASSERT_TRUE(s.crushingGoverns());
  EXPECT_NEAR(s.strength, s.width * 0.2 * 4000, 1e-9 * s.strength);
}

TEST(InfillPanel, RefusesAPanelWithoutClearSize) {
  const InfillWall wall{0.2, 4000, 2.2e6, 1.8, 0};
  InfillFrame frame{5, 3, 6, 0, 64000};
  EXPECT_THROW(infillStruts(wall, frame), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// the strut law

TEST(StrutLaw, CompressionOnlyElasticToThePeakThenResidualThenGone) {
  const StrutLaw law(1000, 2);  // s_p = 0.002
  const StrutLawState fresh;
  EXPECT_EQ(law.evaluate(0.001, fresh).N, 0.0);  // tension: nothing
  EXPECT_EQ(law.evaluate(0.001, fresh).dN, 0.0);
  const StrutResponse e = law.evaluate(-0.001, fresh);
  EXPECT_DOUBLE_EQ(e.N, -1.0);
  EXPECT_DOUBLE_EQ(e.dN, 1000);
  EXPECT_DOUBLE_EQ(law.evaluate(-0.002, fresh).N, -2.0);  // the peak
  // Softening: from 2 at s_p to 0.4 at 5 s_p, slope -1.6/0.008 = -200.
  const StrutResponse soft = law.evaluate(-0.004, fresh);
  EXPECT_NEAR(soft.N, -(2 - 200 * 0.002), 1e-12);
  EXPECT_NEAR(soft.dN, -200, 1e-9);
  EXPECT_NEAR(law.evaluate(-0.012, fresh).N, -0.4, 1e-12);  // residual 0.2 Pu
  EXPECT_NEAR(law.evaluate(-0.015, fresh).N, -0.4, 1e-12);  // held to 8 s_p
  EXPECT_NEAR(law.evaluate(-0.018, fresh).N, -0.2, 1e-12);  // falls to 0 at 10 s_p
  const StrutResponse gone = law.evaluate(-0.0201, fresh);
  EXPECT_TRUE(gone.state.gone);
  EXPECT_EQ(gone.N, 0.0);
  // Gone is for good, whatever the strain.
  EXPECT_EQ(law.evaluate(-0.001, gone.state).N, 0.0);
}

TEST(StrutLaw, UnloadsAlongTheSecantAndReloadsToTheEnvelope) {
  const StrutLaw law(1000, 2);
  const StrutResponse past = law.evaluate(-0.006, StrutLawState{});  // P = 2 - 200 0.004 = 1.2
  ASSERT_NEAR(past.N, -1.2, 1e-12);
  const StrutResponse back = law.evaluate(-0.003, past.state);
  EXPECT_NEAR(back.N, -0.6, 1e-12);  // secant 1.2/0.006
  EXPECT_NEAR(back.dN, 200, 1e-9);
  EXPECT_NEAR(back.energy, 0.5 * 0.6 * 0.003, 1e-15);
  EXPECT_NEAR(law.evaluate(-0.007, past.state).N, -1.0, 1e-12);  // on the envelope again
}

TEST(StrutLaw, ADoomedStrutGoesOnceItCarriesNothing) {
  const StrutLaw law(1000, 2);
  StrutLawState s;
  s.doomed = true;
  EXPECT_DOUBLE_EQ(law.evaluate(-0.001, s).N, -1.0);  // still compressed: carries on
  EXPECT_TRUE(law.evaluate(0.0001, s).state.gone);
}

TEST(StrutLaw, WeakenedKeepsTheShareOfStiffnessAndStrength) {
  StrutLaw law(1000, 2);
  law.scale(0.25);
  EXPECT_DOUBLE_EQ(law.stiffness(), 250);
  EXPECT_DOUBLE_EQ(law.strength(), 0.5);
  EXPECT_DOUBLE_EQ(law.peakStrain(), 0.002);
  EXPECT_THROW(law.scale(0), std::invalid_argument);
  EXPECT_THROW(law.scale(1.5), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// the strut element

InfillStrutData strutData(bool finite) {
  InfillStrutData d;
  d.nodes = {0, 1};
  d.x1 = Vec2(0.3, -0.2);
  d.x2 = Vec2(4.3, 2.8);  // length 5
  d.law = StrutLaw(2e5, 100);  // s_p = 5e-4
  d.nodeMass = 0.7;
  d.finite = finite;
  return d;
}

// Displacements that shorten the strut by the strain s along it, plus a rigid
// rotation phi (finite) and a translation.
ElemVec shortened(double s, double phi) {
  const Vec2 x1(0.3, -0.2), x2(4.3, 2.8);
  const Vec2 c = 0.5 * (x1 + x2);
  const Eigen::Rotation2Dd r(phi);
  ElemVec d = ElemVec::Zero();
  const Vec2 y1 = c + (1 - s) * (r * (x1 - c)) + Vec2(0.1, -0.05);
  const Vec2 y2 = c + (1 - s) * (r * (x2 - c)) + Vec2(0.1, -0.05);
  d.segment<2>(0) = y1 - x1;
  d.segment<2>(3) = y2 - x2;
  d(2) = 0.3;  // rotations: the strut ignores them
  d(5) = -0.2;
  return d;
}

TEST(InfillStrut, TangentMatchesFiniteDifferences) {
  std::mt19937 gen(7);
  for (bool finite : {false, true})
    for (double s : {2e-4, 1.5e-3, 4.5e-3})  // elastic, softening, residual
      for (Scheme scheme : {Scheme::Static, Scheme::MidPoint}) {
        InfillStrut strut(strutData(finite));
        StepRule rule;
        rule.scheme = scheme;
        rule.alpha = scheme == Scheme::MidPoint ? 0.1 : 0;
        if (scheme == Scheme::MidPoint) {
          rule.h = 0.01;
          rule.ca = 2 / rule.h / rule.h;
          rule.av = -2 / rule.h;
        }
        ElementKinematics kin;
        kin.d = shortened(s, finite ? 0.3 : 0.0) + test::randomVec(gen, 1e-6);
        kin.dn = shortened(0.8 * s, finite ? 0.25 : 0.0);
        kin.vn = test::randomVec(gen, 0.1);
        kin.an = test::randomVec(gen, 0.1);
        ElemVec r;
        ElemMat k;
        ASSERT_TRUE(strut.evaluate(kin, rule, true, r, k).ok);
        const ElemMat fd = test::centralDifferenceTangent(strut, kin, rule, 1e-8);
        EXPECT_LT((k - fd).cwiseAbs().maxCoeff(), 1e-5 * std::max(1.0, k.cwiseAbs().maxCoeff()))
            << "finite " << finite << " s " << s << " scheme " << static_cast<int>(scheme)
            << "\nK\n" << k << "\nFD\n" << fd;
        for (int i : {2, 5}) EXPECT_EQ(r(i), 0.0);  // no moment
      }
}

TEST(InfillStrut, GeometricallyExactUnderARigidRotation) {
  InfillStrut strut(strutData(true));
  ElementKinematics kin;
  kin.d = shortened(0, 1.2);
  kin.dn = kin.d;
  kin.vn.setZero();
  kin.an.setZero();
  ElemVec r;
  ElemMat k;
  ASSERT_TRUE(strut.evaluate(kin, StepRule{}, false, r, k).ok);
  EXPECT_LT(r.norm(), 1e-9);
  // Shortened by 2e-4 and turned: the force along the turned chord, N = K eps.
  kin.d = shortened(2e-4, 1.2);
  ASSERT_TRUE(strut.evaluate(kin, StepRule{}, false, r, k).ok);
  const double eps = (std::pow(1 - 2e-4, 2) - 1) / 2;
  EXPECT_NEAR(strut.sectionForces().N, 2e5 * eps, 1e-9);
  const Vec2 chord = Eigen::Rotation2Dd(1.2) * Vec2(4, 3) * (1 - 2e-4);
  const Vec2 f2 = r.segment<2>(3);
  EXPECT_NEAR(f2.normalized().dot(chord.normalized()), -1.0, 1e-12);  // pulls node 2 in
}

TEST(InfillStrut, MidPointConservesTheEnergyOfAnElasticStrut) {
  InfillStrut strut(strutData(true));
  StepRule rule;
  rule.scheme = Scheme::MidPoint;
  ElementKinematics kin;
  kin.dn = shortened(1e-4, 0.2);
  kin.d = shortened(3e-4, 0.5);
  kin.vn.setZero();
  kin.an.setZero();
  ElemVec r;
  ElemMat k;
  ElementKinematics start = kin;
  start.d = kin.dn;
  ASSERT_TRUE(strut.evaluate(start, StepRule{}, false, r, k).ok);
  const double w0 = strut.strainEnergy();
  ASSERT_TRUE(strut.evaluate(kin, StepRule{}, false, r, k).ok);
  const double w1 = strut.strainEnergy();
  ASSERT_GT(w1, 2 * w0);
  ASSERT_TRUE(strut.evaluate(kin, rule, false, r, k).ok);  // no inertia (ca = 0)
  EXPECT_NEAR(r.dot(kin.d - kin.dn), w1 - w0, 1e-12 * w1);
}

TEST(InfillStrut, MassAndWeightAtItsNodes) {
  InfillStrut strut(strutData(false));
  const ElemMat m = strut.mass();
  EXPECT_DOUBLE_EQ(m(0, 0), 0.7);
  EXPECT_DOUBLE_EQ(m(4, 4), 0.7);
  EXPECT_DOUBLE_EQ(m(2, 2), 0.0);
  const ElemVec g = strut.bodyLoad(Vec2(0, -9.81));
  EXPECT_DOUBLE_EQ(g(1), -0.7 * 9.81);
  EXPECT_DOUBLE_EQ(g(4), -0.7 * 9.81);
  EXPECT_FALSE(strut.holdsRotation(0));
  EXPECT_TRUE(isBrace(strut));
}

// ---------------------------------------------------------------------------
// the mesh command

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

// ---------------------------------------------------------------------------
// the infilled frame pushed sideways

TEST(InfillDeck, PushoverFollowsTheFramePlusStrutClosedForm) {
  testing::DeckTempDir dir;
  DeckOptions o;
  o.outDir = dir.path();
  o.quiet = true;
  const SolutionCommands commands;
  std::ostringstream console;
  const DeckOutcome out = runDeck(std::string(C2D_SOURCE_DIR) + "/decks/infill/infilled_frame.inp",
                                  o, commands, console);
  ASSERT_EQ(out.exitCode, 0) << out.message;
  const testing::Csv wall = testing::readCsv(dir.path() / "infilled_frame_op=0_tplot.csv");
  const testing::Csv bare = testing::readCsv(dir.path() / "infilled_frame_op=1_tplot.csv");
  const std::vector<double> H = wall.column("reac_4_1"), u = wall.column("disp_4_1");
  const std::vector<double> Hb = bare.column("reac_4_1"), ub = bare.column("disp_4_1");
  ASSERT_GT(H.size(), 90u);
  ASSERT_EQ(H.size(), Hb.size());
  // The closed form of the deck's header.
  const double E = 30e6, Ic = std::pow(0.4, 4) / 12, Ib = 0.3 * 0.125 / 12, h = 3, L = 5;
  const double k = (Ib / L) / (Ic / h);
  const double Kf = 24 * E * Ic / (h * h * h) * (6 * k + 1) / (6 * k + 4);
  const double Linf = 4.6, hinf = 2.75, t = 0.2, Em = 2.2e6, fm = 4000;
  const double theta = std::atan2(hinf, Linf), rinf = std::hypot(Linf, hinf);
  const double lambda1 = std::pow(Em * t * std::sin(2 * theta) / (4 * E * Ic * hinf), 0.25);
  const double a = 0.175 * std::pow(lambda1 * h, -0.4) * rinf;
  const double r = std::hypot(L, h), c = L / r;
  const double Ks = Em * a * t / r * c * c;
  const double V = std::min(a * t * fm * c, Linf * t * 0.03 * fm);
  const double up = V / c / (Em * a * t) * r / c;
  EXPECT_NEAR(Hb[0] / ub[0], Kf, 0.03 * Kf);              // the bare frame
  EXPECT_NEAR(H[0] / u[0], Kf + Ks, 0.1 * (Kf + Ks));     // frame plus strut
  // The wall's shear: the difference of the two runs at the same drift.
  std::size_t ip = 0;
  for (std::size_t i = 0; i < H.size(); ++i) {
    ASSERT_DOUBLE_EQ(u[i], ub[i]);
    if (H[i] - Hb[i] > H[ip] - Hb[ip]) ip = i;
  }
  EXPECT_NEAR(H[ip] - Hb[ip], V, 0.05 * V);
  EXPECT_NEAR(u[ip], up, 0.15 * up);
  EXPECT_NEAR(H[ip], V + Kf * up, 0.1 * (V + Kf * up));  // the peak of the strut's branch
  // Past 10 u_p the panel is gone: the bare frame's curve.
  ASSERT_GT(u.back(), 10.5 * up);
  EXPECT_NEAR(H.back(), Hb.back(), 1e-9 * Hb.back());
  std::ifstream log(dir.path() / "infilled_frame.out");
  std::stringstream ss;
  ss << log.rdbuf();
  EXPECT_NE(ss.str().find("infill panel 1 crushed at t ="), std::string::npos);
}

}  // namespace
}  // namespace c2d
