#include "macro/studies/EnsemblePicture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "macro/output/SvgChart.h"
#include "macro/output/SvgNumber.h"

namespace c2d {

namespace {

constexpr double kWidth = 720, kChartHeight = 330, kTitleHeight = 34;
constexpr double kFont = 12, kRowHeight = 20;  // the legend strip, in the charts' legend font

// Okabe-Ito colors and dashes for the plans (the reference lines have their own).
constexpr std::array<const char*, 6> kColors = {"#0072B2", "#D55E00", "#009E73",
                                                "#CC79A7", "#E69F00", "#000000"};
constexpr std::array<const char*, 4> kDashes = {"none", "7,3", "2,2.5", "9,3,2,3"};

// Vertical lines at each u (one series: the line breaks at NaN).
SvgChart::Points verticals(const std::vector<double>& us) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  SvgChart::Points p;
  for (double u : us) {
    if (!p.empty()) p.emplace_back(nan, nan);
    p.emplace_back(u, 0);
    p.emplace_back(u, 1);
  }
  return p;
}

// The chart's SVG as a nested <svg> placed at y (its XML declaration dropped).
std::string placed(const std::string& svg, double y) {
  std::string s = svg.substr(svg.find("<svg"));
  char at[48];
  std::snprintf(at, sizeof at, "<svg x=\"0\" y=\"%.1f\"", y);
  return at + s.substr(4);
}

struct Entry {
  std::string name;
  SeriesStyle style;
};

// The legend as rows of entries (a line sample and its name) across the width.
std::string legendStrip(const std::vector<Entry>& entries, double y0, double* height) {
  std::string out = "<g class=\"legend\" font-family=\"sans-serif\" font-size=\"12\">\n";
  double x = 16, y = y0 + kRowHeight / 2;
  char buf[512];
  for (const Entry& e : entries) {
    const double w = 30 + 7 + 0.6 * kFont * static_cast<double>(e.name.size()) + 18;
    if (x + w > kWidth - 8 && x > 16) {
      x = 16;
      y += kRowHeight;
    }
    const double sw = e.style.width > 0 ? e.style.width : 1.6;
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" "
                  "stroke-width=\"%.2f\"%s%s%s/>\n<text x=\"%.1f\" y=\"%.1f\">",
                  x, y, x + 30, y, e.style.color.c_str(), sw,
                  e.style.dash == "none" ? "" : " stroke-dasharray=\"",
                  e.style.dash == "none" ? "" : e.style.dash.c_str(),
                  e.style.dash == "none" ? "" : "\"", x + 37, y + 0.36 * kFont);
    out += buf + xmlEscape(e.name) + "</text>\n";
    x += w;
  }
  *height = y - y0 + kRowHeight / 2;
  return out + "</g>\n";
}

// A run's leftmost and rightmost x.
double leftEnd(const EnsembleRun& r) { return r.figure("footprint_xmin") - r.figure("left"); }
double rightEnd(const EnsembleRun& r) { return r.figure("footprint_xmax") + r.figure("right"); }

using RunsByPlan = std::map<int, std::vector<const EnsembleRun*>>;

// Where the picture lies: the footprint, the site, the zones' edges as u and
// the u-range that holds every run's ends and every mark.
struct Frame {
  double fpMin = NAN, fpMax = NAN, siteMin = NAN, siteMax = NAN, ulo = 0, uhi = 0;
  std::vector<double> zoneEdges;
  // u beyond the footprint of a site's x, and the x of a u.
  double beyond(double x) const { return x < fpMin ? x - fpMin : x > fpMax ? x - fpMax : 0.0; }
  double at(double u) const { return u < 0 ? fpMin + u : u > 0 ? fpMax + u : 0.5 * (fpMin + fpMax); }
};

Frame frameOf(const EnsembleData& data, const RunsByPlan& byPlan) {
  Frame f;
  for (const auto& [plan, runs] : byPlan)
    for (const EnsembleRun* r : runs) {
      f.fpMin = r->figure("footprint_xmin");
      f.fpMax = r->figure("footprint_xmax");
      if (r->site != "none") {
        f.siteMin = r->figure("site_xmin");
        f.siteMax = r->figure("site_xmax");
      }
    }
  for (const auto& [plan, runs] : byPlan)
    for (const EnsembleRun* r : runs) {
      f.ulo = std::min(f.ulo, f.beyond(leftEnd(*r)));
      f.uhi = std::max(f.uhi, f.beyond(rightEnd(*r)));
    }
  // The deck's zones (not the sides, which the site's edges mark).
  for (const std::string& z : data.zones)
    for (const char* end : {"x1_", "x2_"})
      for (const EnsembleRun& r : data.runs)
        if (const double x = r.figure(end + z); !std::isnan(x)) {
          f.zoneEdges.push_back(f.beyond(x));
          break;
        }
  std::vector<double> marks = f.zoneEdges;
  if (!std::isnan(f.siteMin)) marks.insert(marks.end(), {f.beyond(f.siteMin), f.beyond(f.siteMax)});
  for (double u : marks) f.ulo = std::min(f.ulo, u), f.uhi = std::max(f.uhi, u);
  const double margin = 0.04 * std::max(f.uhi - f.ulo, 1e-9);
  f.ulo -= margin;
  f.uhi += margin;
  return f;
}

