// RIGId (macro/mesh/RigidCommand): the zones reach the elements, the log
// echoes them, the restart fingerprint sees them, and the deck errors at
// file:line:col.
#include <gtest/gtest.h>

#include <sstream>

#include "elements/ElementFactory.h"
#include "elements/LinearFrame.h"
#include "solvers/ModelFingerprint.h"
#include "tests/unit/MeshBuildSupport.h"

namespace c2d {
namespace {

using testing::bindMesh;
using testing::buildMesh;
using testing::expectMeshError;
using testing::kBeamMesh;

TEST(RigidCommand, ZonesReachTheElements) {
  std::ostringstream echo;
  const Model m = buildMesh(kBeamMesh + "RIGId\n 1 0.3 0\n 3 0.1 0.2\n\n", &echo);
  EXPECT_EQ(rigidOffsets(m.element(0)), (std::array<double, 2>{0.3, 0.0}));
  EXPECT_EQ(rigidOffsets(m.element(1)), (std::array<double, 2>{0.0, 0.0}));
  EXPECT_EQ(rigidOffsets(m.element(2)), (std::array<double, 2>{0.1, 0.2}));
  EXPECT_NEAR(dynamic_cast<const LinearFrame&>(m.element(2)).length(), 0.7, 1e-15);
  EXPECT_NE(echo.str().find("Rigid end zones: element 3"), std::string::npos) << echo.str();
  EXPECT_NE(ModelFingerprint::of(m).elements, ModelFingerprint::of(buildMesh(kBeamMesh)).elements);
  // Given before the elements: the same.
  const Model before = buildMesh("RIGId\n 1 0.3 0\n\n" + kBeamMesh);
  EXPECT_EQ(rigidOffsets(before.element(0)), (std::array<double, 2>{0.3, 0.0}));
}

TEST(RigidCommand, Errors) {
  expectMeshError(kBeamMesh + "RIGId\n 1 -0.1 0\n\n", 16, 4,
                  "a rigid end zone must not be negative");
  expectMeshError(kBeamMesh + "RIGId\n 1 0 -2\n\n", 16, 6, "a rigid end zone must not be negative");
  expectMeshError(kBeamMesh + "RIGId\n 2 0.5 0.5\n\n", 16, 4, "leave no flexible length");
  expectMeshError(kBeamMesh + "RIGId\n 4 0.1 0.1\n\n", 16, 2, "element 4 is not defined");
  expectMeshError(kBeamMesh + "RIGId\n 1 0.1 0.1\n 1 0.2 0\n\n", 17, 2,
                  "element 1 has rigid end zones already (line 16)");
  expectMeshError(kBeamMesh + "RIGId\n 1 0.1 0.1 7\n\n", 16, 12, "too many fields");
}

// Members with hinge laws take rigid zones too: their hinges form at the faces
// (the joints made there: elements/JointedElement.h).
TEST(RigidCommand, MembersWithHingeLawsTakeZones) {
  const std::string hinged =
      "COOR\n 1 1 0 0\n 4 0 3 0\n\n"
      "MATErial,1\n FRAMe\n RESUltant STIFfness 1e7 1e7 1e4\n SOFTening LINEar 10 -100\n\n"
      "ELEM\n 1 1 1 1 2\n 3 0 1 3 4\n\n";
  const Model m = buildMesh(hinged + "RIGId\n 1 0.1 0\n 3 0 0.25\n\n");
  EXPECT_EQ(rigidOffsets(m.element(0)), (std::array<double, 2>{0.1, 0.0}));
  EXPECT_EQ(rigidOffsets(m.element(2)), (std::array<double, 2>{0.0, 0.25}));
}

TEST(RigidCommand, RemovedOrEarlierElementsAreRefused) {
  Model model = buildMesh(kBeamMesh);
  model.removeElement(1);
  testing::expectDeckError([&] { bindMesh(model, "RIGId\n 2 0.1 0.1\n\n"); }, "mesh.inp", 4, 2,
                           "element 2 was removed");
  testing::expectDeckError([&] { bindMesh(model, "RIGId\n 3 0.1 0.1\n\n"); }, "mesh.inp", 4, 2,
                           "element 3 was built by an earlier mesh input");
}

}  // namespace
}  // namespace c2d
