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

std::string SvgChart::svg() const {
  // Plain variables, not structured bindings: lambdas below capture them.
  const std::pair<double, double> xr = xRange(), yr = yRange();
  const double xlo = xr.first, xhi = xr.second, ylo = yr.first, yhi = yr.second;
  const int n = numSeries();

  struct Layout {
    double L = 0, T = 0, R = 0, B = 0;
    std::vector<double> xTicks, yTicks;
    TickLabels xLab, yLab;
  };
  // rightExtra: room kept right of the plot for a legend outside it.
  auto layout = [&](double rightExtra) {
    Layout f;
    // Vertical layout first: the y tick labels it yields set the left margin.
    f.T = title_.empty() ? 20 : 44;
    f.B = height_ - (5 + 6 + kFontTick + (xLabel_.empty() ? 12 : 12 + kFontLabel + 10));
    const int maxYTicks = std::max(3, static_cast<int>((f.B - f.T) / 45));
    f.yTicks = niceTicks(ylo, yhi, maxYTicks);
    f.yLab = formatTicks(f.yTicks, tickStep(ylo, yhi, maxYTicks));
    double yLabW = 0;
    for (const auto& s : f.yLab.text) yLabW = std::max(yLabW, textWidth(s, kFontTick));
    f.L = 10 + (yLabel_.empty() ? 0 : kFontLabel + 10) + yLabW + 8;
    f.R = width_ - 22 - rightExtra;
    // Fewer x ticks until their labels leave room between them.
    for (int maxXTicks = std::max(3, static_cast<int>((f.R - f.L) / 70));; --maxXTicks) {
      f.xTicks = niceTicks(xlo, xhi, maxXTicks);
      f.xLab = formatTicks(f.xTicks, tickStep(xlo, xhi, maxXTicks));
      double w = 0;
      for (const auto& s : f.xLab.text) w = std::max(w, textWidth(s, kFontTick));
      if (maxXTicks <= 3 || (w + 14) * static_cast<double>(f.xTicks.size()) <= f.R - f.L) break;
    }
    return f;
  };
  auto mapX = [&](const Layout& f, double x) { return f.L + (x - xlo) / (xhi - xlo) * (f.R - f.L); };
  auto mapY = [&](const Layout& f, double y) { return f.T + (yhi - y) / (yhi - ylo) * (f.B - f.T); };

  // Pixel polylines of the series (a non-finite point starts a new piece).
  using Polyline = std::vector<std::pair<double, double>>;
  auto polylines = [&](const Layout& f, const Series& s) {
    std::vector<Polyline> pieces(1);
    for (const auto& [x, y] : s.points) {
      if (!std::isfinite(x) || !std::isfinite(y)) {
        if (!pieces.back().empty()) pieces.emplace_back();
        continue;
      }
      pieces.back().emplace_back(mapX(f, x), mapY(f, y));
    }
    if (pieces.back().empty()) pieces.pop_back();
    return pieces;
  };
  // Curve samples about every 3 px inside the plot: what a legend box would hide.
  auto curveSamples = [&](const Layout& f) {
    std::vector<std::pair<double, double>> samples;
    const Rect plot{f.L, f.T, f.R, f.B};
    for (const Series& s : series_)
      for (const Polyline& p : polylines(f, s))
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
  };

  // Legend: inside, where it hides no curve (corners first), else outside on the right.
  bool anyName = false;
  for (const Series& s : series_) anyName = anyName || !s.name.empty();
  const bool showLegend = legend_.value_or(anyName) && n > 0;
  const double legPad = 8, legRowH = 18, legSample = 32;
  Layout f = layout(0);
  // A legend entry is never wider than the plot leaves it: a longer one is set
  // smaller, then squeezed (as a title is).
  const double legTextMax = std::max(40.0, f.R - f.L - 16 - 2 * legPad - legSample - 7);
  double legTextW = 0;
  for (const Series& s : series_) legTextW = std::max(legTextW, textWidth(s.name, kFontLegend));
  legTextW = std::min(legTextW, legTextMax);
  const double boxW = legPad + legSample + 7 + legTextW + legPad, boxH = 2 * 5 + n * legRowH;

  Rect box{};
  if (showLegend) {
    const double inset = 8;
    const double xl = f.L + inset, xr = f.R - inset - boxW, xc = 0.5 * (f.L + f.R - boxW);
    const double yt = f.T + inset, yb = f.B - inset - boxH, ym = 0.5 * (f.T + f.B - boxH);
    const std::array<std::pair<double, double>, 8> spots = {
        {{xr, yt}, {xl, yt}, {xr, yb}, {xl, yb}, {xc, yt}, {xc, yb}, {xr, ym}, {xl, ym}}};
    const auto samples = curveSamples(f);
    std::size_t bestCount = std::numeric_limits<std::size_t>::max();
    for (const auto& [x0, y0] : spots) {
      const Rect grown{x0 - 4, y0 - 4, x0 + boxW + 4, y0 + boxH + 4};
      const auto count = static_cast<std::size_t>(std::count_if(
          samples.begin(), samples.end(), [&](const auto& p) { return grown.contains(p.first, p.second); }));
      if (count < bestCount) {
        bestCount = count;
        box = {x0, y0, x0 + boxW, y0 + boxH};
      }
    }
    // Outside only while the plot keeps most of the width.
    if (bestCount > 0 && boxW + 12 < 0.35 * (f.R - f.L)) {
      f = layout(boxW + 12);
      box = {f.R + 12, f.T, f.R + 12 + boxW, f.T + boxH};
    }
  }
  const double L = f.L, T = f.T, R = f.R, B = f.B, plotW = R - L, plotH = B - T;
  auto X = [&](double x) { return mapX(f, x); };
  auto Y = [&](double y) { return mapY(f, y); };

  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << px(width_) << "\" height=\""
    << px(height_) << "\" viewBox=\"0 0 " << px(width_) << ' ' << px(height_)
    << "\" font-family=\"sans-serif\" font-size=\"" << px(kFontTick) << "\">\n";
  if (!title_.empty()) o << "<title>" << xmlEscape(title_) << "</title>\n";
  o << "<defs><clipPath id=\"plot-area\"><rect x=\"" << px(L) << "\" y=\"" << px(T) << "\" width=\""
    << px(plotW) << "\" height=\"" << px(plotH) << "\"/></clipPath></defs>\n";
  o << "<rect width=\"" << px(width_) << "\" height=\"" << px(height_) << "\" fill=\"white\"/>\n";

  // Grid at the ticks, light enough to stay behind the curves.
  o << "<g class=\"grid\" stroke=\"#dcdcdc\" stroke-width=\"0.7\">\n";
  for (double t : f.xTicks)
    if (std::abs(X(t) - L) > 0.5 && std::abs(X(t) - R) > 0.5)
      o << "<line x1=\"" << px(X(t)) << "\" y1=\"" << px(T) << "\" x2=\"" << px(X(t)) << "\" y2=\"" << px(B)
        << "\"/>\n";
  for (double t : f.yTicks)
    if (std::abs(Y(t) - T) > 0.5 && std::abs(Y(t) - B) > 0.5)
      o << "<line x1=\"" << px(L) << "\" y1=\"" << px(Y(t)) << "\" x2=\"" << px(R) << "\" y2=\"" << px(Y(t))
        << "\"/>\n";
  o << "</g>\n";
  // Zero lines: a force-time curve crossing zero reads better against them.
  if (ylo < 0 && yhi > 0)
    o << "<line class=\"zero\" x1=\"" << px(L) << "\" y1=\"" << px(Y(0)) << "\" x2=\"" << px(R) << "\" y2=\""
      << px(Y(0)) << "\" stroke=\"#808080\" stroke-width=\"0.8\"/>\n";
  if (xlo < 0 && xhi > 0)
    o << "<line class=\"zero\" x1=\"" << px(X(0)) << "\" y1=\"" << px(T) << "\" x2=\"" << px(X(0)) << "\" y2=\""
      << px(B) << "\" stroke=\"#808080\" stroke-width=\"0.8\"/>\n";

  const Rect plot{L - 1, T - 1, R + 1, B + 1};
  o << "<g clip-path=\"url(#plot-area)\" fill=\"none\" stroke-linejoin=\"round\">\n";
  for (int i = 0; i < n; ++i) {
    const Series& s = series_[i];
    const std::string color = s.style.color.empty() ? kPalette[i % kPalette.size()] : s.style.color;
    const std::string dash = s.style.dash.empty() ? kDashes[i % kDashes.size()] : s.style.dash;
    const double width = s.style.width > 0 ? s.style.width : kLineWidth;
    std::ostringstream d, marks;
    // Markers evenly spaced along the drawn curve, staggered between series so
    // that coincident curves still show every marker shape.
    double sinceMark = kMarkerSpacing * (1.0 - static_cast<double>(i) / n);
    for (const Polyline& p : polylines(f, s))
      for (std::size_t k = 0; k < p.size(); ++k) {
        const auto [qx, qy] = p[k];
        d << (k == 0 ? "M" : "L") << px(qx) << ' ' << px(qy);
        if (k > 0) sinceMark += std::hypot(qx - p[k - 1].first, qy - p[k - 1].second);
        if (s.style.markers && sinceMark >= kMarkerSpacing && plot.contains(qx, qy)) {
          markerPath(marks, i, qx, qy);
          sinceMark = 0;
        }
      }
    o << "<path class=\"series\" data-name=\"" << xmlEscape(s.name) << "\" stroke=\"" << xmlEscape(color)
      << "\" stroke-width=\"" << px(width) << "\"";
    if (dash != "none") o << " stroke-dasharray=\"" << xmlEscape(dash) << "\"";
    o << " d=\"" << d.str() << "\"/>\n";
    if (s.style.markers)
      o << "<path class=\"markers\" stroke=\"" << xmlEscape(color) << "\" stroke-width=\"1.2\" fill=\"white\" d=\""
        << marks.str() << "\"/>\n";
  }
  o << "</g>\n";

  // Frame with inward ticks, mirrored (shorter) on the top and right edges.
  o << "<rect class=\"frame\" x=\"" << px(L) << "\" y=\"" << px(T) << "\" width=\"" << px(plotW)
    << "\" height=\"" << px(plotH) << "\" fill=\"none\" stroke=\"black\" stroke-width=\"1\"/>\n";
  o << "<path class=\"ticks\" stroke=\"black\" stroke-width=\"1\" d=\"";
  for (double t : f.xTicks) o << "M" << px(X(t)) << ' ' << px(B) << "v-5M" << px(X(t)) << ' ' << px(T) << "v3";
  for (double t : f.yTicks) o << "M" << px(L) << ' ' << px(Y(t)) << "h5M" << px(R) << ' ' << px(Y(t)) << "h-3";
  o << "\"/>\n";

  o << "<g class=\"tick-labels\" fill=\"black\">\n";
  const double xLabBase = B + 6 + kFontTick;
  for (std::size_t k = 0; k < f.xTicks.size(); ++k)
    o << "<text x=\"" << px(X(f.xTicks[k])) << "\" y=\"" << px(xLabBase) << "\" text-anchor=\"middle\">"
      << f.xLab.text[k] << "</text>\n";
  for (std::size_t k = 0; k < f.yTicks.size(); ++k)
    o << "<text x=\"" << px(L - 7) << "\" y=\"" << px(Y(f.yTicks[k]) + 0.36 * kFontTick)
      << "\" text-anchor=\"end\">" << f.yLab.text[k] << "</text>\n";
  if (f.xLab.exponent != 0)
    o << "<text x=\"" << px(R) << "\" y=\"" << px(xLabBase + kFontLabel + 8) << "\" text-anchor=\"end\">×10"
      << superscript(f.xLab.exponent) << "</text>\n";
  if (f.yLab.exponent != 0)
    o << "<text x=\"" << px(L) << "\" y=\"" << px(T - 6) << "\" text-anchor=\"start\">×10"
      << superscript(f.yLab.exponent) << "</text>\n";
  o << "</g>\n";

  if (!xLabel_.empty())
    o << "<text class=\"xlabel\" x=\"" << px(0.5 * (L + R)) << "\" y=\"" << px(xLabBase + kFontLabel + 8)
      << "\" font-size=\"" << px(kFontLabel) << "\" text-anchor=\"middle\">" << xmlEscape(xLabel_) << "</text>\n";
  if (!yLabel_.empty()) {
    const double x = 10 + kFontLabel * 0.8, y = 0.5 * (T + B);
    o << "<text class=\"ylabel\" x=\"" << px(x) << "\" y=\"" << px(y) << "\" font-size=\"" << px(kFontLabel)
      << "\" text-anchor=\"middle\" transform=\"rotate(-90 " << px(x) << ' ' << px(y) << ")\">"
      << xmlEscape(yLabel_) << "</text>\n";
  }
  // Centred over the plot, within the picture less a margin on either side.
  if (!title_.empty())
    o << svgTitle(title_, 0.5 * (L + R), T - 18, kFontTitle,
                  2 * std::min(0.5 * (L + R), width_ - 0.5 * (L + R)) - 16);

  if (showLegend) {
    o << "<g class=\"legend\">\n<rect x=\"" << px(box.x0) << "\" y=\"" << px(box.y0) << "\" width=\"" << px(boxW)
      << "\" height=\"" << px(boxH) << "\" fill=\"white\" fill-opacity=\"0.92\" stroke=\"#9a9a9a\" "
         "stroke-width=\"0.8\"/>\n";
    for (int i = 0; i < n; ++i) {
      const Series& s = series_[i];
      const std::string color = s.style.color.empty() ? kPalette[i % kPalette.size()] : s.style.color;
      const std::string dash = s.style.dash.empty() ? kDashes[i % kDashes.size()] : s.style.dash;
      const double width = s.style.width > 0 ? s.style.width : kLineWidth;
      const double cy = box.y0 + 5 + (i + 0.5) * legRowH;
      const double x0 = box.x0 + legPad;
      o << "<line x1=\"" << px(x0) << "\" y1=\"" << px(cy) << "\" x2=\"" << px(x0 + legSample) << "\" y2=\""
        << px(cy) << "\" stroke=\"" << xmlEscape(color) << "\" stroke-width=\"" << px(width) << "\"";
      if (dash != "none") o << " stroke-dasharray=\"" << xmlEscape(dash) << "\"";
      o << "/>\n";
      if (s.style.markers) {
        std::ostringstream m;
        markerPath(m, i, x0 + 0.5 * legSample, cy);
        o << "<path stroke=\"" << xmlEscape(color) << "\" stroke-width=\"1.2\" fill=\"white\" d=\"" << m.str()
          << "\"/>\n";
      }
      const auto [font, squeeze] = fittedFont(s.name, kFontLegend, legTextW);
      o << "<text x=\"" << px(x0 + legSample + 7) << "\" y=\"" << px(cy + 0.36 * kFontLegend) << "\""
        << (font < kFontLegend ? fitAttributes(font, squeeze) : std::string()) << ">" << xmlEscape(s.name)
        << "</text>\n";
    }
    o << "</g>\n";
  }
  o << "</svg>\n";
  return o.str();
}

void SvgChart::save(const std::filesystem::path& path) const { AtomicFile::write(path, svg()); }

}  // namespace c2d
