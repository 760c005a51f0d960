// MATErial's records that belong to no law (macro/mesh/MaterialCommand): the
// contact radius RADIus in place of the section's half depth.
#include <gtest/gtest.h>

#include <sstream>

#include "core/contact/ContactSearch.h"
#include "tests/unit/MeshBuildSupport.h"

namespace c2d {
namespace {

// A wall in the plane: 0.4 x 4.5 m, whose contact radius would be 2.25 m.
std::string wall(const std::string& extra) {
  return "MATErial,1 wall\n FRAMe\n ELAStic ISOTropic 30e6 0.2\n"
         " CROSs SECTion 0.4*4.5 0.4*4.5^3/12\n" +
         extra + "\n";
}

TEST(MaterialCommand, RadiusReplacesTheSectionsHalfDepthAsTheContactRadius) {
  const Model bare = testing::buildMesh(testing::cantilever(wall("")));
  EXPECT_NEAR(sectionRadius(bare, 0), 2.25, 1e-12);
  std::ostringstream echo;
  const Model given = testing::buildMesh(testing::cantilever(wall(" RADIus,,0.9\n")), &echo);
  EXPECT_NEAR(sectionRadius(given, 0), 0.9, 1e-15);
  EXPECT_NEAR(given.material(1)->A, 1.8, 1e-12);  // the section itself is kept
  EXPECT_NE(echo.str().find("Contact radius"), std::string::npos);
}

TEST(MaterialCommand, RadiusMustBePositive) {
  // Lines: COOR 1-4, MATErial 5, FRAMe 6, ELAStic 7, CROSs 8, RADIus 9.
  testing::expectMeshError(testing::cantilever(wall(" RADIus,,0\n")), 9 + 2, 10,
                           "the contact radius must be positive");
  testing::expectMeshError(testing::cantilever(wall(" RADIus,WALL,1\n")), 9 + 2, 9,
                           "RADIus takes no option");
}

}  // namespace
}  // namespace c2d
