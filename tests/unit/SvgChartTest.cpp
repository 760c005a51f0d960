// SvgChart: tick arithmetic, a well-formed standalone SVG, one path per series,
// the data-to-pixel mapping, automatic ranges, styles that differ in grayscale,
// and a legend that keeps off the curves.
#include "macro/output/SvgChart.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <vector>

#include "tests/unit/OutputTestSupport.h"

namespace c2d {
namespace {

using testing::XmlNode;
using testing::XmlReader;

// Vertices of an SVG path made of absolute M/L commands.
std::vector<std::vector<std::pair<double, double>>> pathPieces(const std::string& d) {
  std::vector<std::vector<std::pair<double, double>>> pieces;
  std::istringstream in(d);
  char cmd;
  double x, y;
  while (in >> cmd >> x >> y) {
    if (cmd == 'M') pieces.emplace_back();
    EXPECT_TRUE(cmd == 'M' || cmd == 'L') << cmd;
    pieces.back().emplace_back(x, y);
  }
  return pieces;
}

bool isNiceStep(double step) {
  const double p = std::pow(10.0, std::floor(std::log10(step) + 1e-12));
  const double m = step / p;
  return std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 5) < 1e-9;
}

TEST(SvgChartTicks, NiceNumbers) {
  EXPECT_DOUBLE_EQ(SvgChart::niceNumber(0.23, true), 0.2);
  EXPECT_DOUBLE_EQ(SvgChart::niceNumber(0.37, true), 0.5);
  EXPECT_DOUBLE_EQ(SvgChart::niceNumber(7.5, true), 10);
  EXPECT_DOUBLE_EQ(SvgChart::niceNumber(1.2e-3, true), 1e-3);
  EXPECT_DOUBLE_EQ(SvgChart::niceNumber(0.23, false), 0.5);
  EXPECT_DOUBLE_EQ(SvgChart::niceNumber(2.0, false), 2.0);
  EXPECT_DOUBLE_EQ(SvgChart::niceNumber(2.0001, false), 5.0);
  EXPECT_DOUBLE_EQ(SvgChart::niceNumber(6.0, false), 10.0);
  EXPECT_THROW(SvgChart::niceNumber(0, true), std::invalid_argument);
}

TEST(SvgChartTicks, UnitIntervalInFifths) {
  const auto t = SvgChart::niceTicks(0, 1, 6);
  ASSERT_EQ(t.size(), 6u);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(t[k], 0.2 * k, 1e-12);
  EXPECT_EQ(t[0], 0.0);  // exactly zero, so that the label reads "0"
}

TEST(SvgChartTicks, OneTwoFiveStepsInsideAnyRange) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> mag(-6, 6), frac(-1, 1);
  for (int trial = 0; trial < 500; ++trial) {
    const double scale = std::pow(10.0, mag(gen));
    double lo = frac(gen) * scale, hi = frac(gen) * scale;
    if (lo > hi) std::swap(lo, hi);
    if (!(hi - lo > 1e-6 * scale)) continue;
    const int maxTicks = 6 + trial % 5;
    const auto t = SvgChart::niceTicks(lo, hi, maxTicks);
    const double step = SvgChart::tickStep(lo, hi, maxTicks);
    ASSERT_TRUE(isNiceStep(step)) << step;
    ASSERT_GE(t.size(), 2u) << lo << " " << hi;
    ASSERT_LE(static_cast<int>(t.size()), maxTicks);
    EXPECT_GE(t.front(), lo - 1e-9 * step);
    EXPECT_LE(t.back(), hi + 1e-9 * step);
    EXPECT_GT(t.front() - step, lo - 1e-9 * step - step);  // no tick missing below
    EXPECT_LT(t.front() - step, lo);
    EXPECT_GT(t.back() + step, hi);
    for (std::size_t k = 0; k < t.size(); ++k) {
      EXPECT_NEAR(std::remainder(t[k], step), 0.0, 1e-9 * step);
      if (k > 0) {
        EXPECT_NEAR(t[k] - t[k - 1], step, 1e-9 * step);
      }
    }
  }
}

