// The mesh binder: FEAP's generation rules on small meshes (exact coordinates,
// connectivity, codes and loads), edge and coordinate commands, BLOCk,
// material records, joints, contact, gravity, parameters, echo, and errors.
#include <gtest/gtest.h>

#include <sstream>

#include "macro/deck/DeckParser.h"
#include "macro/deck/DeckReader.h"
#include "macro/mesh/MeshBinder.h"
#include "macro/mesh/ParseDeck.h"
#include "materials/RcSection.h"
#include "tests/unit/MeshBuildSupport.h"

namespace c2d {
namespace {

using testing::DeckTempDir;
using testing::expectDeckError;
using testing::meshDeck;

const char* kMaterial =
    "MATErial,1\n FRAMe\n ELAStic ISOTropic 200e6 0.3\n CROSs SECTion 0.01 1e-4\n\n";

// The mesh of a one-problem deck applied to a new model (the mesh may lack elements;
// buildModel, which insists on them, is tested on its own).
Model build(const std::string& mesh, Parameters* params = nullptr, std::ostream* echo = nullptr,
            const std::string& control = "0 0 0 2 3 2") {
  return testing::buildMesh(mesh, echo, control, params);
}

void expectBuildError(const std::string& mesh, int line, int col, const std::string& msg,
                      const std::string& control = "0 0 0 2 3 2") {
  expectDeckError([&] { build(mesh, nullptr, nullptr, control); }, "mesh.inp", line, col, msg);
}

std::array<int, 2> nodesOf(const Model& m, int e) { return m.element(e).nodes(); }

TEST(MeshBinderCoordinates, GenerationInterpolatesLinearly) {
  const Model m = build(std::string("COOR\n 1 1 0 0\n 5 0 4 8\n\n") + kMaterial +
                        "ELEM\n 1 1 1 1 2\n 4 0 1 4 5\n\n");
  ASSERT_EQ(m.numNodes(), 5);
  for (int k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(m.coord(k).x(), k);
    EXPECT_DOUBLE_EQ(m.coord(k).y(), 2.0 * k);
  }
}

TEST(MeshBinderCoordinates, IncrementOnTheEarlierRecord) {
  // 1 -> 6 with increment 2: FEAP steps (|6-1+2|-1)/2 = 3 intervals, nodes 3 and 5.
  Model m = build("COOR\n 1 2 0 0\n 6 0 3 0\n\n");
  ASSERT_EQ(m.numNodes(), 6);
  EXPECT_TRUE(m.hasCoord(2));
  EXPECT_TRUE(m.hasCoord(4));
  EXPECT_FALSE(m.hasCoord(1));
  EXPECT_FALSE(m.hasCoord(3));
  EXPECT_DOUBLE_EQ(m.coord(2).x(), 1.0);
  EXPECT_DOUBLE_EQ(m.coord(4).x(), 2.0);
  EXPECT_DOUBLE_EQ(m.coord(5).x(), 3.0);
}

TEST(MeshBinderCoordinates, DescendingAndChainedGeneration) {
  // 5 -> 1 counts down; then 1 -> 3 is plain (ng = 0 on node 1's record).
  Model m = build("COOR\n 5 1 4 4\n 1 0 0 0\n 7 1 10 0\n 9 0 12 2\n\n");
  EXPECT_DOUBLE_EQ(m.coord(3).x(), 3.0);
  EXPECT_DOUBLE_EQ(m.coord(3).y(), 3.0);
  EXPECT_DOUBLE_EQ(m.coord(1).x(), 1.0);
  EXPECT_FALSE(m.hasCoord(5));  // node 6 is not between 1 and 7 with an increment
  EXPECT_DOUBLE_EQ(m.coord(7).x(), 11.0);
  EXPECT_DOUBLE_EQ(m.coord(7).y(), 1.0);
}

TEST(MeshBinderCoordinates, ExpressionsAndParametersInFields) {
  Parameters p;
  p.set("L", 2.0);
  Model m = build("PARA\n n = 3\n\nCOOR\n 1 n-2 0 0\n n+1 0 n*L L/2\n\n", &p);
  ASSERT_EQ(m.numNodes(), 4);
  EXPECT_DOUBLE_EQ(m.coord(3).x(), 6.0);
  EXPECT_DOUBLE_EQ(m.coord(3).y(), 1.0);
  EXPECT_DOUBLE_EQ(m.coord(1).x(), 2.0);
  EXPECT_DOUBLE_EQ(m.coord(1).y(), 1.0 / 3.0);
  EXPECT_EQ(p.get("n"), 3.0);
}

TEST(MeshBinderElements, GapFilledByCopyingWithIncrement) {
  const Model m = build(std::string("COOR\n 1 1 0 0\n 9 0 8 0\n\n") + kMaterial +
                        "ELEM\n 1 1 1 1 2\n 4 2 1 4 5\n 6 0 1 8 9\n\n");
  ASSERT_EQ(m.numElements(), 6);
  EXPECT_EQ(nodesOf(m, 1), (std::array<int, 2>{1, 2}));  // element 2: nodes 2 3
  EXPECT_EQ(nodesOf(m, 2), (std::array<int, 2>{2, 3}));
  EXPECT_EQ(nodesOf(m, 3), (std::array<int, 2>{3, 4}));  // element 4 as given
  EXPECT_EQ(nodesOf(m, 4), (std::array<int, 2>{5, 6}));  // element 5: 4's nodes + 2
  EXPECT_EQ(nodesOf(m, 5), (std::array<int, 2>{7, 8}));  // the last record generates nothing
  for (int e = 0; e < 6; ++e) EXPECT_EQ(m.element(e).materialNumber(), 1);
}

TEST(MeshBinderElements, ZeroIncrementCountsAsOne) {
  const Model m = build(std::string("COOR\n 1 1 0 0\n 4 0 3 0\n\n") + kMaterial +
                        "ELEM\n 1 0 1 1 2\n 3 0 1 3 4\n\n");
  EXPECT_EQ(nodesOf(m, 1), (std::array<int, 2>{1, 2}));
}

TEST(MeshBinderElements, MaterialsMayComeAfterElements) {
  const Model m =
      build(std::string("COOR\n 1 1 0 0\n 3 0 2 0\n\nELEM\n 1 1 2 1 2\n 2 0 2 2 3\n\n") +
            "MATErial 2\n FRAMe\n RESUltant STIFfness 1e5 4e4 2e3\n\n");
  EXPECT_EQ(m.numElements(), 2);
  EXPECT_EQ(m.element(1).materialNumber(), 2);
}

TEST(MeshBinderElements, Errors) {
  expectBuildError(
      std::string("COOR\n 1 1 0 0\n 3 0 2 0\n\n") + kMaterial + "ELEM\n 2 0 1 1 2\n 1 0 1 2 3\n\n",
      14, 2, "element 1 comes after element 2");
  expectBuildError(std::string("COOR\n 1 1 0 0\n 3 0 2 0\n\n") + "ELEM\n 1 1 7 1 2\n 2 0 7 2 3\n\n",
                   8, 6, "element 1 uses material 7, which is not defined");
  expectBuildError(std::string("COOR\n 1 1 0 0\n 3 0 2 0\n\n") + kMaterial + "ELEM\n 1 0 1 1 4\n\n",
                   13, 10, "uses node 4, which has no coordinates");
  // Generated element 2 needs node 5: reported at the record that generated it.
  expectBuildError(
      std::string("COOR\n 1 1 0 0\n 4 0 3 0\n\n") + kMaterial + "ELEM\n 1 3 1 1 2\n 3 0 1 3 4\n\n",
      13, 10, "element 2 (generated from this record) uses node 5");
  expectBuildError(std::string("COOR\n 1 0 0 0\n 2 0 0 0\n\n") + kMaterial + "ELEM\n 1 0 1 1 2\n\n",
                   13, 8, "zero length");
  expectBuildError(std::string("COOR\n 1 1 0 0\n 3 0 2 0\n\n") + kMaterial +
                       "ELEM\n 1 0 1 1 2\n\nELEM\n 3 0 1 2 3\n\n",
                   18, 1, "element 2 is not defined");
  expectBuildError(std::string("COOR\n 1 1 0 0\n 3 0 2 0\n\n") + kMaterial + "ELEM\n 1 0 1 1 2\n\n",
                   15, 1, "element 2 is not defined (numel = 2)", "0 2 0 2 3 2");
}

TEST(MeshBinderBoundary, NegativeCodesPropagateFeapStyle) {
  Model m = build(std::string("COOR\n 1 1 0 0\n 8 0 7 0\n\n") +
                  "BOUN\n 1 1 -1 0 1\n 4 0 0 0 1\n 6 1 1 0 0\n 8 0 0 0 0\n\n");
  using A = std::array<int, 3>;
  EXPECT_EQ(m.bound(0), (A{-1, 0, 1}));
  EXPECT_EQ(m.bound(1), (A{-1, 0, 0}));  // generated: only the negative code is carried
  EXPECT_EQ(m.bound(2), (A{-1, 0, 0}));
  EXPECT_EQ(m.bound(3), (A{-1, 0, 1}));  // zero code of the next record takes the negative one
  EXPECT_EQ(m.bound(4), (A{0, 0, 0}));
  EXPECT_EQ(m.bound(5), (A{1, 0, 0}));
  EXPECT_EQ(m.bound(6), (A{0, 0, 0}));  // positive codes are not generated
  EXPECT_EQ(m.bound(7), (A{0, 0, 0}));
}

TEST(MeshBinderBoundary, RecordReplacesTheNodeCodes) {
  Model m = build("COOR\n 1 1 0 0\n 3 0 2 0\n\nBOUN\n 2 0 1 1 1\n\nBOUN\n 2 0 0 1 0\n\n");
  EXPECT_EQ(m.bound(1), (std::array<int, 3>{0, 1, 0}));
}

TEST(MeshBinderLoads, ForcesAndDisplacementsInterpolate) {
  Model m = build(
      "COOR\n 1 1 0 0\n 5 0 4 0\n\nFORCe\n 1 1 0 -10 2\n 5 0 0 -50 6\n\n"
      "DISPlacement\n 2 2 0.1 0 0\n 4 0 0.3 0 0\n\n");
  for (int k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(m.force(k)[0], 0.0);
    EXPECT_DOUBLE_EQ(m.force(k)[1], -10.0 * (k + 1));
    EXPECT_DOUBLE_EQ(m.force(k)[2], 2.0 + k);
  }
  EXPECT_DOUBLE_EQ(m.disp(1)[0], 0.1);
  EXPECT_DOUBLE_EQ(m.disp(2)[0], 0.0);  // increment 2 jumps straight to node 4
  EXPECT_DOUBLE_EQ(m.disp(3)[0], 0.3);
}

TEST(MeshBinderLoads, LoadOnANodeWithoutCoordinatesIsAnError) {
  expectBuildError("COOR\n 1 1 0 0\n 3 0 2 0\n\nFORC\n 4 0 1 0 0\n\n", 8, 2,
                   "node 4 has no coordinates");
}

// A portal: columns 1-2-3 (x = 0) and 7-8-9 (x = 4), beam 3-4-5-6-7 (y = 4).
const std::string kPortal =
    std::string("COOR\n 1 1 0 0\n 3 0 0 4\n 4 1 1 4\n 6 0 3 4\n 7 1 4 4\n 9 0 4 0\n\n") +
    kMaterial + "ELEM\n 1 1 1 1 2\n 8 0 1 8 9\n\n";

TEST(MeshBinderEdges, EdgeCommandsSelectByCoordinate) {
  Model m = build(kPortal +
                  "EBOUndary\n 2 0 1 1 1\n\nEFORce\n 2 4 0 -1 0\n\nEFORce\n 2 4 0 -1 0\n\n"
                  "EDISplacement,SET\n 1 4 0.5 0 0\n\n");
  using A = std::array<int, 3>;
  EXPECT_EQ(m.bound(0), (A{1, 1, 1}));
  EXPECT_EQ(m.bound(8), (A{1, 1, 1}));
  EXPECT_EQ(m.bound(1), (A{0, 0, 0}));
  for (int k = 2; k <= 6; ++k) EXPECT_DOUBLE_EQ(m.force(k)[1], -2.0) << k;  // ADD: twice
  EXPECT_DOUBLE_EQ(m.force(1)[1], 0.0);
  for (int k : {6, 7, 8}) EXPECT_DOUBLE_EQ(m.disp(k)[0], 0.5) << k;
  EXPECT_DOUBLE_EQ(m.disp(5)[0], 0.0);
}

TEST(MeshBinderEdges, EdgeCommandsMayComeBeforeCoordinates) {
  Model m = build(std::string("EBOU\n 1 0 1 1 0\n\n") + kPortal);
  EXPECT_EQ(m.bound(0), (std::array<int, 3>{1, 1, 0}));
  EXPECT_EQ(m.bound(2), (std::array<int, 3>{1, 1, 0}));
}

TEST(MeshBinderEdges, EdgeAddKeepsOtherCodes) {
  Model m = build(kPortal + "BOUN\n 1 0 0 0 1\n\nEBOU\n 2 0 1 1 0\n\n");
  EXPECT_EQ(m.bound(0), (std::array<int, 3>{1, 1, 1}));
}

TEST(MeshBinderEdges, NoNodeOnTheEdgeIsAnError) {
  expectBuildError(kPortal + "EBOU\n 1 7.5 1 1 0\n\n", 21, 4,
                   "no node has coordinate 1 equal to 7.5");
}

TEST(MeshBinderEdges, CoordinateCommandsPickTheNearestNode) {
  Model m = build(kPortal +
                  "CBOUndary\n NODE 0.1 -0.2 1 1 1\n NODE 4.2 0.1 0 1 0\n\n"
                  "CFORce\n node 2.1 3.8 0 -5 0\n\nCFOR,ADD\n NODE 2 4 0 -5 0\n\n");
  EXPECT_EQ(m.bound(0), (std::array<int, 3>{1, 1, 1}));
  EXPECT_EQ(m.bound(8), (std::array<int, 3>{0, 1, 0}));
  EXPECT_DOUBLE_EQ(m.force(4)[1], -10.0);
  expectBuildError(kPortal + "CBOU\n 1 0 0 1 1 1\n\n", 21, 2, "expected NODE");
}

TEST(MeshBinderBlock, LineOfTwoNodeElements) {
  Model m = build(std::string(kMaterial) + "BLOCk\n CARTesian 4 0 1 1 1\n 1 0 0\n 2 4 2\n\n");
  ASSERT_EQ(m.numNodes(), 5);
  ASSERT_EQ(m.numElements(), 4);
  for (int k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(m.coord(k).x(), k);
    EXPECT_DOUBLE_EQ(m.coord(k).y(), 0.5 * k);
  }
  for (int e = 0; e < 4; ++e) EXPECT_EQ(nodesOf(m, e), (std::array<int, 2>{e, e + 1}));
}

TEST(MeshBinderBlock, ZerosContinueNumbering) {
  Model m =
      build(std::string(kMaterial) +
            "MATE,2\n FRAM\n RESU STIF 1 1 1\n\n"
            "BLOC\n CART 2 0 1 1 2\n 1 0 0\n 2 0 2\n\nBLOC\n CART 2 0 0 0 0\n 1 0 2\n 2 2 2\n\n");
  ASSERT_EQ(m.numNodes(), 6);
  ASSERT_EQ(m.numElements(), 4);
  EXPECT_EQ(nodesOf(m, 2), (std::array<int, 2>{3, 4}));
  EXPECT_DOUBLE_EQ(m.coord(5).x(), 2.0);
  EXPECT_EQ(m.element(3).materialNumber(), 2);  // mat 0 repeats the previous block's
  expectBuildError(std::string(kMaterial) + "BLOC\n CART 2 0 1 1 1\n 1 0 0\n\n", 10, 2,
                   "needs master nodes 1 and 2");
}

TEST(MeshBinderMaterial, SubRecordsFillTheMaterialSet) {
  const Model m = build(
      "COOR\n 1 0 0 0\n 2 0 1 0\n\nELEM\n 1 0 1 1 2\n 2 0 2 1 2\n\n"
      "MATErial,1 columns of the portal\n FRAMe\n  ELAStic ISOTropic 30e6 0.25\n"
      "  CROSs SECTion 0.12 1.6e-3 9 9 9 0.9 9\n  SHEAr OFF\n  FINIte\n  DENSity,,2.5\n"
      "  MASS LUMPed\n\n"
      "MATE,2\n FRAM\n RESUltant STIFfness 1e6 4e5 2e4\n HARDening BILInear 37.9 268 29400 272\n"
      " SOFTening LINEar 300 -1500\n SMALl\n\n");
  const MaterialSet& a = *m.material(1);
  EXPECT_EQ(a.label, "columns of the portal");
  EXPECT_EQ(a.elementType, "FRAMe");
  EXPECT_EQ(a.E, 30e6);
  EXPECT_EQ(a.nu, 0.25);
  EXPECT_EQ(a.A, 0.12);
  EXPECT_EQ(a.I, 1.6e-3);
  EXPECT_EQ(a.kappa, 0.9);  // FEAPpv: the sixth number
  EXPECT_FALSE(a.shear);
  EXPECT_EQ(a.kinematics, Kinematics::Finite);
  EXPECT_EQ(a.density, 2.5);
  EXPECT_EQ(a.mass, MassType::Lumped);
  EXPECT_FALSE(a.hardening.has_value());
  const MaterialSet& b = *m.material(2);
  EXPECT_EQ(b.EA(), 1e6);
  EXPECT_EQ(b.GA(), 4e5);
  EXPECT_EQ(b.EI(), 2e4);
  EXPECT_TRUE(b.shear);
  EXPECT_EQ(b.mass, MassType::Consistent);
  ASSERT_TRUE(b.hardening.has_value());
  EXPECT_EQ(b.hardening->Mc, 37.9);
  EXPECT_EQ(b.hardening->My, 268.0);
  EXPECT_EQ(b.hardening->Kh1, 29400.0);
  EXPECT_EQ(b.hardening->Kh2, 272.0);
  ASSERT_TRUE(b.softening.has_value());
  EXPECT_EQ(b.softening->Mu, 300.0);
  EXPECT_EQ(b.softening->Ks, -1500.0);
  EXPECT_EQ(b.kinematics, Kinematics::Small);
  EXPECT_EQ(m.element(0).materialNumber(), 1);
}

TEST(MeshBinderMaterial, DefaultShearFactor) {
  const Model m = build(std::string(kMaterial));
  EXPECT_DOUBLE_EQ(m.material(1)->kappa, 5.0 / 6.0);
}

TEST(MeshBinderMaterial, Errors) {
  const std::string head = "MATE,1\n FRAMe\n ELAS ISOT 1e6 0.2\n CROS SECT 1 1\n";
  expectBuildError(head + " SOFTening LINEar 300 1500\n\n", 7, 23, "Ks must be negative");
  expectBuildError(head + " DENSity 2.5\n\n", 7, 10, "DENSity takes two text fields, then numbers");
  expectBuildError(head + " DNSITY,,2\n\n", 7, 2, "unknown material record 'DNSITY'");
  expectBuildError(head + " MASS OFF\n\n", 7, 7, "unknown option 'OFF' of MASS");
  expectBuildError(head + " HARD BILI 1 2 3\n\n", 7, 17, "HARDening needs 4 values");
  expectBuildError(head + " ELAS ORTH 1 2 3\n\n", 7, 7, "only isotropic");
  expectBuildError("MATE,1\n FRAMe\n ELAS ISOT 1e6 0.2\n\n", 3, 1, "has no CROSs record");
  expectBuildError("MATE,1\n ELAS ISOT 1e6 0.2\n\n", 4, 2,
                   "element type record (FRAMe) must come first");
  expectBuildError("MATE,1\n TRUSs\n\n", 4, 2, "unknown element type 'TRUSs'");
  expectBuildError("MATE,1\n FRAMe\n RESU STIF 1 0 1\n\n", 3, 1,
                   "GA = 0 with shear deformation on");
  try {
    build(head + " DNSITY,,2\n\n");
  } catch (const DeckError& e) {
    EXPECT_EQ(e.hint(), "did you mean 'DENSity'?");
  }
}

// SECTion with STIRrups: the shear the links carry sets the shortest piece Lb
// of the member's softening law (materials/RcSection shortestPiece).
TEST(MeshBinderMaterial, SectionStirrupsSetTheShortestPiece) {
  const std::string sect =
      "MATE,1\n FRAMe\n SECTion RECTangular 0.3 0.5 30e3 500e3\n REBAr 0.04 4e-4 0.45 9.42e-4\n";
  std::ostringstream echo;
  const Model m = build(sect + " STIRrups 1e-4 0.2\n\n", nullptr, &echo);
  const MaterialSet& mat = *m.material(1);
  ASSERT_TRUE(mat.rc && mat.softening);
  // The links at the flattest strut, cot theta = 2.5 (materials/ShearResistance).
  EXPECT_NEAR(mat.rc->shearCapacity(0.0, 1), 1e-4 / 0.2 * 0.9 * 0.45 * 500e3 * 2.5, 1e-9);
  EXPECT_GT(mat.softening->pieceLength, 0.5);  // Mu+ / Vu+ = 200 / 253 m
  EXPECT_EQ(mat.softening->pieceLength, mat.rc->shortestPiece());
  EXPECT_NE(echo.str().find("Shortest piece Lb"), std::string::npos);
  // Without links the concrete's VRd,c sets it (longer: the member carries less shear).
  const Model without = build(sect + "\n");
  EXPECT_GT(without.material(1)->softening->pieceLength, mat.softening->pieceLength);
  // Its own yield stress.
  const Model fyw = build(sect + " STIRrups,,1e-4,0.2,250e3\n\n");
  EXPECT_NEAR(fyw.material(1)->rc->shearCapacity(0.0, 1), 0.5 * mat.rc->shearCapacity(0.0, 1),
              1e-9);
  expectBuildError(sect + " STIRrups 1e-4 0\n\n", 7, 16, "spacing s must be positive");
  expectBuildError(sect + " STIRrups 1e-4\n\n", 7, 15, "STIRrups needs Asw and s");
  expectBuildError(sect + " STIRrups 1e-4 0.2 5e5 9\n\n", 7, 24, "too many values");
  expectBuildError(sect + " STIRrups 1e-4 0.2\n STIRrups 1e-4 0.2\n\n", 8, 2, "given twice");
  expectBuildError("MATE,1\n FRAMe\n ELAS ISOT 1e6 0.2\n CROS SECT 1 1\n STIRrups 1e-4 0.2\n\n", 7,
                   2, "STIRrups without SECTion");
}

TEST(MeshBinderJoints, CoincidentNodes) {
  Model m = build(std::string("COOR\n 1 0 0 0\n 2 0 1 0\n 3 0 1 0\n 4 0 2 0\n\n") + kMaterial +
                  "ELEM\n 1 0 1 1 2\n 2 0 1 3 4\n\nJOINt\n 2 3\n\n");
  ASSERT_EQ(m.joints().size(), 1u);
  EXPECT_EQ(m.joints()[0].master, 1);
  EXPECT_EQ(m.joints()[0].slave, 2);
  expectBuildError(std::string("COOR\n 1 0 0 0\n 2 0 1 0\n 3 0 1.5 0\n 4 0 2 0\n\n") + kMaterial +
                       "ELEM\n 1 0 1 1 2\n 2 0 1 3 4\n\nJOINt\n 2 3\n\n",
                   19, 4, "joint nodes 2 and 3 are not coincident");
}

TEST(MeshBinderContact, GroundGravityAndPrint) {
  std::ostringstream echo;
  Model m = build(kPortal +
                      "CONTact\n GROUnd,,-0.5,1e7\n\nGRAVity,,0,-9.81\nNOPRint\n"
                      "FORC\n 5 0 0 -77 0\n\nPRINt\nBOUN\n 1 0 1 1 1\n\n",
                  nullptr, &echo);
  ASSERT_TRUE(m.ground().has_value());
  EXPECT_EQ(m.ground()->y0, -0.5);
  EXPECT_EQ(m.ground()->k, 1e7);
  EXPECT_EQ(m.ground()->zeta, 0.0);
  EXPECT_EQ(m.gravity().y(), -9.81);
  EXPECT_EQ(m.force(4)[1], -77.0);
  const std::string s = echo.str();
  EXPECT_NE(s.find("N o d a l   C o o r d i n a t e s"), std::string::npos);
  EXPECT_NE(s.find("M a t e r i a l   S e t   1"), std::string::npos);
  EXPECT_NE(s.find("N o d a l   B. C."), std::string::npos);
  EXPECT_EQ(s.find("N o d a l   F o r c e s"), std::string::npos);  // under NOPRint
  Model a = build(kPortal + "CONT\n GROU,,0,1e5,0.25\n\n");
  EXPECT_EQ(a.ground()->zeta, 0.25);
  expectBuildError(kPortal + "CONT\n GROU,,0,-1\n\n", 21, 10,
                   "penalty stiffness k must be positive");
  expectBuildError(kPortal + "CONT\n WALL,,0,1\n\n", 21, 2, "unknown contact type 'WALL'");
  expectBuildError(kPortal + "GRAV,0,-9.81\n", 20, 6, "GRAVity takes no option word");
  expectBuildError(kPortal + "GRAV,DOWN,0,-9.81\n", 20, 6, "GRAVity takes no option word");
  expectBuildError(kPortal + "CONT\n GROU,Y,0,1e5\n\n", 21, 7, "GROUnd takes no option word");
  expectBuildError(kPortal + "CONT\n GROU,,0,1e5\n MEMB,X,1e5\n\n", 22, 7,
                   "MEMBers takes no option word");
}

TEST(MeshBinderControl, LimitsAndChecks) {
  Model m = build(
      std::string("COOR\n 1 1 0 0\n 3 0 2 0\n\n") + kMaterial + "ELEM\n 1 1 1 1 2\n 2 0 1 2 3\n\n",
      nullptr, nullptr, "5 2 1 2 3 2");
  EXPECT_EQ(m.numNodes(), 5);  // numnp sizes the model
  EXPECT_FALSE(m.hasCoord(4));
  expectBuildError("COOR\n 1 1 0 0\n 4 0 2 0\n\n", 5, 2, "node 4 is beyond numnp = 3",
                   "3 0 0 2 3 2");
  expectBuildError(std::string(kMaterial) + "ELEM\n 3 0 1 1 2\n\n", 9, 2,
                   "element 3 is beyond numel = 2", "0 2 0 2 3 2");
  expectBuildError("MATE,2\n FRAM\n\n", 3, 6, "material 2 is beyond nummat = 1", "0 0 1 2 3 2");
  expectBuildError("", 2, 7, "ndm must be 2", "0 0 0 3 3 2");
  expectBuildError("", 2, 9, "ndf must be 3", "0 0 0 2 6 2");
  expectBuildError("", 2, 11, "nen must be 2", "0 0 0 2 3 3");
  expectBuildError("", 2, 1, "numnp must not be negative", "-1 0 0 2 3 2");
}

TEST(MeshBinderControl, BuildModelNeedsElements) {
  const Deck empty = parseDeckText(meshDeck("COOR\n 1 0 0 0\n\n"), "empty.inp");
  Parameters p;
  expectDeckError([&] { buildModel(std::get<Problem>(empty.items[0]), p, nullptr); }, "empty.inp",
                  6, 1, "the mesh has no elements");
  const Deck ok = parseDeckText(meshDeck(kPortal), "ok.inp");
  std::ostringstream echo;
  const Model m = buildModel(std::get<Problem>(ok.items[0]), p, &echo);
  EXPECT_EQ(m.numElements(), 8);
  EXPECT_EQ(m.numNodes(), 9);
  EXPECT_NE(echo.str().find("Number of nodal points      = counted"), std::string::npos);
}

TEST(MeshBinderErrors, UndefinedParameterAndDivisionByZeroAtTheirColumns) {
  expectBuildError("COOR\n 1 0 0 0\n 2 0 L 0\n\n", 5, 6, "undefined parameter 'l'");
  expectBuildError("PARA\n z = 0\n\nCOOR\n 1 0 0 0\n 2 0 1/z 0\n\n", 8, 7, "division by zero");
  expectBuildError("COOR\n 1 0 0 0\n 2.5 0 1 0\n\n", 5, 2, "node number must be a whole number");
  expectBuildError("COOR\n 1 0 0 0\n 1 0 1 0\n\n", 5, 2, "node 1 is given on two records in a row");
  expectBuildError("COOR\n 1 0 0 0 7\n\n", 4, 10, "too many fields");
}

TEST(MeshBinderReentry, ApplyMeshChangesAnExistingModel) {
  Parameters p;
  Model m = build(kPortal, &p);
  const int version = m.topologyVersion();
  const Deck more = parseDeckText(meshDeck("PARA\n f = -3\n\nFORC\n 5 0 0 f 0\n\n"), "more.inp");
  const auto& items = std::get<Problem>(more.items[0]).mesh;
  applyMesh(items, p, m, nullptr);
  EXPECT_EQ(m.force(4)[1], -3.0);
  EXPECT_EQ(p.get("f"), -3.0);
  EXPECT_EQ(m.topologyVersion(), version);  // loads only: same dofs
  EXPECT_EQ(m.numElements(), 8);
  // MESH re-entry data: mesh records alone, END optional.
  const auto bc =
      parseMeshRecords(DeckReader::readString("BOUN\n 9 0 1 1 0\n\nEND\n", "re.inp"), "re.inp");
  applyMesh(bc, p, m, nullptr);
  EXPECT_EQ(m.bound(8), (std::array<int, 3>{1, 1, 0}));
  EXPECT_GT(m.topologyVersion(), version);
  const auto mat = parseMeshRecords(
      DeckReader::readString("MATE,1\n FRAM\n RESU STIF 1 2 3\n\nELEM\n 9 0 1 9 1\n\n", "re.inp"),
      "re.inp");
  applyMesh(mat, p, m, nullptr);
  EXPECT_EQ(m.numElements(), 9);
  EXPECT_EQ(m.material(1)->EI(), 3.0);
  EXPECT_EQ(nodesOf(m, 8), (std::array<int, 2>{8, 0}));
  expectDeckError(
      [] {
        parseMeshRecords(DeckReader::readString("FORC\n 1 0 1 0 0\nEND\n", "re.inp"), "re.inp");
      },
      "re.inp", 3, 1, "not ended by a blank record");
  expectDeckError(
      [] { parseMeshRecords(DeckReader::readString("END\nFORC\n", "re.inp"), "re.inp"); }, "re.inp",
      2, 1, "record after the END");
}

TEST(MeshBinderErrors, DeckFileWithIncludedMesh) {
  DeckTempDir dir;
  const std::string main =
      dir.write("frame.inp", "FEAP * * x\n0 0 0 2 3 2\nINCLude mesh.inc\nEND\nSTOP\n");
  const std::string inc =
      dir.write("mesh.inc", std::string(kMaterial) +
                                "COOR\n 1 1 0 0\n 3 0 2 0\n\nELEM\n 1 1 9 1 2\n 2 0 9 2 3\n\n");
  const Deck d = parseDeck(main);
  Parameters p;
  expectDeckError([&] { buildModel(std::get<Problem>(d.items[0]), p, nullptr); }, inc, 11, 6,
                  "uses material 9");
}

}  // namespace
}  // namespace c2d
