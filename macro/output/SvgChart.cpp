#include "macro/output/SvgChart.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "macro/output/SvgNumber.h"
#include "core/io/AtomicFile.h"

namespace c2d {

namespace {

// Okabe-Ito colors, ordered so that neighbours also differ in gray value.
constexpr std::array<const char*, 7> kPalette = {"#000000", "#0072B2", "#D55E00", "#009E73",
                                                 "#CC79A7", "#E69F00", "#56B4E9"};
// Dash cycle of a different length than the palette: a sweep of up to 42 curves
// never repeats a (color, dash) pair.
constexpr std::array<const char*, 6> kDashes = {"none", "7,3", "2,2.5", "9,3,2,3", "13,4", "5,2,1.5,2,1.5,2"};

constexpr double kFontTick = 12, kFontLabel = 14, kFontTitle = 15, kFontLegend = 12;
constexpr double kLineWidth = 1.6;
constexpr double kMarkerSpacing = 30;  // px along the curve between markers
constexpr double kMarkerSize = 3.5;

// Pixel numbers with two decimals, trailing zeros dropped: compact and exact enough.

// Code points of UTF-8 text: the width estimate counts characters, not bytes.
int textLength(std::string_view s) {
  int n = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++n;
  return n;
}

// A sans-serif glyph is on average a bit over half the font size wide.
double textWidth(std::string_view s, double fontSize) { return 0.56 * fontSize * textLength(s); }

std::string superscript(int k) {
  static const std::array<const char*, 10> digits = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string s = k < 0 ? "⁻" : "";
  for (char c : std::to_string(std::abs(k))) s += digits[c - '0'];
  return s;
}

struct TickLabels {
  std::vector<std::string> text;
  int exponent = 0;  // labels are value / 10^exponent
};

TickLabels formatTicks(const std::vector<double>& ticks, double step) {
  TickLabels out;
  double biggest = 0;
  for (double t : ticks) biggest = std::max(biggest, std::abs(t));
  if (biggest >= 1e4 || (biggest > 0 && biggest < 1e-2))
    out.exponent = static_cast<int>(std::floor(std::log10(biggest) + 1e-9));
  const double scale = std::pow(10.0, -out.exponent);
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step * scale) + 1e-9)));
  for (double t : ticks) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(t) < 1e-9 * step ? 0.0 : t * scale);
    std::string s(buf);
    if (s[0] == '-') s = "\xE2\x88\x92" + s.substr(1);  // U+2212 minus: the typographic sign
    out.text.push_back(s);
  }
  return out;
}

void markerPath(std::ostringstream& d, int shape, double x, double y) {
  const double r = kMarkerSize;
  switch (shape % 6) {
    case 0:
      d << "M" << px(x - r) << ' ' << px(y) << "a" << px(r) << ' ' << px(r) << " 0 1 0 " << px(2 * r)
        << " 0a" << px(r) << ' ' << px(r) << " 0 1 0 " << px(-2 * r) << " 0Z";
      break;
    case 1:
      d << "M" << px(x - r) << ' ' << px(y - r) << "h" << px(2 * r) << "v" << px(2 * r) << "h"
        << px(-2 * r) << "Z";
      break;
    case 2:
      d << "M" << px(x) << ' ' << px(y - 1.25 * r) << "L" << px(x + 1.15 * r) << ' ' << px(y + 0.75 * r)
        << "L" << px(x - 1.15 * r) << ' ' << px(y + 0.75 * r) << "Z";
      break;
    case 3:
      d << "M" << px(x) << ' ' << px(y - 1.3 * r) << "L" << px(x + 1.3 * r) << ' ' << px(y) << "L"
        << px(x) << ' ' << px(y + 1.3 * r) << "L" << px(x - 1.3 * r) << ' ' << px(y) << "Z";
      break;
    case 4:
      d << "M" << px(x) << ' ' << px(y + 1.25 * r) << "L" << px(x + 1.15 * r) << ' ' << px(y - 0.75 * r)
        << "L" << px(x - 1.15 * r) << ' ' << px(y - 0.75 * r) << "Z";
      break;
    default:
      d << "M" << px(x - r) << ' ' << px(y - r) << "L" << px(x + r) << ' ' << px(y + r) << "M"
        << px(x - r) << ' ' << px(y + r) << "L" << px(x + r) << ' ' << px(y - r);
      break;
  }
}