TEST(SvgChart, WellFormedStandaloneSvgWithOnePathPerSeries) {
  SvgChart c;
  c.setTitle("Load <vs> displacement & more").setXLabel("u (m)").setYLabel("P (kN)");
  for (int s = 0; s < 3; ++s) {
    SvgChart::Points p;
    for (int i = 0; i <= 50; ++i) p.emplace_back(0.01 * i, (s + 1) * std::sin(0.06 * i));
    c.addSeries("ks = -" + std::to_string(393 * (s + 1)), p, SeriesStyle{"", "", s == 1, 0});
  }
  const std::string text = c.svg();
  const XmlNode root = XmlReader::parse(text);
  EXPECT_EQ(root.name, "svg");
  EXPECT_EQ(root.attr("version"), "1.1");
  EXPECT_EQ(root.attr("xmlns"), "http://www.w3.org/2000/svg");
  EXPECT_EQ(root.attr("viewBox"), "0 0 640 440");
  EXPECT_EQ(root.attr("font-family"), "sans-serif");
  EXPECT_EQ(root.all("path", "series").size(), 3u);
  EXPECT_EQ(root.all("path", "markers").size(), 1u);
  // Title (escaped in the file, decoded by the reader), labels and legend text.
  bool title = false, xl = false, yl = false;
  std::vector<std::string> texts;
  for (const XmlNode* t : root.all("text")) {
    texts.push_back(t->text);
    title = title || (t->attr("class") == "title" && t->text == "Load <vs> displacement & more");
    xl = xl || (t->attr("class") == "xlabel" && t->text == "u (m)");
    yl = yl || (t->attr("class") == "ylabel" && t->text == "P (kN)");
  }
  EXPECT_TRUE(title && xl && yl);
  const auto legend = root.all("g", "legend");
  ASSERT_EQ(legend.size(), 1u);
  std::vector<std::string> names;
  for (const XmlNode* t : legend[0]->all("text")) names.push_back(t->text);
  EXPECT_EQ(names, (std::vector<std::string>{"ks = -393", "ks = -786", "ks = -1179"}));
  EXPECT_NE(text.find("&lt;vs&gt; displacement &amp; more"), std::string::npos);
}

TEST(SvgChart, SeriesDifferInDashAsWellAsColor) {
  SvgChart c;
  for (int s = 0; s < 6; ++s) c.addSeries(std::string(1, static_cast<char>('a' + s)), {{0, 0}, {1, 1.0 + s}});
  const XmlNode root = XmlReader::parse(c.svg());
  std::set<std::string> dashes, colors;
  for (const XmlNode* p : root.all("path", "series")) {
    dashes.insert(p->has("stroke-dasharray") ? p->attr("stroke-dasharray") : "solid");
    colors.insert(p->attr("stroke"));
  }
  EXPECT_EQ(dashes.size(), 6u);  // readable in grayscale
  EXPECT_EQ(colors.size(), 6u);
}

TEST(SvgChart, FixedRangesMapDataOntoThePlotFrame) {
  SvgChart c;
  c.setXRange(0, 10).setYRange(-5, 5);
  c.addSeries("", {{0, -5}, {5, 0}, {10, 5}});
  const XmlNode root = XmlReader::parse(c.svg());
  const auto frame = root.all("rect", "frame");
  ASSERT_EQ(frame.size(), 1u);
  const double x = std::stod(frame[0]->attr("x")), y = std::stod(frame[0]->attr("y"));
  const double w = std::stod(frame[0]->attr("width")), h = std::stod(frame[0]->attr("height"));
  const auto series = root.all("path", "series");
  ASSERT_EQ(series.size(), 1u);
  const auto pieces = pathPieces(series[0]->attr("d"));
  ASSERT_EQ(pieces.size(), 1u);
  ASSERT_EQ(pieces[0].size(), 3u);
  EXPECT_NEAR(pieces[0][0].first, x, 0.01);  // (0, -5): bottom left
  EXPECT_NEAR(pieces[0][0].second, y + h, 0.01);
  EXPECT_NEAR(pieces[0][1].first, x + w / 2, 0.01);  // (5, 0): centre
  EXPECT_NEAR(pieces[0][1].second, y + h / 2, 0.01);
  EXPECT_NEAR(pieces[0][2].first, x + w, 0.01);  // (10, 5): top right
  EXPECT_NEAR(pieces[0][2].second, y, 0.01);
  // y = 0 inside the range: a zero line; no legend for a nameless series.
  EXPECT_EQ(root.all("line", "zero").size(), 1u);
  EXPECT_TRUE(root.all("g", "legend").empty());
  EXPECT_THROW(c.setXRange(1, 1), std::invalid_argument);
}

TEST(SvgChart, AutomaticRangesHaveMarginsAndKeepZero) {
  SvgChart c;
  c.addSeries("a", {{0, -1}, {1, 3}, {2, 0.5}});
  const auto [xlo, xhi] = c.xRange();
  const auto [ylo, yhi] = c.yRange();
  EXPECT_EQ(xlo, 0.0);  // data starts at exactly 0: the axis does too
  EXPECT_DOUBLE_EQ(xhi, 2.08);
  EXPECT_DOUBLE_EQ(ylo, -1.16);
  EXPECT_DOUBLE_EQ(yhi, 3.16);
  // Every tick label lies inside the drawn range.
  const XmlNode root = XmlReader::parse(c.svg());
  const auto labels = root.all("g", "tick-labels");
  ASSERT_EQ(labels.size(), 1u);
  int count = 0;
  for (const XmlNode* t : labels[0]->all("text")) {
    std::string s = t->text;
    if (s.rfind("\xE2\x88\x92", 0) == 0) s = "-" + s.substr(3);  // U+2212
    const double v = std::stod(s);
    if (t->attr("text-anchor") == "middle") {
      EXPECT_GE(v, xlo);
      EXPECT_LE(v, xhi);
    } else {
      EXPECT_GE(v, ylo);
      EXPECT_LE(v, yhi);
    }
    ++count;
  }
  EXPECT_GE(count, 6);
  // A constant series still gets a usable range.
  SvgChart flat;
  flat.addSeries("", {{0, 2}, {1, 2}});
  EXPECT_LT(flat.yRange().first, 2.0);
  EXPECT_GT(flat.yRange().second, 2.0);
}

