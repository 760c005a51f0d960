// The table of a study of plans (macro/studies/PlanTable): columns, empty cells for
// absent sweep values and debris, CSV quoting of the failure reason.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "macro/studies/PlanTable.h"
#include "tests/unit/DeckTestSupport.h"

namespace c2d {
namespace {

using testing::lines;

TEST(PlanTable, RowsWithAndWithoutDebris) {
  PlanTable t({"tb", "e"});
  DebrisFigures d;
  d.right = 2;
  d.site = Site{0, 10};
  d.xmin = 0;
  d.xmax = 12;
  d.outsideMass = 3;
  t.add({1, "deck_tb=1", {{"tb", 1.0}}, true, "", d, ""});
  t.add({3,
         "deck_tb=2_e=7",
         {{"tb", 2.0}, {"e", 7.0}},
         false,
         "deck.inp:9:3: error: Newton iteration \"diverged\", step 4",
         std::nullopt,
         ""});
  EXPECT_EQ(t.failed(), 1);
  const auto l = lines(t.csv());
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[0], "run,stem,tb,e,status,reason," + debrisCsvHeader());
  EXPECT_EQ(l[1].rfind("1,deck_tb=1,1,,ok,,0.000000e+00,2.000000e+00,", 0), 0u) << l[1];
  EXPECT_NE(l[1].find(",outside,"), std::string::npos) << l[1];
  EXPECT_EQ(l[2].rfind("3,deck_tb=2_e=7,2,7,failed,\"deck.inp:9:3: error: Newton iteration "
                       "\"\"diverged\"\", step 4\",",
                       0),
            0u)
      << l[2];
  // Every row has as many cells as the header (the quoted comma is one cell).
  const auto commas = [](const std::string& s) {
    int n = 0;
    bool quoted = false;
    for (char c : s) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted) ++n;
    }
    return n;
  };
  EXPECT_EQ(commas(l[1]), commas(l[0]));
  EXPECT_EQ(commas(l[2]), commas(l[0]));
}

}  // namespace
}  // namespace c2d
