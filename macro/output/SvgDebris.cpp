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

}  // namespace

std::string debrisSvg(const Model& model, const State& state, const DebrisFigures& d,
                      const std::string& title, int bins) {
  // The drawn x range: the nodes now, the footprint and the site.
  double x0 = std::min(d.xmin, d.footprintMin), x1 = std::max(d.xmax, d.footprintMax);
  double y0 = model.ground() ? model.ground()->y0 : 0.0, y1 = y0;
  const std::vector<char> held = model.heldNodes();
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n) || !held[n]) continue;
    const Vec2 p = position(model, state, n);
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }
  if (d.site) {
    x0 = std::min(x0, d.site->xmin);
    x1 = std::max(x1, d.site->xmax);
  }
  const double span = std::max(x1 - x0, 1e-9);
  x0 -= 0.05 * span;
  x1 += 0.05 * span;
  const double plotW = kWidth - kLeft - kRight;
  // One scale in x and y (the frame keeps its shape), centred in the panel.
  const double s = std::min(plotW / (x1 - x0), kFrameHeight / std::max(y1 - y0, 1e-9 * span));
  const double left = kLeft + 0.5 * (plotW - s * (x1 - x0));
  const double groundPx = kTop + kFrameHeight - 0.5 * (kFrameHeight - s * (y1 - y0));
  auto X = [&](double x) { return left + (x - x0) * s; };
  auto Y = [&](double y) { return groundPx - (y - y0) * s; };
  const double histTop = kTop + kFrameHeight + kGap, histBottom = histTop + kHistHeight;
  const double height = histBottom + kBottom;

  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << px(kWidth)
    << "\" height=\"" << px(height) << "\" viewBox=\"0 0 " << px(kWidth) << ' ' << px(height)
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // Footprint band over both panels.
  o << "<rect class=\"footprint\" x=\"" << px(X(d.footprintMin)) << "\" y=\"" << px(kTop)
    << "\" width=\"" << px(X(d.footprintMax) - X(d.footprintMin)) << "\" height=\""
    << px(histBottom - kTop) << "\" fill=\"#E8E8E8\"/>\n";
  o << "<text x=\"" << px(0.5 * (X(d.footprintMin) + X(d.footprintMax))) << "\" y=\""
    << px(kTop + 14) << "\" text-anchor=\"middle\" fill=\"#666666\">footprint</text>\n";
  // Ground.
  if (model.ground()) {
    const double gy = Y(model.ground()->y0);
    o << "<path class=\"ground\" fill=\"none\" stroke=\"#555555\" stroke-width=\"1.5\" d=\"M" << px(kLeft) << ' '
      << px(gy) << "H" << px(kWidth - kRight) << "\"/>\n";
  }
  // Members in their current state.
  o << "<path class=\"members\" stroke=\"#1F77B4\" stroke-width=\"2\" fill=\"none\" d=\"";
  for (int e = 0; e < model.numElements(); ++e) {
    if (!model.elements()[e]) continue;
    const auto n = model.element(e).nodes();
    const Vec2 a = position(model, state, n[0]), b = position(model, state, n[1]);
    o << "M" << px(X(a.x())) << ' ' << px(Y(a.y())) << "L" << px(X(b.x())) << ' ' << px(Y(b.y()));
  }
  o << "\"/>\n";
  // Nodal masses.
  for (int n = 0; n < model.numNodes(); ++n)
    if (model.hasCoord(n) && held[n] &&
        std::max(model.nodalMass(n)[0], model.nodalMass(n)[1]) > 0) {
      const Vec2 p = position(model, state, n);
      o << "<circle class=\"mass\" cx=\"" << px(X(p.x())) << "\" cy=\"" << px(Y(p.y()))
        << "\" r=\"3\" fill=\"#1F77B4\"/>\n";
    }
  // Histogram of the mass along the ground.
  const double width = (x1 - x0) / std::max(bins, 1);
  const auto h = massHistogram(massPieces(model, state), x0, width, bins);
  const double hmax = h.empty() ? 0.0 : *std::max_element(h.begin(), h.end());
  o << "<path class=\"axis\" fill=\"none\" stroke=\"black\" stroke-width=\"1\" d=\"M" << px(kLeft) << ' '
    << px(histTop) << "V" << px(histBottom) << "H" << px(kWidth - kRight) << "\"/>\n";
  o << "<g class=\"histogram\" fill=\"#8C564B\">\n";
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (h[k] <= 0 || hmax <= 0) continue;
    const double bh = h[k] / hmax * kHistHeight;
    o << "<rect x=\"" << px(X(x0 + k * width) + 0.5) << "\" y=\"" << px(histBottom - bh)
      << "\" width=\"" << px(std::max(0.5, X(x0 + (k + 1) * width) - X(x0 + k * width) - 1))
      << "\" height=\"" << px(bh) << "\"/>\n";
  }
  o << "</g>\n";
  o << "<text x=\"" << px(kLeft - 6) << "\" y=\"" << px(histTop + 4) << "\" text-anchor=\"end\">"
    << shortNum(hmax) << "</text>\n";
  o << "<text x=\"" << px(kLeft - 6) << "\" y=\"" << px(histBottom + 4)
    << "\" text-anchor=\"end\">0</text>\n";
  o << "<text x=\"" << px(kLeft + 6) << "\" y=\"" << px(histTop - 6) << "\">mass per "
    << shortNum(width) << " m of ground [t]</text>\n";
  // x axis ticks: footprint and site limits, the debris extent.
  auto tick = [&](double x, const char* color) {
    o << "<text x=\"" << px(X(x)) << "\" y=\"" << px(histBottom + 16)
      << "\" text-anchor=\"middle\" fill=\"" << color << "\">" << shortNum(onAxis(x, x1 - x0))
      << "</text>\n";
  };
  tick(d.footprintMin, "#666666");
  tick(d.footprintMax, "#666666");
  // Site limits.
  if (d.site) {
    for (double x : {d.site->xmin, d.site->xmax}) {
      o << "<path class=\"site\" fill=\"none\" stroke=\"#D62728\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\" "
           "d=\"M"
        << px(X(x)) << ' ' << px(kTop) << "V" << px(histBottom) << "\"/>\n";
      tick(x, "#D62728");
    }
    o << "<text x=\"" << px(X(d.site->xmax) - 4) << "\" y=\"" << px(kTop + 14)
      << "\" text-anchor=\"end\" fill=\"#D62728\">site</text>\n";
  }
  o << "<text x=\"" << px(kWidth - kRight) << "\" y=\"" << px(histBottom + 32)
    << "\" text-anchor=\"end\">x [m]</text>\n";
  // Title and figures.
  o << svgTitle(title, 0.5 * kWidth, 22, 15, kWidth - 20);
  std::string line = "beyond the footprint: left " + shortNum(d.left) + " m, right " +
                     shortNum(d.right) + " m; height " + shortNum(d.height) + " m";
  if (d.site)
    line += "; " + std::string(d.outside() ? "OUTSIDE the site, " : "inside the site, ") +
            shortNum(d.outsideMass) + " t outside";
  o << svgFittedText(line, 0.5 * kWidth, 42, 12, kWidth - 20,
                     d.outside() ? "class=\"figures\" fill=\"#D62728\"" : "class=\"figures\"");
  o << "</svg>\n";
  return o.str();
}

void saveDebrisSvg(const std::filesystem::path& path, const Model& model, const State& state,
                   const DebrisFigures& figures, const std::string& title) {
  AtomicFile::write(path, debrisSvg(model, state, figures, title));
}

}  // namespace c2d
