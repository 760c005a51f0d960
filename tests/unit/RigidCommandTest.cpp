// RIGId (macro/mesh/RigidCommand): the zones reach the elements, the log
// echoes them, the restart fingerprint sees them, and the deck errors at
// file:line:col.
#include <gtest/gtest.h>

#include <sstream>

#include "elements/ElementFactory.h"
#include "elements/LinearFrame.h"
#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/mesh/MeshBinder.h"
#include "solvers/ModelFingerprint.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d {
namespace {

// Lines 3-14: three elements along x (nodes 1-4, 1 m each), then the tested commands from line 15.
const std::string kBeam =
    "COOR\n 1 1 0 0\n 4 0 3 0\n\n"
    "MATErial,1\n FRAMe\n RESUltant STIFfness 1e7 1e7 1e4\n\n"
    "ELEM\n 1 1 1 1 2\n 3 0 1 3 4\n\n";

void apply(Model& model, const std::string& mesh, std::ostream* echo = nullptr) {
  const Deck d = parseDeckText("FEAP * * test\n0 0 0 2 3 2\n" + mesh + "END\nSTOP\n", "mesh.inp");
  const Problem& pr = std::get<Problem>(d.items.at(0));
  Parameters params;
  MeshBinder binder(model, params, echo);
  binder.setControl(pr.control);
  binder.apply(pr.mesh);
  binder.finish(pr.meshEnd.loc, pr.meshEnd.lineText());
}

Model build(const std::string& mesh, std::ostream* echo = nullptr) {
  Model model;
  apply(model, mesh, echo);
  return model;
}

void expectError(const std::string& mesh, int line, int col, const std::string& msg) {
  testing::expectDeckError([&] { build(mesh); }, "mesh.inp", line, col, msg);
}

TEST(RigidCommand, ZonesReachTheElements) {
  std::ostringstream echo;
  const Model m = build(kBeam + "RIGId\n 1 0.3 0\n 3 0.1 0.2\n\n", &echo);
  EXPECT_EQ(rigidOffsets(m.element(0)), (std::array<double, 2>{0.3, 0.0}));
  EXPECT_EQ(rigidOffsets(m.element(1)), (std::array<double, 2>{0.0, 0.0}));
  EXPECT_EQ(rigidOffsets(m.element(2)), (std::array<double, 2>{0.1, 0.2}));
  EXPECT_NEAR(dynamic_cast<const LinearFrame&>(m.element(2)).length(), 0.7, 1e-15);
  EXPECT_NE(echo.str().find("Rigid end zones: element 3"), std::string::npos) << echo.str();
  EXPECT_NE(ModelFingerprint::of(m).elements, ModelFingerprint::of(build(kBeam)).elements);
  // Given before the elements: the same.
  const Model before = build("RIGId\n 1 0.3 0\n\n" + kBeam);
  EXPECT_EQ(rigidOffsets(before.element(0)), (std::array<double, 2>{0.3, 0.0}));
}

TEST(RigidCommand, Errors) {
  expectError(kBeam + "RIGId\n 1 -0.1 0\n\n", 16, 4, "a rigid end zone must not be negative");
  expectError(kBeam + "RIGId\n 1 0 -2\n\n", 16, 6, "a rigid end zone must not be negative");
  expectError(kBeam + "RIGId\n 2 0.5 0.5\n\n", 16, 4, "leave no flexible length");
  expectError(kBeam + "RIGId\n 4 0.1 0.1\n\n", 16, 2, "element 4 is not defined");
  expectError(kBeam + "RIGId\n 1 0.1 0.1\n 1 0.2 0\n\n", 17, 2,
              "element 1 has rigid end zones already (line 16)");
  expectError(kBeam + "RIGId\n 1 0.1 0.1 7\n\n", 16, 12, "too many fields");
}

// Members with hinge laws take rigid zones too: their hinges form at the faces
// (the joints made there: elements/JointedElement.h).
TEST(RigidCommand, MembersWithHingeLawsTakeZones) {
  const std::string hinged =
      "COOR\n 1 1 0 0\n 4 0 3 0\n\n"
      "MATErial,1\n FRAMe\n RESUltant STIFfness 1e7 1e7 1e4\n SOFTening LINEar 10 -100\n\n"
      "ELEM\n 1 1 1 1 2\n 3 0 1 3 4\n\n";
  const Model m = build(hinged + "RIGId\n 1 0.1 0\n 3 0 0.25\n\n");
  EXPECT_EQ(rigidOffsets(m.element(0)), (std::array<double, 2>{0.1, 0.0}));
  EXPECT_EQ(rigidOffsets(m.element(2)), (std::array<double, 2>{0.0, 0.25}));
}

TEST(RigidCommand, RemovedOrEarlierElementsAreRefused) {
  Model model = build(kBeam);
  model.removeElement(1);
  testing::expectDeckError([&] { apply(model, "RIGId\n 2 0.1 0.1\n\n"); }, "mesh.inp", 4, 2,
                           "element 2 was removed");
  testing::expectDeckError([&] { apply(model, "RIGId\n 3 0.1 0.1\n\n"); }, "mesh.inp", 4, 2,
                           "element 3 was built by an earlier mesh input");
}

}  // namespace
}  // namespace c2d
