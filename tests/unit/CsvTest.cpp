// The study tables' number cells (macro/studies/Csv): subnormals read as
// written, what is not finite refused.
#include <gtest/gtest.h>

#include "macro/studies/Csv.h"

namespace c2d {
namespace {

TEST(StudyTables, NumberCellsReadSubnormalsAndRefuseWhatIsNotFinite) {
  EXPECT_EQ(numberCell("1e-310"), 1e-310);
  EXPECT_EQ(numberCell("-4.9406564584124654e-324"), -4.9406564584124654e-324);
  EXPECT_EQ(numberCell("1e-400"), 0.0);  // below the least subnormal: zero, as written
  for (const char* bad : {"inf", "-inf", "nan", "1e309", "-1e400x", "", " 1"})
    EXPECT_FALSE(numberCell(bad)) << bad;
}

}  // namespace
}  // namespace c2d
