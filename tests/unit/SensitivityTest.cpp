// The sensitivity of an ensemble's figures to its drawn values
// (macro/studies/Sensitivity): three runs in perfect order mark nothing.
#include <gtest/gtest.h>

#include <string>

#include "macro/studies/EnsembleTable.h"
#include "macro/studies/Sensitivity.h"

namespace c2d {
namespace {

// Three runs in perfect order: rho = 1, but one ordering in three reaches it
// by chance (the exact law), so nothing stands out.
TEST(EnsembleStatistics, SensitivityOfFewRunsMarksNothing) {
  EnsembleData d;
  d.drawn = {"mu"};
  for (int k = 1; k <= 3; ++k) {
    EnsembleRun r;
    r.run = r.sample = k;
    r.plan = 1;
    r.ok = r.debris = true;
    r.drawn = {0.1 * k};
    r.figures["right"] = 1.0 * k;
    d.runs.push_back(r);
  }
  const std::string text = sensitivityText(d);
  EXPECT_NE(text.find("(3 runs"), std::string::npos) << text;
  EXPECT_NE(text.find("(p 0.333)"), std::string::npos) << text;
  EXPECT_EQ(text.find(")*"), std::string::npos) << text;
}

}  // namespace
}  // namespace c2d
