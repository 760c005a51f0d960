// A log line repeated for the same reason: the first few written, the rest
// counted with the number of cases they were about.
#include <gtest/gtest.h>

#include "macro/run/LogFolding.h"

namespace c2d {
namespace {

TEST(LogFolding, WritesTheFirstCasesAndCountsTheRest) {
  LogFolding fold(3);
  // 10 lines about joint 5, 4 about joint 9, 2 of another reason.
  int written = 0;
  for (int k = 0; k < 10; ++k) written += fold.admit("joint held", "element 5 node 7");
  for (int k = 0; k < 4; ++k) written += fold.admit("joint held", "element 9 node 2");
  for (int k = 0; k < 2; ++k) written += fold.admit("other", "x");
  EXPECT_EQ(written, 3 + 2);
  EXPECT_EQ(fold.summary(),
            "  joint held: 14 lines (2 cases), the first 3 written above, the other 11 left out\n");
}

TEST(LogFolding, NothingLeftOutSaysNothing) {
  LogFolding fold(3);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(fold.admit("joint held", "a"));
  EXPECT_EQ(fold.summary(), "");
}

}  // namespace
}  // namespace c2d