// Per plan with runs (in the plans' order) the two curves; `same`: they agree.
struct Curves {
  std::vector<SvgChart::Points> reach, lies;
  bool same = true;
};

Curves curvesOf(const std::vector<PlanStats>& plans, const RunsByPlan& byPlan, const Frame& f,
                int points) {
  Curves c;
  for (const PlanStats& s : plans) {
    const auto it = byPlan.find(s.plan);
    if (it == byPlan.end()) continue;
    const auto& runs = it->second;
    const double n = static_cast<double>(runs.size());
    SvgChart::Points pr, pl;
    for (int i = 0; i <= points; ++i) {
      const double u = f.ulo + (f.uhi - f.ulo) * i / points, x = f.at(u);
      double past = 0, lies = 0;
      for (const EnsembleRun* r : runs) {
        past += u > 0 ? (rightEnd(*r) > x) : u < 0 ? (leftEnd(*r) < x) : 1;
        lies += std::any_of(r->cover.begin(), r->cover.end(),
                            [x](const auto& cv) { return x >= cv.first && x <= cv.second; });
      }
      pr.emplace_back(u, past / n);
      pl.emplace_back(u, lies / n);
      c.same = c.same && past == lies;
    }
    c.reach.push_back(std::move(pr));
    c.lies.push_back(std::move(pl));
  }
  return c;
}

}  // namespace

std::string ensembleSvg(const EnsembleData& data, const std::vector<PlanStats>& plans,
                        const std::string& title, int points) {
  RunsByPlan byPlan;
  for (const EnsembleRun& r : data.runs)
    if (r.ok && r.debris) byPlan[r.plan].push_back(&r);
  if (byPlan.empty()) return {};
  const Frame f = frameOf(data, byPlan);
  const Curves cv = curvesOf(plans, byPlan, f, points);
  const bool same = cv.same;
  const double fpMin = f.fpMin, fpMax = f.fpMax, siteMin = f.siteMin, siteMax = f.siteMax;
  const double ulo = f.ulo, uhi = f.uhi;
  const std::vector<double>& zoneEdges = f.zoneEdges;
  auto beyond = [&f](double x) { return f.beyond(x); };
  char xlabel[256];
  std::snprintf(xlabel, sizeof xlabel,
                "beyond the footprint (m): left < 0 < right (footprint x = %.4g to %.4g m)",
                onAxis(fpMin, fpMax - fpMin), onAxis(fpMax, fpMax - fpMin));
  std::vector<SvgChart> charts(same ? 1 : 2);
  const char* titles[2] = {same ? "probability that debris lies at and reaches past u"
                                : "probability that the debris reaches past u",
                           "probability that debris lies at u"};
  std::vector<Entry> legend;
  for (std::size_t c = 0; c < charts.size(); ++c) {
    charts[c].setTitle(titles[c]).setXLabel(xlabel).setYLabel("probability")
        .setSize(kWidth, kChartHeight).setXRange(ulo, uhi).setYRange(0, 1).setLegend(false);
    const auto& curves = c == 0 ? cv.reach : cv.lies;
    std::size_t k = 0;
    for (const PlanStats& s : plans) {
      if (!byPlan.count(s.plan)) continue;
      const SeriesStyle style{kColors[k % kColors.size()], kDashes[(k / kColors.size()) % kDashes.size()],
                              false, 0};
      charts[c].addSeries(s.label, curves[k], style);
      if (c == 0) legend.push_back({s.label, style});
      ++k;
    }
  }
  const SeriesStyle footprint{"#999999", "none", false, 1};
  const SeriesStyle site{"#d62728", "6,3", false, 1.5};
  const SeriesStyle zone{"#7b3294", "2,2", false, 1.5};
  std::string protectedSides;
  for (const char* side : {"left", "right"})
    if (std::find(data.zones.begin(), data.zones.end(), side) != data.zones.end())
      protectedSides += std::string(protectedSides.empty() ? "" : " and ") + side;
  for (SvgChart& c : charts) {
    c.addSeries("footprint", verticals({0.0}), footprint);
    if (!std::isnan(siteMin)) c.addSeries("site", verticals({beyond(siteMin), beyond(siteMax)}), site);
    if (!zoneEdges.empty()) c.addSeries("zones", verticals(zoneEdges), zone);
  }
  legend.push_back({"footprint", footprint});
  if (!std::isnan(siteMin))
    legend.push_back({protectedSides.empty() ? "site edges"
                                             : "site edges (protected: " + protectedSides + ")",
                      site});
  if (!zoneEdges.empty()) legend.push_back({"protected zones' edges", zone});

  double legendHeight = 0;
  const double chartsBottom = kTitleHeight + kChartHeight * static_cast<double>(charts.size());
  const std::string strip = legendStrip(legend, chartsBottom, &legendHeight);
  char head[512];
  const double height = chartsBottom + legendHeight + 8;
  std::snprintf(head, sizeof head,
                "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
                "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%.0f\" "
                "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n"
                "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
                kWidth, height, kWidth, height);
  std::string out = head;
  out += svgTitle(title, kWidth / 2, 24, 16, kWidth - 20) + "\n";
  for (std::size_t c = 0; c < charts.size(); ++c)
    out += placed(charts[c].svg(), kTitleHeight + kChartHeight * static_cast<double>(c));
  return out + strip + "</svg>\n";
}

}  // namespace c2d
