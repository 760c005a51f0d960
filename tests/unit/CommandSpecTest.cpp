// The command registry (macro/deck/CommandSpec): unique four-character keys and
// aliases, the nearest command suggested, every mesh command and material
// record documented in the generated help.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include "macro/deck/CommandSpec.h"
#include "macro/mesh/MeshCommands.h"

namespace c2d {
namespace {

CommandSpec spec(const std::string& name) {
  CommandSpec s;
  s.name = name;
  s.doc = "doc";
  return s;
}

TEST(CommandSpecRegistry, FourCharacterKeysAreUnique) {
  CommandRegistry r("test");
  r.add(spec("COORdinates"));
  EXPECT_THROW(r.add(spec("COORx")), std::logic_error);
  EXPECT_THROW(r.add(spec("coordinate")), std::logic_error);
  CommandSpec alias = spec("PARAmeter");
  alias.aliases = {"CONStant"};
  r.add(alias);
  EXPECT_THROW(r.add(spec("CONSistent")), std::logic_error);
  r.add(spec("END"));
  r.add(spec("ENDS"));  // 'end' and 'ends' differ
  EXPECT_EQ(r.find("coor")->name, "COORdinates");
  EXPECT_EQ(r.find("Coordinates")->name, "COORdinates");
  EXPECT_EQ(r.find("cons")->name, "PARAmeter");
  EXPECT_EQ(r.find("end")->name, "END");
  EXPECT_EQ(r.find("endsxx")->name, "ENDS");
  EXPECT_EQ(r.find("coo"), nullptr);
  EXPECT_EQ(r.find("xyz"), nullptr);
}

TEST(CommandSpecRegistry, SuggestsTheNearestCommand) {
  CommandRegistry r;
  registerMeshCommands(r);
  EXPECT_EQ(r.suggest("CORDinates"), "did you mean 'COORdinates'?");
  EXPECT_EQ(r.suggest("bundary"), "did you mean 'BOUNdary'?");
  EXPECT_EQ(r.suggest("ELMENTS"), "did you mean 'ELEMents'?");
  EXPECT_EQ(r.suggest("matrial"), "did you mean 'MATErial'?");
  EXPECT_EQ(r.suggest("xyzzy"), "");
}

TEST(CommandSpecRegistry, EveryMeshCommandIsDocumented) {
  CommandRegistry mesh("Mesh commands"), sub("Material records");
  ASSERT_NO_THROW(registerMeshCommands(mesh));
  ASSERT_NO_THROW(registerMaterialSubRecords(sub));
  for (const char* name :
       {"COOR", "ELEM", "MATE", "BOUN", "FORC", "DISP", "EBOU", "EFOR", "EDIS", "CBOU", "CFOR",
        "CDIS", "BLOC", "PRIN", "NOPR", "JOIN", "CONT", "GRAV", "END",  "PARA", "CONS", "INCL"})
    EXPECT_NE(mesh.find(name), nullptr) << name;
  for (const char* name :
       {"FRAM", "ELAS", "CROS", "SHEA", "SMAL", "FINI", "DENS", "MASS", "RESU", "HARD", "SOFT"})
    EXPECT_NE(sub.find(name), nullptr) << name;
  for (const auto* reg : {&mesh, &sub})
    for (const auto& s : reg->specs()) {
      EXPECT_FALSE(s.doc.empty()) << s.name;
      if (s.data == DataForm::Records) {
        EXPECT_FALSE(s.dataSyntax.empty()) << s.name;
      }
    }
  std::ostringstream help;
  mesh.printHelp(help);
  EXPECT_NE(help.str().find("COORdinates"), std::string::npos);
  EXPECT_NE(help.str().find("node ng x y"), std::string::npos);
  EXPECT_NE(help.str().find("(also CONStant)"), std::string::npos);
}

}  // namespace
}  // namespace c2d
