// The ensemble picture (macro/studies/EnsemblePicture): the reach beyond the
// footprint on both sides, the zones marked, the legend in a strip below the
// charts; one panel when the debris is contiguous in every run, two when not.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "macro/studies/EnsemblePicture.h"
#include "macro/studies/EnsembleTable.h"
#include "macro/studies/PlanStatistics.h"
#include "tests/unit/EnsembleTestSupport.h"

namespace c2d {
namespace {

using testing::okRun;

// The ensemble picture: u beyond the footprint on both sides, the zones
// marked, the legend in a strip below the charts; one panel when the debris is
// contiguous in every run (the two curves agree), two when it is not.
TEST(SiteZones, EnsemblePictureMarksZonesAndKeepsItsLegendApart) {
  auto debrisRun = [](int plan, int sample, double left, double right,
                      std::vector<std::pair<double, double>> cover) {
    EnsembleRun r = okRun({{"footprint_xmin", 0}, {"footprint_xmax", 10}, {"left", left},
                         {"right", right}, {"site_xmin", -5}, {"site_xmax", 30},
                         {"mass_left", 0}, {"hit_left", 0}, {"mass_wall", 0}, {"hit_wall", 0},
                         {"x1_wall", -9}, {"x2_wall", -7}});
    r.plan = plan;
    r.sample = sample;
    r.cover = std::move(cover);
    return r;
  };
  EnsembleData data;
  data.zones = {"left", "wall"};
  data.runs = {debrisRun(1, 1, 0, 12, {{0, 22}}), debrisRun(1, 2, 1, 14, {{-1, 24}})};
  std::vector<PlanStats> plans = planStatistics(data);
  std::string svg = ensembleSvg(data, plans, "test");
  auto count = [](const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count(svg, "<svg x=\"0\""), 1u);  // contiguous: one panel
  EXPECT_NE(svg.find("beyond the footprint (m)"), std::string::npos);
  EXPECT_NE(svg.find("protected zones&apos; edges"), std::string::npos) << svg;
  EXPECT_NE(svg.find("site edges (protected: left)"), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"legend\""), 1u);  // the strip only, no legend box in a chart
  // The strip starts below the chart (title 34 + 330).
  const std::size_t strip = svg.find("<g class=\"legend\"");
  const std::size_t line = svg.find("<line", strip);
  const std::size_t y1 = svg.find("y1=\"", line);
  EXPECT_GE(std::stod(svg.substr(y1 + 4)), 364.0);
  // A gap in the debris of one run: two panels.
  data.runs[1].cover = {{-1, 12}, {15, 24}};  // a gap beyond the footprint
  plans = planStatistics(data);
  svg = ensembleSvg(data, plans, "test");
  EXPECT_EQ(count(svg, "<svg x=\"0\""), 2u);
}

}  // namespace
}  // namespace c2d
