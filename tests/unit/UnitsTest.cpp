// --help gives the unit of every field of every command in the decks' system
// (macro/mesh/Units): a command or field added without its unit fails here.
#include <gtest/gtest.h>

#include <sstream>

#include "macro/Help.h"
#include "macro/mesh/MeshCommands.h"
#include "macro/deck/SolutionCommand.h"
#include "macro/deck/StudyBlocks.h"
#include "macro/mesh/Units.h"

namespace c2d {
namespace {

void expectUnits(const CommandRegistry& r) {
  for (const CommandSpec& s : r.specs()) {
    for (const FieldSpec& f : s.fields)
      EXPECT_TRUE(units::ofField(s.section, s.key(), f.name).has_value())
          << r.title() << ": " << s.name << " field '" << f.name << "' has no unit";
    if (s.data != DataForm::None) {
      EXPECT_FALSE(units::ofDataRecords(s.section, s.key()).empty())
          << r.title() << ": " << s.name << "'s data records have no units";
    }
  }
}

TEST(Units, EveryFieldOfEveryCommandHasItsUnit) {
  CommandRegistry mesh("mesh"), sub("sub"), blocks("blocks");
  registerMeshCommands(mesh);
  registerMaterialSubRecords(sub);
  registerDeckBlocks(blocks);
  const SolutionCommands solution;
  for (const CommandRegistry* r :
       {static_cast<const CommandRegistry*>(&mesh), static_cast<const CommandRegistry*>(&sub),
        static_cast<const CommandRegistry*>(&blocks), &solution.registry()})
    expectUnits(*r);
}

TEST(Units, HelpShowsThemAndExplainsTheSystem) {
  const SolutionCommands solution;
  std::ostringstream os;
  ASSERT_TRUE(printCommandHelp(os, solution, "SECTion"));
  EXPECT_NE(os.str().find("fc: concrete compressive strength [kN/m^2]"), std::string::npos) << os.str();
  std::ostringstream g;
  ASSERT_TRUE(printCommandHelp(g, solution, "GRAVity"));
  EXPECT_NE(g.str().find("[m/s^2]"), std::string::npos) << g.str();
  std::ostringstream q;
  ASSERT_TRUE(printCommandHelp(q, solution, "QLOAd"));
  EXPECT_NE(q.str().find("qx, qy [kN/m]"), std::string::npos) << q.str();
  std::ostringstream u;
  ASSERT_TRUE(printCommandHelp(u, solution, "UNITs"));
  EXPECT_NE(u.str().find("t/mm^3"), std::string::npos) << u.str();
  EXPECT_NE(u.str().find("Es = 200e6"), std::string::npos);
}

}  // namespace
}  // namespace c2d