TEST(SvgChart, TypographicMinusAndCommonExponent) {
  SvgChart c;
  c.addSeries("F", {{0, -2.0e4}, {1, 3.0e4}});
  const XmlNode root = XmlReader::parse(c.svg());
  bool minus = false, exponent = false, asciiMinus = false;
  for (const XmlNode* t : root.all("g", "tick-labels")[0]->all("text")) {
    minus = minus || t->text.rfind("\xE2\x88\x92", 0) == 0;
    asciiMinus = asciiMinus || t->text.find('-') != std::string::npos;
    exponent = exponent || t->text == "×10⁴";
    EXPECT_LE(t->text.size(), 8u) << t->text;  // "−2" rather than "-20000"
  }
  EXPECT_TRUE(minus);
  EXPECT_FALSE(asciiMinus);
  EXPECT_TRUE(exponent);
}

TEST(SvgChart, NonFiniteValueBreaksTheLine) {
  SvgChart c;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  c.addSeries("broken", {{0, 0}, {1, 1}, {2, nan}, {3, 1}, {4, 0}});
  const XmlNode root = XmlReader::parse(c.svg());
  const auto pieces = pathPieces(root.all("path", "series")[0]->attr("d"));
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].size(), 2u);
  EXPECT_EQ(pieces[1].size(), 2u);
}

TEST(SvgChart, LegendKeepsOffTheCurve) {
  // A rising diagonal occupies the bottom-left and top-right corners.
  SvgChart c;
  SvgChart::Points p;
  for (int i = 0; i <= 100; ++i) p.emplace_back(i, i);
  c.addSeries("rising diagonal", p);
  const XmlNode root = XmlReader::parse(c.svg());
  const XmlNode* box = root.all("g", "legend")[0]->all("rect")[0];
  const double x0 = std::stod(box->attr("x")), y0 = std::stod(box->attr("y"));
  const double x1 = x0 + std::stod(box->attr("width")), y1 = y0 + std::stod(box->attr("height"));
  const auto pieces = pathPieces(root.all("path", "series")[0]->attr("d"));
  for (const auto& [x, y] : pieces[0]) EXPECT_FALSE(x >= x0 && x <= x1 && y >= y0 && y <= y1) << x << " " << y;
}

TEST(SvgChart, SpansAndSaveAgree) {
  testing::DeckTempDir dir;
  const std::vector<double> x = {0, 1, 2}, y = {0, 1, 4};
  SvgChart c;
  EXPECT_EQ(c.addSeries("squares", x, y), 0);
  EXPECT_THROW(c.addSeries("bad", x, std::vector<double>{1.0}), std::invalid_argument);
  c.save(dir / "chart.svg");
  EXPECT_EQ(testing::readText(dir / "chart.svg"), c.svg());
}

// The drawn width of a title: its textLength, or the estimate of the font
// (0.56 font size per character, as the writer estimates it).
double titleWidth(const XmlNode& t) {
  if (t.has("textLength")) return std::stod(t.attr("textLength"));
  return 0.56 * std::stod(t.attr("font-size")) * static_cast<double>(t.text.size());
}

TEST(SvgChart, LongTitleFitsInThePicture) {
  const std::string title(200, 'W');
  SvgChart chart;
  chart.setTitle(title).addSeries("a", {{0, 0}, {1, 1}});
  const XmlNode root = XmlReader::parse(chart.svg());
  const auto t = root.all("text", "title");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0]->text, title);
  const double x = std::stod(t[0]->attr("x")), w = titleWidth(*t[0]);
  const double width = std::stod(root.attr("width"));
  EXPECT_GE(x - 0.5 * w, 0.0);
  EXPECT_LE(x + 0.5 * w, width);
  // A short title keeps its font.
  SvgChart small;
  small.setTitle("short").addSeries("a", {{0, 0}, {1, 1}});
  const XmlNode r2 = XmlReader::parse(small.svg());
  EXPECT_EQ(r2.all("text", "title")[0]->attr("font-size"), "15");
  EXPECT_FALSE(r2.all("text", "title")[0]->has("textLength"));
}

TEST(SvgTitle, ShrinksThenSqueezes) {
  // 40 characters at 15 px: 336 px. In 300 px: a smaller font, no squeezing.
  const XmlNode a = XmlReader::parse(svgTitle(std::string(40, 'x'), 150, 20, 15, 300));
  EXPECT_LT(std::stod(a.attr("font-size")), 15);
  EXPECT_FALSE(a.has("textLength"));
  EXPECT_LE(titleWidth(a), 300 + 1e-9);
  // 200 characters in 300 px: the smallest font (9 px) and squeezed to 300 px.
  const XmlNode b = XmlReader::parse(svgTitle(std::string(200, 'x'), 150, 20, 15, 300));
  EXPECT_EQ(b.attr("font-size"), "9");
  EXPECT_EQ(b.attr("textLength"), "300");
  EXPECT_EQ(b.attr("lengthAdjust"), "spacingAndGlyphs");
}

}  // namespace
}  // namespace c2d