struct Rect {
  double x0, y0, x1, y1;
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

}  // namespace

namespace {

// The font size and squeeze (textLength, 0: none) that keep text within maxWidth.
std::pair<double, double> fittedFont(std::string_view text, double fontSize, double maxWidth) {
  const double natural = textWidth(text, fontSize);
  if (maxWidth <= 0 || natural <= maxWidth) return {fontSize, 0.0};
  const double font = std::max(0.6 * fontSize, fontSize * maxWidth / natural);
  return {font, textWidth(text, font) > maxWidth * (1 + 1e-9) ? maxWidth : 0.0};
}

std::string fitAttributes(double font, double squeeze) {
  std::string o = " font-size=\"" + px(font) + "\"";
  if (squeeze > 0) o += " textLength=\"" + px(squeeze) + "\" lengthAdjust=\"spacingAndGlyphs\"";
  return o;
}

}  // namespace

std::string svgFittedText(std::string_view text, double cx, double y, double fontSize, double maxWidth,
                          std::string_view attributes) {
  const auto [font, squeeze] = fittedFont(text, fontSize, maxWidth);
  return "<text " + std::string(attributes) + " x=\"" + px(cx) + "\" y=\"" + px(y) + "\"" +
         fitAttributes(font, squeeze) + " text-anchor=\"middle\">" + xmlEscape(text) + "</text>\n";
}

std::string svgTitle(std::string_view title, double cx, double y, double fontSize, double maxWidth) {
  return svgFittedText(title, cx, y, fontSize, maxWidth, "class=\"title\"");
}

std::string xmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

SvgChart& SvgChart::setTitle(std::string title) {
  title_ = std::move(title);
  return *this;
}
SvgChart& SvgChart::setXLabel(std::string label) {
  xLabel_ = std::move(label);
  return *this;
}
SvgChart& SvgChart::setYLabel(std::string label) {
  yLabel_ = std::move(label);
  return *this;
}
SvgChart& SvgChart::setSize(double width, double height) {
  if (!(width >= 200 && height >= 150)) throw std::invalid_argument("SvgChart: size below 200 x 150 px");
  width_ = width;
  height_ = height;
  return *this;
}
SvgChart& SvgChart::setXRange(double lo, double hi) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument("SvgChart: x range needs lo < hi");
  xFixed_ = {lo, hi};
  return *this;
}
SvgChart& SvgChart::setYRange(double lo, double hi) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument("SvgChart: y range needs lo < hi");
  yFixed_ = {lo, hi};
  return *this;
}
SvgChart& SvgChart::setLegend(bool show) {
  legend_ = show;
  return *this;
}

int SvgChart::addSeries(std::string name, Points points, SeriesStyle style) {
  series_.push_back({std::move(name), std::move(points), std::move(style)});
  return numSeries() - 1;
}

int SvgChart::addSeries(std::string name, std::span<const double> x, std::span<const double> y,
                        SeriesStyle style) {
  if (x.size() != y.size()) throw std::invalid_argument("SvgChart: series '" + name + "' has x and y of different lengths");
  Points p(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) p[i] = {x[i], y[i]};
  return addSeries(std::move(name), std::move(p), std::move(style));
}

double SvgChart::niceNumber(double x, bool round) {
  if (!(x > 0) || !std::isfinite(x)) throw std::invalid_argument("niceNumber: needs a finite x > 0");
  const double e = std::floor(std::log10(x));
  const double p = std::pow(10.0, e);
  const double f = x / p;
  double nice;
  if (round)
    nice = f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10;
  else
    nice = f <= 1 + 1e-9 ? 1 : f <= 2 + 1e-9 ? 2 : f <= 5 + 1e-9 ? 5 : 10;
  return nice * p;
}

double SvgChart::tickStep(double lo, double hi, int maxTicks) {
  // The smallest nice step at or above span/(maxTicks-1) keeps the count within maxTicks.
  return niceNumber((hi - lo) / std::max(1, maxTicks - 1), false);
}

