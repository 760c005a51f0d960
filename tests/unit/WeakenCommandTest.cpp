// The mesh command WEAKen (macro/commands/WeakenCommand): a weakened member
// keeps its rigid ends, an infill strut keeps the share of its law (the
// panel's other strut its own), and the records' errors.
#include <gtest/gtest.h>

#include <string>

#include "elements/ElementFactory.h"
#include "elements/InfillStrut.h"
#include "tests/unit/MeshBuildSupport.h"

namespace c2d {
namespace {

using testing::cantilever;
using testing::kHand;

TEST(WeakenCommand, AWeakenedMemberKeepsItsRigidEnds) {
  const std::string beam =
      "COOR\n 1 1 0 0\n 3 0 4 0\n\n"
      "MATE,1\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.12 1.6e-3\n\n"
      "ELEM\n 1 1 1 1 2\n 2 1 1 2 3\n\n"
      "RIGId\n 1 0.3 0\n\n";
  const Model m = testing::buildMesh(beam + "WEAKen\n 0.5 1\n\n");
  const auto offsets = rigidOffsets(m.element(0));
  EXPECT_EQ(offsets[0], 0.3);
  EXPECT_EQ(offsets[1], 0.0);
}

TEST(WeakenCommand, InfillStrutKeepsTheShareOfItsLaw) {
  const std::string frame =
      "COOR\n 1 0 0 0\n 2 0 5 0\n 3 0 5 3\n 4 0 0 3\n\n"
      "ELEM\n 1 1 1 1 4\n 2 1 1 2 3\n 3 1 2 4 3\n\n"
      "MATE,1\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.16 2.133333333333e-3\n\n"
      "MATE,2\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n CROSs SECTion 0.15 3.125e-3\n\n"
      "INFIll,,0.2,4000\n 1 2 3 4\n\n";
  const Model a = testing::buildMesh(frame);
  const Model b = testing::buildMesh(frame + "WEAKen\n 0.3 5\n\n");
  const auto& sa = dynamic_cast<const InfillStrut&>(a.element(4));
  const auto& sb = dynamic_cast<const InfillStrut&>(b.element(4));
  EXPECT_NEAR(sb.data().law.stiffness(), 0.3 * sa.data().law.stiffness(), 1e-9);
  EXPECT_NEAR(sb.data().law.strength(), 0.3 * sa.data().law.strength(), 1e-12);
  // The panel's other strut (element 4) keeps its law.
  EXPECT_EQ(dynamic_cast<const InfillStrut&>(b.element(3)).data().law.strength(),
            dynamic_cast<const InfillStrut&>(a.element(3)).data().law.strength());
}

TEST(WeakenCommand, Errors) {
  const std::string c = cantilever(kHand);
  const int l = 20;  // the first record after the cantilever's mesh
  testing::expectMeshError(c + "WEAKen\n 0 1\n\n", l + 1, 2, "share kept must lie in (0, 1]");
  testing::expectMeshError(c + "WEAKen\n 1.5 1\n\n", l + 1, 2, "share kept must lie in (0, 1]");
  testing::expectMeshError(c + "WEAKen\n 0.5 4\n\n", l + 1, 6, "element 4 is not defined");
  testing::expectMeshError(c + "WEAKen\n 0.5 1 5\n\n", l + 1, 8, "element 4 is not defined");
  testing::expectMeshError(c + "WEAKen\n 0.5 1 3\n 0.7 2\n\n", l + 2, 6, "already weakened");
  testing::expectMeshError(c + "WEAKen\n 0.5 3 1\n\n", l + 1, 8, "comes before the first");
  testing::expectMeshError(c + "WEAKen\n\n", l, 1, "needs data records");
  testing::expectMeshError(c + "WEAKen\n 0.5 1 2 1 9\n\n", l + 1, 12, "too many fields");
}

}  // namespace
}  // namespace c2d
