#include "macro/output/SvgDebris.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "macro/output/SvgNumber.h"
#include "core/io/AtomicFile.h"
#include "macro/output/SvgChart.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

constexpr double kWidth = 720, kFrameHeight = 300, kHistHeight = 130;
constexpr double kLeft = 60, kRight = 20, kTop = 56, kGap = 34, kBottom = 40;


std::string shortNum(double v) { return formatNumber("%.3g", v); }

Vec2 position(const Model& model, const State& s, int n) {
  const Eigen::Index i = static_cast<Eigen::Index>(n) * kNodeDofs;
  return model.coord(n) + (i + 1 < s.u.size() ? Vec2(s.u[i], s.u[i + 1]) : Vec2::Zero());
}

// The picture's scale: the drawn x range (the nodes now, the footprint and the
// site) and the frame's y range, one scale in x and y (the frame keeps its
// shape), centred in the panel; the histogram below it.
struct DebrisView {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  double s = 1, left = 0, groundPx = 0;
  double histTop = 0, histBottom = 0, height = 0;
  double X(double x) const { return left + (x - x0) * s; }
  double Y(double y) const { return groundPx - (y - y0) * s; }
};

DebrisView debrisView(const Model& model, const State& state, const DebrisFigures& d,
                      const std::vector<char>& held) {
  DebrisView v;
  v.x0 = std::min(d.xmin, d.footprintMin);
  v.x1 = std::max(d.xmax, d.footprintMax);
  v.y0 = model.ground() ? model.ground()->y0 : 0.0;
  v.y1 = v.y0;
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n) || !held[n]) continue;
    const Vec2 p = position(model, state, n);
    v.y0 = std::min(v.y0, p.y());
    v.y1 = std::max(v.y1, p.y());
  }
  if (d.site) {
    v.x0 = std::min(v.x0, d.site->xmin);
    v.x1 = std::max(v.x1, d.site->xmax);
  }
  const double span = std::max(v.x1 - v.x0, 1e-9);
  v.x0 -= 0.05 * span;
  v.x1 += 0.05 * span;
  const double plotW = kWidth - kLeft - kRight;
  v.s = std::min(plotW / (v.x1 - v.x0), kFrameHeight / std::max(v.y1 - v.y0, 1e-9 * span));
  v.left = kLeft + 0.5 * (plotW - v.s * (v.x1 - v.x0));
  v.groundPx = kTop + kFrameHeight - 0.5 * (kFrameHeight - v.s * (v.y1 - v.y0));
  v.histTop = kTop + kFrameHeight + kGap;
  v.histBottom = v.histTop + kHistHeight;
  v.height = v.histBottom + kBottom;
  return v;
}

// The footprint band over both panels, the ground, the members in their
// current state and the nodal masses.
void drawFrame(std::ostringstream& o, const DebrisView& v, const Model& model, const State& state,
               const DebrisFigures& d, const std::vector<char>& held) {
  o << "<rect class=\"footprint\" x=\"" << px(v.X(d.footprintMin)) << "\" y=\"" << px(kTop)
    << "\" width=\"" << px(v.X(d.footprintMax) - v.X(d.footprintMin)) << "\" height=\""
    << px(v.histBottom - kTop) << "\" fill=\"#E8E8E8\"/>\n";
  o << "<text x=\"" << px(0.5 * (v.X(d.footprintMin) + v.X(d.footprintMax))) << "\" y=\""
    << px(kTop + 14) << "\" text-anchor=\"middle\" fill=\"#666666\">footprint</text>\n";
  if (model.ground()) {
    const double gy = v.Y(model.ground()->y0);
    o << "<path class=\"ground\" fill=\"none\" stroke=\"#555555\" stroke-width=\"1.5\" d=\"M" << px(kLeft) << ' '
      << px(gy) << "H" << px(kWidth - kRight) << "\"/>\n";
  }
  o << "<path class=\"members\" stroke=\"#1F77B4\" stroke-width=\"2\" fill=\"none\" d=\"";
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.elements()[e]) continue;
    const auto n = model.element(e).nodes();
    const Vec2 a = position(model, state, n[0]), b = position(model, state, n[1]);
    o << "M" << px(v.X(a.x())) << ' ' << px(v.Y(a.y())) << "L" << px(v.X(b.x())) << ' '
      << px(v.Y(b.y()));
  }
  o << "\"/>\n";
  for (int n = 0; n < model.numNodes(); ++n)
    if (model.hasCoord(n) && held[n] &&
        std::max(model.nodalMass(n)[0], model.nodalMass(n)[1]) > 0) {
      const Vec2 p = position(model, state, n);
      o << "<circle class=\"mass\" cx=\"" << px(v.X(p.x())) << "\" cy=\"" << px(v.Y(p.y()))
        << "\" r=\"3\" fill=\"#1F77B4\"/>\n";
    }
}