std::vector<double> SvgChart::niceTicks(double lo, double hi, int maxTicks) {
  if (!(hi > lo)) throw std::invalid_argument("niceTicks: needs lo < hi");
  const double step = tickStep(lo, hi, maxTicks);
  const double k0 = std::ceil(lo / step - 1e-9), k1 = std::floor(hi / step + 1e-9);
  std::vector<double> ticks;
  for (double k = k0; k <= k1; k += 1) ticks.push_back(k == 0 ? 0.0 : k * step);
  return ticks;
}

std::pair<double, double> SvgChart::autoRange(bool xAxis) const {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Series& s : series_)
    for (const auto& [x, y] : s.points) {
      const double v = xAxis ? x : y;
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  if (!(lo <= hi)) return {0, 1};
  if (hi == lo) {
    const double pad = lo == 0 ? 1 : 0.1 * std::abs(lo);
    return {lo - pad, hi + pad};
  }
  const double margin = 0.04 * (hi - lo);
  return {lo == 0 ? 0 : lo - margin, hi == 0 ? 0 : hi + margin};
}

std::pair<double, double> SvgChart::xRange() const { return xFixed_ ? *xFixed_ : autoRange(true); }
std::pair<double, double> SvgChart::yRange() const { return yFixed_ ? *yFixed_ : autoRange(false); }

