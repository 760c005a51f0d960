// The study tables read back what they write: a subnormal value swept or
// drawn, swept values that differ in their seventh digit or beyond (written
// with the digits that read back to the same double, as the drawn ones). The
// number cells alone: CsvTest.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "macro/studies/Csv.h"
#include "macro/studies/EnsembleTable.h"
#include "macro/draws/Sweep.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/RunDeckSupport.h"

namespace c2d {
namespace {

TEST(StudyTables, SweptValuesAreWrittenToReadBackExactly) {
  for (double v : {0.1234567, 0.1234568, 1e16, 1e16 + 2, 1e-308, 0.1 + 2 * 0.1, 3.0}) {
    const std::string text = exactSweepValue(v);
    EXPECT_EQ(numberCell(text), v) << text;
  }
  EXPECT_NE(exactSweepValue(0.1234567), exactSweepValue(0.1234568));
  EXPECT_NE(exactSweepValue(1e16), exactSweepValue(1e16 + 2));
  EXPECT_EQ(exactSweepValue(-0.0), "0");
  EXPECT_EQ(exactSweepValue(0.3), "0.3");
}

using testing::readText;

// A study whose swept and drawn values are subnormal or close in the seventh
// digit runs to its end and writes its plans, its table reading back.
TEST(StudyTables, AStudyOfSubnormalAndCloseValuesReadsItsOwnTable) {
  testing::DeckTempDir dir;
  const std::string deck = R"(ENSEmble,,2,1
  eps = NORMal 0 1e-310

SWEEp
  a = 1e-308 0.1234567 0.1234568

FEAP * * a cantilever under a load a + eps
  0 0 0 2 3 2

COORdinates
  1 0 0 0
  2 0 1 0

ELEMents
  1 0 1 1 2

MATErial,1
  FRAMe
    RESUltant STIFfness 1e6 1e6 1e3

BOUNdary
  1 0 1 1 1

FORCe
  2 0 0 a+eps 0

END
BATCh
  TANG,,1
END

STOP
)";
  const auto r = testing::runDeckText(dir, "tiny.inp", deck);
  ASSERT_EQ(r.outcome.exitCode, 0) << r.outcome.message << r.console;
  const std::string table = readText(r.out / "tiny_ensemble.csv");
  EXPECT_NE(table.find(",1e-308,"), std::string::npos) << table;
  EXPECT_NE(table.find(",0.1234567,"), std::string::npos) << table;
  EXPECT_NE(table.find(",0.1234568,"), std::string::npos) << table;
  const EnsembleData d = readEnsembleTable(table, 1);
  ASSERT_EQ(d.runs.size(), 6u);
  EXPECT_EQ(d.runs[0].swept[0], 1e-308);
  EXPECT_TRUE(std::filesystem::exists(r.out / "tiny_plans.csv"));
}

}  // namespace
}  // namespace c2d