// The histogram of the mass along the ground, with its axis and labels.
void drawHistogram(std::ostringstream& o, const DebrisView& v, const Model& model,
                   const State& state, int bins) {
  const double width = (v.x1 - v.x0) / std::max(bins, 1);
  const auto h = massHistogram(massPieces(model, state), v.x0, width, bins);
  const double hmax = h.empty() ? 0.0 : *std::max_element(h.begin(), h.end());
  o << "<path class=\"axis\" fill=\"none\" stroke=\"black\" stroke-width=\"1\" d=\"M" << px(kLeft) << ' '
    << px(v.histTop) << "V" << px(v.histBottom) << "H" << px(kWidth - kRight) << "\"/>\n";
  o << "<g class=\"histogram\" fill=\"#8C564B\">\n";
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (h[k] <= 0 || hmax <= 0) continue;
    const double bh = h[k] / hmax * kHistHeight;
    o << "<rect x=\"" << px(v.X(v.x0 + k * width) + 0.5) << "\" y=\"" << px(v.histBottom - bh)
      << "\" width=\""
      << px(std::max(0.5, v.X(v.x0 + (k + 1) * width) - v.X(v.x0 + k * width) - 1))
      << "\" height=\"" << px(bh) << "\"/>\n";
  }
  o << "</g>\n";
  o << "<text x=\"" << px(kLeft - 6) << "\" y=\"" << px(v.histTop + 4) << "\" text-anchor=\"end\">"
    << shortNum(hmax) << "</text>\n";
  o << "<text x=\"" << px(kLeft - 6) << "\" y=\"" << px(v.histBottom + 4)
    << "\" text-anchor=\"end\">0</text>\n";
  o << "<text x=\"" << px(kLeft + 6) << "\" y=\"" << px(v.histTop - 6) << "\">mass per "
    << shortNum(width) << " m of ground [t]</text>\n";
}

// The x axis's ticks (footprint and site limits), the site's lines, the axis name.
void drawLimits(std::ostringstream& o, const DebrisView& v, const DebrisFigures& d) {
  auto tick = [&](double x, const char* color) {
    o << "<text x=\"" << px(v.X(x)) << "\" y=\"" << px(v.histBottom + 16)
      << "\" text-anchor=\"middle\" fill=\"" << color << "\">" << shortNum(onAxis(x, v.x1 - v.x0))
      << "</text>\n";
  };
  tick(d.footprintMin, "#666666");
  tick(d.footprintMax, "#666666");
  if (d.site) {
    for (double x : {d.site->xmin, d.site->xmax}) {
      o << "<path class=\"site\" fill=\"none\" stroke=\"#D62728\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\" "
           "d=\"M"
        << px(v.X(x)) << ' ' << px(kTop) << "V" << px(v.histBottom) << "\"/>\n";
      tick(x, "#D62728");
    }
    o << "<text x=\"" << px(v.X(d.site->xmax) - 4) << "\" y=\"" << px(kTop + 14)
      << "\" text-anchor=\"end\" fill=\"#D62728\">site</text>\n";
  }
  o << "<text x=\"" << px(kWidth - kRight) << "\" y=\"" << px(v.histBottom + 32)
    << "\" text-anchor=\"end\">x [m]</text>\n";
}

// The title and the figures' line (red when debris is outside the site).
void drawFigures(std::ostringstream& o, const DebrisFigures& d, const std::string& title) {
  o << svgTitle(title, 0.5 * kWidth, 22, 15, kWidth - 20);
  std::string line = "beyond the footprint: left " + shortNum(d.left) + " m, right " +
                     shortNum(d.right) + " m; height " + shortNum(d.height) + " m";
  if (d.site)
    line += "; " + std::string(d.outside() ? "OUTSIDE the site, " : "inside the site, ") +
            shortNum(d.outsideMass) + " t outside";
  o << svgFittedText(line, 0.5 * kWidth, 42, 12, kWidth - 20,
                     d.outside() ? "class=\"figures\" fill=\"#D62728\"" : "class=\"figures\"");
}

}  // namespace

std::string debrisSvg(const Model& model, const State& state, const DebrisFigures& d,
                      const std::string& title, int bins) {
  const std::vector<char> held = model.heldNodes();
  const DebrisView v = debrisView(model, state, d, held);
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << px(kWidth)
    << "\" height=\"" << px(v.height) << "\" viewBox=\"0 0 " << px(kWidth) << ' ' << px(v.height)
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  drawFrame(o, v, model, state, d, held);
  drawHistogram(o, v, model, state, bins);
  drawLimits(o, v, d);
  drawFigures(o, d, title);
  o << "</svg>\n";
  return o.str();
}

void saveDebrisSvg(const std::filesystem::path& path, const Model& model, const State& state,
                   const DebrisFigures& figures, const std::string& title) {
  AtomicFile::write(path, debrisSvg(model, state, figures, title));
}

}  // namespace c2d
