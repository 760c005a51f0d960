#include "macro/studies/EnsemblePicture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/output/SvgChart.h"

namespace c2d {

namespace {

constexpr double kWidth = 720, kChartHeight = 330, kTitleHeight = 34;

// Vertical lines at x = a and x = b from 0 to 1 (one series: the line breaks at NaN).
SvgChart::Points verticals(double a, double b) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {{a, 0}, {a, 1}, {nan, nan}, {b, 0}, {b, 1}};
}

// The chart's SVG as a nested <svg> placed at y (its XML declaration dropped).
std::string placed(const std::string& svg, double y) {
  std::string s = svg.substr(svg.find("<svg"));
  char at[48];
  std::snprintf(at, sizeof at, "<svg x=\"0\" y=\"%.1f\"", y);
  return at + s.substr(4);
}

}  // namespace

std::string ensembleSvg(const EnsembleData& data, const std::vector<PlanStats>& plans,
                        const std::string& title, int points) {
  std::map<int, std::vector<const EnsembleRun*>> byPlan;
  double fpMin = NAN, fpMax = NAN, siteMin = NAN, siteMax = NAN;
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo;
  for (const EnsembleRun& r : data.runs) {
    if (!r.ok || !r.debris) continue;
    byPlan[r.plan].push_back(&r);
    fpMin = r.figure("footprint_xmin");
    fpMax = r.figure("footprint_xmax");
    xlo = std::min({xlo, fpMin - r.figure("left"), fpMin});
    xhi = std::max({xhi, fpMax + r.figure("right"), fpMax});
    if (r.site != "none") {
      siteMin = r.figure("site_xmin");
      siteMax = r.figure("site_xmax");
    }
  }
  if (byPlan.empty()) return {};
  if (!std::isnan(siteMin)) {
    xlo = std::min(xlo, siteMin);
    xhi = std::max(xhi, siteMax);
  }
  const double margin = 0.04 * std::max(xhi - xlo, 1e-9);
  xlo -= margin;
  xhi += margin;

  SvgChart reach, lies;
  reach.setTitle("probability that the debris reaches past x")
      .setXLabel("x (m)")
      .setYLabel("probability")
      .setSize(kWidth, kChartHeight)
      .setXRange(xlo, xhi)
      .setYRange(0, 1);
  lies.setTitle("probability that debris lies at x")
      .setXLabel("x (m)")
      .setYLabel("probability")
      .setSize(kWidth, kChartHeight)
      .setXRange(xlo, xhi)
      .setYRange(0, 1);
  for (const PlanStats& s : plans) {
    const auto it = byPlan.find(s.plan);
    if (it == byPlan.end()) continue;
    const auto& runs = it->second;
    const double n = static_cast<double>(runs.size());
    SvgChart::Points pr, pl;
    for (int i = 0; i <= points; ++i) {
      const double x = xlo + (xhi - xlo) * i / points;
      double past = 0, at = 0;
      for (const EnsembleRun* r : runs) {
        const double left = r->figure("footprint_xmin") - r->figure("left");
        const double right = r->figure("footprint_xmax") + r->figure("right");
        past += x >= r->figure("footprint_xmax")   ? (right > x)
                : x <= r->figure("footprint_xmin") ? (left < x)
                                                   : 1;
        at += std::any_of(r->cover.begin(), r->cover.end(),
                          [x](const auto& c) { return x >= c.first && x <= c.second; });
      }
      pr.emplace_back(x, past / n);
      pl.emplace_back(x, at / n);
    }
    reach.addSeries(s.label, pr);
    lies.addSeries(s.label, pl);
  }
  for (SvgChart* c : {&reach, &lies}) {
    c->addSeries("footprint", verticals(fpMin, fpMax), SeriesStyle{"#999999", "none", false, 1});
    if (!std::isnan(siteMin))
      c->addSeries("site", verticals(siteMin, siteMax), SeriesStyle{"#d62728", "6,3", false, 1.5});
  }
  char head[512];
  const double height = kTitleHeight + 2 * kChartHeight;
  std::snprintf(head, sizeof head,
                "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
                "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%.0f\" "
                "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n"
                "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
                kWidth, height, kWidth, height);
  std::string out = head;
  out += svgTitle(title, kWidth / 2, 24, 16, kWidth - 20) + "\n";
  out += placed(reach.svg(), kTitleHeight);
  out += placed(lies.svg(), kTitleHeight + kChartHeight);
  return out + "</svg>\n";
}

}  // namespace c2d
