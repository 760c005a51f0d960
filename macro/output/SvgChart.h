#pragma once
// x-y line charts as standalone SVG 1.1 (load-displacement, force-time and
// energy-time curves, overlays of a parameter sweep), written without a display.
//
// Each series is one <path class="series"> (a non-finite point breaks the line),
// optional markers one <path class="markers">. Series are told apart by color
// (Okabe-Ito palette, safe for color blindness) and by dash pattern together, so
// a grayscale print stays readable. Axis ranges are the data range plus a small
// margin unless fixed; an axis whose data starts or ends at exactly 0 keeps 0 as
// its limit. Ticks are 1-2-5 multiples of a power of ten; very large or small
// tick values share a factor "x10^k" printed at the end of the axis.
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace c2d {

// Text for SVG/XML content and attribute values: & < > " ' escaped.
std::string xmlEscape(std::string_view text);

// The <text class="title"> element of a picture, centred at (cx, baseline y),
// never wider than maxWidth: a long title is set in a smaller font (down to
// 60 % of fontSize) and, if it still does not fit, squeezed to maxWidth
// (textLength), so that neither edge of the picture clips it.
std::string svgTitle(std::string_view title, double cx, double y, double fontSize, double maxWidth);
// The same for any centred line of text: attributes (class, fill) go into the
// element as given.
std::string svgFittedText(std::string_view text, double cx, double y, double fontSize, double maxWidth,
                          std::string_view attributes);

struct SeriesStyle {
  std::string color;     // any SVG color; empty: from the palette by series index
  std::string dash;      // stroke-dasharray ("6,3"), "none" for solid; empty: from the cycle
  bool markers = false;  // open markers spaced along the curve
  double width = 0;      // stroke width in px; 0: the default
};

class SvgChart {
 public:
  using Points = std::vector<std::pair<double, double>>;

  SvgChart& setTitle(std::string title);
  SvgChart& setXLabel(std::string label);  // with units: "u (m)"
  SvgChart& setYLabel(std::string label);  // "P (kN)"
  SvgChart& setSize(double width, double height);  // px; default 640 x 440
  SvgChart& setXRange(double lo, double hi);        // fixed range (curves are clipped to it)
  SvgChart& setYRange(double lo, double hi);
  SvgChart& setLegend(bool show);  // default: shown when some series has a name

  // Returns the index of the series.
  int addSeries(std::string name, Points points, SeriesStyle style = {});
  int addSeries(std::string name, std::span<const double> x, std::span<const double> y,
                SeriesStyle style = {});  // x and y of equal length
  int numSeries() const { return static_cast<int>(series_.size()); }

  std::string svg() const;
  void save(const std::filesystem::path& path) const;  // atomically (core/io/AtomicFile.h)

  // Axis helpers (also used for scale bars). niceNumber: a 1, 2 or 5 x 10^k close
  // to x > 0 (round: nearest; otherwise the smallest not below x). niceTicks: the
  // multiples of a nice step inside [lo, hi], at most about maxTicks of them.
  static double niceNumber(double x, bool round);
  static double tickStep(double lo, double hi, int maxTicks);
  static std::vector<double> niceTicks(double lo, double hi, int maxTicks);

  // The range drawn for an axis: fixed, or the data range with margins.
  std::pair<double, double> xRange() const;
  std::pair<double, double> yRange() const;

 private:
  struct Series {
    std::string name;
    Points points;
    SeriesStyle style;
  };

  std::pair<double, double> autoRange(bool xAxis) const;

  std::string title_, xLabel_, yLabel_;
  double width_ = 640, height_ = 440;
  std::optional<std::pair<double, double>> xFixed_, yFixed_;
  std::optional<bool> legend_;
  std::vector<Series> series_;
};

}  // namespace c2d