namespace {

// What the page shows besides the curves: its size, title and axis labels.
struct ChartPage {
  double width, height;
  const std::string& title;
  const std::string& xLabel;
  const std::string& yLabel;
};

// One series as the drawing reads it.
struct Curve {
  const std::string& name;
  const SvgChart::Points& points;
  const SeriesStyle& style;
};

// A curve's color, dash and width: its style's, else the palette's, the dash
// cycle's and the default width by its index.
struct CurveLook {
  std::string color, dash;
  double width;
};

CurveLook lookOf(const Curve& c, int i) {
  return {c.style.color.empty() ? kPalette[i % kPalette.size()] : c.style.color,
          c.style.dash.empty() ? kDashes[i % kDashes.size()] : c.style.dash,
          c.style.width > 0 ? c.style.width : kLineWidth};
}

// The plot's place on the page (left, top, right, bottom), its ticks and their
// labels, and the ranges it maps.
struct Frame {
  double xlo = 0, xhi = 1, ylo = 0, yhi = 1;
  double L = 0, T = 0, R = 0, B = 0;
  std::vector<double> xTicks, yTicks;
  TickLabels xLab, yLab;
  double X(double x) const { return L + (x - xlo) / (xhi - xlo) * (R - L); }
  double Y(double y) const { return T + (yhi - y) / (yhi - ylo) * (B - T); }
};

// rightExtra: room kept right of the plot for a legend outside it.
Frame layoutFrame(const ChartPage& page, std::pair<double, double> xr,
                  std::pair<double, double> yr, double rightExtra) {
  Frame f;
  f.xlo = xr.first;
  f.xhi = xr.second;
  f.ylo = yr.first;
  f.yhi = yr.second;
  // Vertical layout first: the y tick labels it yields set the left margin.
  f.T = page.title.empty() ? 20 : 44;
  f.B = page.height - (5 + 6 + kFontTick + (page.xLabel.empty() ? 12 : 12 + kFontLabel + 10));
  const int maxYTicks = std::max(3, static_cast<int>((f.B - f.T) / 45));
  f.yTicks = SvgChart::niceTicks(f.ylo, f.yhi, maxYTicks);
  f.yLab = formatTicks(f.yTicks, SvgChart::tickStep(f.ylo, f.yhi, maxYTicks));
  double yLabW = 0;
  for (const auto& s : f.yLab.text) yLabW = std::max(yLabW, textWidth(s, kFontTick));
  f.L = 10 + (page.yLabel.empty() ? 0 : kFontLabel + 10) + yLabW + 8;
  f.R = page.width - 22 - rightExtra;
  // Fewer x ticks until their labels leave room between them.
  for (int maxXTicks = std::max(3, static_cast<int>((f.R - f.L) / 70));; --maxXTicks) {
    f.xTicks = SvgChart::niceTicks(f.xlo, f.xhi, maxXTicks);
    f.xLab = formatTicks(f.xTicks, SvgChart::tickStep(f.xlo, f.xhi, maxXTicks));
    double w = 0;
    for (const auto& s : f.xLab.text) w = std::max(w, textWidth(s, kFontTick));
    if (maxXTicks <= 3 || (w + 14) * static_cast<double>(f.xTicks.size()) <= f.R - f.L) break;
  }
  return f;
}

// Pixel polylines of a series (a non-finite point starts a new piece).
using Polyline = std::vector<std::pair<double, double>>;
std::vector<Polyline> polylines(const Frame& f, const SvgChart::Points& points) {
  std::vector<Polyline> pieces(1);
  for (const auto& [x, y] : points) {
    if (!std::isfinite(x) || !std::isfinite(y)) {
      if (!pieces.back().empty()) pieces.emplace_back();
      continue;
    }
    pieces.back().emplace_back(f.X(x), f.Y(y));
  }
  if (pieces.back().empty()) pieces.pop_back();
  return pieces;
}

// Curve samples about every 3 px inside the plot: what a legend box would hide.
std::vector<std::pair<double, double>> curveSamples(const Frame& f,
                                                    const std::vector<Curve>& curves) {
  std::vector<std::pair<double, double>> samples;
  const Rect plot{f.L, f.T, f.R, f.B};
  for (const Curve& c : curves)
    for (const Polyline& p : polylines(f, c.points))
      for (std::size_t k = 0; k < p.size(); ++k) {
        if (k == 0) {
          samples.push_back(p[0]);
          continue;
        }
        const auto [ax, ay] = p[k - 1];
        const auto [bx, by] = p[k];
        const int pieces = std::clamp(static_cast<int>(std::hypot(bx - ax, by - ay) / 3), 1, 2000);
        for (int j = 1; j <= pieces; ++j) {
          const double sx = ax + (bx - ax) * j / pieces, sy = ay + (by - ay) * j / pieces;
          if (plot.contains(sx, sy)) samples.emplace_back(sx, sy);
        }
      }
  return samples;
}

// The legend's box: its size, its text's width and its place.
struct Legend {
  static constexpr double kPad = 8, kRowH = 18, kSample = 32;
  bool show = false;
  double textW = 0, boxW = 0, boxH = 0;
  Rect box{};
};

// A legend entry is never wider than the plot leaves it: a longer one is set
// smaller, then squeezed (as a title is).
Legend legendSize(const Frame& f, const std::vector<Curve>& curves, bool show) {
  Legend g;
  g.show = show;
  const double legTextMax = std::max(40.0, f.R - f.L - 16 - 2 * Legend::kPad - Legend::kSample - 7);
  for (const Curve& c : curves) g.textW = std::max(g.textW, textWidth(c.name, kFontLegend));
  g.textW = std::min(g.textW, legTextMax);
  g.boxW = Legend::kPad + Legend::kSample + 7 + g.textW + Legend::kPad;
  g.boxH = 2 * 5 + static_cast<int>(curves.size()) * Legend::kRowH;
  return g;
}

// The legend inside, where it hides no curve (corners first), else outside on
// the right while the plot keeps most of the width (f laid out again for it).
void placeLegend(Legend& g, Frame& f, const ChartPage& page, const std::vector<Curve>& curves) {
  const double boxW = g.boxW, boxH = g.boxH;
  const double inset = 8;
  const double xl = f.L + inset, xr = f.R - inset - boxW, xc = 0.5 * (f.L + f.R - boxW);
  const double yt = f.T + inset, yb = f.B - inset - boxH, ym = 0.5 * (f.T + f.B - boxH);
  const std::array<std::pair<double, double>, 8> spots = {
      {{xr, yt}, {xl, yt}, {xr, yb}, {xl, yb}, {xc, yt}, {xc, yb}, {xr, ym}, {xl, ym}}};
  const auto samples = curveSamples(f, curves);
  std::size_t bestCount = std::numeric_limits<std::size_t>::max();
  for (const auto& [x0, y0] : spots) {
    const Rect grown{x0 - 4, y0 - 4, x0 + boxW + 4, y0 + boxH + 4};
    const auto count = static_cast<std::size_t>(std::count_if(
        samples.begin(), samples.end(), [&](const auto& p) { return grown.contains(p.first, p.second); }));
    if (count < bestCount) {
      bestCount = count;
      g.box = {x0, y0, x0 + boxW, y0 + boxH};
    }
  }
  if (bestCount > 0 && boxW + 12 < 0.35 * (f.R - f.L)) {
    f = layoutFrame(page, {f.xlo, f.xhi}, {f.ylo, f.yhi}, boxW + 12);
    g.box = {f.R + 12, f.T, f.R + 12 + boxW, f.T + boxH};
  }
}

// The document's head: size, title, the plot's clip path, the white page.
void writeHead(std::ostringstream& o, const ChartPage& page, const Frame& f) {
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << px(page.width) << "\" height=\""
    << px(page.height) << "\" viewBox=\"0 0 " << px(page.width) << ' ' << px(page.height)
    << "\" font-family=\"sans-serif\" font-size=\"" << px(kFontTick) << "\">\n";
  if (!page.title.empty()) o << "<title>" << xmlEscape(page.title) << "</title>\n";
  o << "<defs><clipPath id=\"plot-area\"><rect x=\"" << px(f.L) << "\" y=\"" << px(f.T) << "\" width=\""
    << px(f.R - f.L) << "\" height=\"" << px(f.B - f.T) << "\"/></clipPath></defs>\n";
  o << "<rect width=\"" << px(page.width) << "\" height=\"" << px(page.height) << "\" fill=\"white\"/>\n";
}

// Grid at the ticks, light enough to stay behind the curves; zero lines: a
// force-time curve crossing zero reads better against them.
void writeGrid(std::ostringstream& o, const Frame& f) {
  const double L = f.L, T = f.T, R = f.R, B = f.B;
  o << "<g class=\"grid\" stroke=\"#dcdcdc\" stroke-width=\"0.7\">\n";
  for (double t : f.xTicks)
    if (std::abs(f.X(t) - L) > 0.5 && std::abs(f.X(t) - R) > 0.5)
      o << "<line x1=\"" << px(f.X(t)) << "\" y1=\"" << px(T) << "\" x2=\"" << px(f.X(t)) << "\" y2=\"" << px(B)
        << "\"/>\n";
  for (double t : f.yTicks)
    if (std::abs(f.Y(t) - T) > 0.5 && std::abs(f.Y(t) - B) > 0.5)
      o << "<line x1=\"" << px(L) << "\" y1=\"" << px(f.Y(t)) << "\" x2=\"" << px(R) << "\" y2=\"" << px(f.Y(t))
        << "\"/>\n";
  o << "</g>\n";
  if (f.ylo < 0 && f.yhi > 0)
    o << "<line class=\"zero\" x1=\"" << px(L) << "\" y1=\"" << px(f.Y(0)) << "\" x2=\"" << px(R) << "\" y2=\""
      << px(f.Y(0)) << "\" stroke=\"#808080\" stroke-width=\"0.8\"/>\n";
  if (f.xlo < 0 && f.xhi > 0)
    o << "<line class=\"zero\" x1=\"" << px(f.X(0)) << "\" y1=\"" << px(T) << "\" x2=\"" << px(f.X(0)) << "\" y2=\""
      << px(B) << "\" stroke=\"#808080\" stroke-width=\"0.8\"/>\n";
}

// The curves, clipped to the plot, with their markers evenly spaced along the
// drawn curve, staggered between series so that coincident curves still show
// every marker shape.
void writeCurves(std::ostringstream& o, const Frame& f, const std::vector<Curve>& curves) {
  const int n = static_cast<int>(curves.size());
  const Rect plot{f.L - 1, f.T - 1, f.R + 1, f.B + 1};
  o << "<g clip-path=\"url(#plot-area)\" fill=\"none\" stroke-linejoin=\"round\">\n";
  for (int i = 0; i < n; ++i) {
    const Curve& s = curves[i];
    const CurveLook look = lookOf(s, i);
    std::ostringstream d, marks;
    double sinceMark = kMarkerSpacing * (1.0 - static_cast<double>(i) / n);
    for (const Polyline& p : polylines(f, s.points))
      for (std::size_t k = 0; k < p.size(); ++k) {
        const auto [qx, qy] = p[k];
        d << (k == 0 ? "M" : "L") << px(qx) << ' ' << px(qy);
        if (k > 0) sinceMark += std::hypot(qx - p[k - 1].first, qy - p[k - 1].second);
        if (s.style.markers && sinceMark >= kMarkerSpacing && plot.contains(qx, qy)) {
          markerPath(marks, i, qx, qy);
          sinceMark = 0;
        }
      }
    o << "<path class=\"series\" data-name=\"" << xmlEscape(s.name) << "\" stroke=\"" << xmlEscape(look.color)
      << "\" stroke-width=\"" << px(look.width) << "\"";
    if (look.dash != "none") o << " stroke-dasharray=\"" << xmlEscape(look.dash) << "\"";
    o << " d=\"" << d.str() << "\"/>\n";
    if (s.style.markers)
      o << "<path class=\"markers\" stroke=\"" << xmlEscape(look.color) << "\" stroke-width=\"1.2\" fill=\"white\" d=\""
        << marks.str() << "\"/>\n";
  }
  o << "</g>\n";
}

// Frame with inward ticks, mirrored (shorter) on the top and right edges, and
// the tick labels (with the axes' powers of ten).
void writeAxes(std::ostringstream& o, const Frame& f) {
  const double L = f.L, T = f.T, R = f.R, B = f.B;
  o << "<rect class=\"frame\" x=\"" << px(L) << "\" y=\"" << px(T) << "\" width=\"" << px(R - L)
    << "\" height=\"" << px(B - T) << "\" fill=\"none\" stroke=\"black\" stroke-width=\"1\"/>\n";
  o << "<path class=\"ticks\" stroke=\"black\" stroke-width=\"1\" d=\"";
  for (double t : f.xTicks) o << "M" << px(f.X(t)) << ' ' << px(B) << "v-5M" << px(f.X(t)) << ' ' << px(T) << "v3";
  for (double t : f.yTicks) o << "M" << px(L) << ' ' << px(f.Y(t)) << "h5M" << px(R) << ' ' << px(f.Y(t)) << "h-3";
  o << "\"/>\n";

  o << "<g class=\"tick-labels\" fill=\"black\">\n";
  const double xLabBase = B + 6 + kFontTick;
  for (std::size_t k = 0; k < f.xTicks.size(); ++k)
    o << "<text x=\"" << px(f.X(f.xTicks[k])) << "\" y=\"" << px(xLabBase) << "\" text-anchor=\"middle\">"
      << f.xLab.text[k] << "</text>\n";
  for (std::size_t k = 0; k < f.yTicks.size(); ++k)
    o << "<text x=\"" << px(L - 7) << "\" y=\"" << px(f.Y(f.yTicks[k]) + 0.36 * kFontTick)
      << "\" text-anchor=\"end\">" << f.yLab.text[k] << "</text>\n";
  if (f.xLab.exponent != 0)
    o << "<text x=\"" << px(R) << "\" y=\"" << px(xLabBase + kFontLabel + 8) << "\" text-anchor=\"end\">×10"
      << superscript(f.xLab.exponent) << "</text>\n";
  if (f.yLab.exponent != 0)
    o << "<text x=\"" << px(L) << "\" y=\"" << px(T - 6) << "\" text-anchor=\"start\">×10"
      << superscript(f.yLab.exponent) << "</text>\n";
  o << "</g>\n";
}

// The axis labels and the title, centred over the plot, within the picture
// less a margin on either side.
void writeLabels(std::ostringstream& o, const ChartPage& page, const Frame& f) {
  const double L = f.L, T = f.T, R = f.R, B = f.B;
  const double xLabBase = B + 6 + kFontTick;
  if (!page.xLabel.empty())
    o << "<text class=\"xlabel\" x=\"" << px(0.5 * (L + R)) << "\" y=\"" << px(xLabBase + kFontLabel + 8)
      << "\" font-size=\"" << px(kFontLabel) << "\" text-anchor=\"middle\">" << xmlEscape(page.xLabel) << "</text>\n";
  if (!page.yLabel.empty()) {
    const double x = 10 + kFontLabel * 0.8, y = 0.5 * (T + B);
    o << "<text class=\"ylabel\" x=\"" << px(x) << "\" y=\"" << px(y) << "\" font-size=\"" << px(kFontLabel)
      << "\" text-anchor=\"middle\" transform=\"rotate(-90 " << px(x) << ' ' << px(y) << ")\">"
      << xmlEscape(page.yLabel) << "</text>\n";
  }
  if (!page.title.empty())
    o << svgTitle(page.title, 0.5 * (L + R), T - 18, kFontTitle,
                  2 * std::min(0.5 * (L + R), page.width - 0.5 * (L + R)) - 16);
}

// The legend: a line sample (and marker) and the name of each curve.
void writeLegend(std::ostringstream& o, const Legend& g, const std::vector<Curve>& curves) {
  const Rect& box = g.box;
  o << "<g class=\"legend\">\n<rect x=\"" << px(box.x0) << "\" y=\"" << px(box.y0) << "\" width=\"" << px(g.boxW)
    << "\" height=\"" << px(g.boxH) << "\" fill=\"white\" fill-opacity=\"0.92\" stroke=\"#9a9a9a\" "
       "stroke-width=\"0.8\"/>\n";
  for (int i = 0; i < static_cast<int>(curves.size()); ++i) {
    const Curve& s = curves[i];
    const CurveLook look = lookOf(s, i);
    const double cy = box.y0 + 5 + (i + 0.5) * Legend::kRowH;
    const double x0 = box.x0 + Legend::kPad;
    o << "<line x1=\"" << px(x0) << "\" y1=\"" << px(cy) << "\" x2=\"" << px(x0 + Legend::kSample) << "\" y2=\""
      << px(cy) << "\" stroke=\"" << xmlEscape(look.color) << "\" stroke-width=\"" << px(look.width) << "\"";
    if (look.dash != "none") o << " stroke-dasharray=\"" << xmlEscape(look.dash) << "\"";
    o << "/>\n";
    if (s.style.markers) {
      std::ostringstream m;
      markerPath(m, i, x0 + 0.5 * Legend::kSample, cy);
      o << "<path stroke=\"" << xmlEscape(look.color) << "\" stroke-width=\"1.2\" fill=\"white\" d=\"" << m.str()
        << "\"/>\n";
    }
    const auto [font, squeeze] = fittedFont(s.name, kFontLegend, g.textW);
    o << "<text x=\"" << px(x0 + Legend::kSample + 7) << "\" y=\"" << px(cy + 0.36 * kFontLegend) << "\""
      << (font < kFontLegend ? fitAttributes(font, squeeze) : std::string()) << ">" << xmlEscape(s.name)
      << "</text>\n";
  }
  o << "</g>\n";
}

}  // namespace

std::string SvgChart::svg() const {
  const ChartPage page{width_, height_, title_, xLabel_, yLabel_};
  std::vector<Curve> curves;
  bool anyName = false;
  for (const Series& s : series_) {
    curves.push_back({s.name, s.points, s.style});
    anyName = anyName || !s.name.empty();
  }
  Frame f = layoutFrame(page, xRange(), yRange(), 0);
  Legend legend = legendSize(f, curves, legend_.value_or(anyName) && numSeries() > 0);
  if (legend.show) placeLegend(legend, f, page, curves);

  std::ostringstream o;
  writeHead(o, page, f);
  writeGrid(o, f);
  writeCurves(o, f, curves);
  writeAxes(o, f);
  writeLabels(o, page, f);
  if (legend.show) writeLegend(o, legend, curves);
  o << "</svg>\n";
  return o.str();
}

void SvgChart::save(const std::filesystem::path& path) const { AtomicFile::write(path, svg()); }

}  // namespace c2d
