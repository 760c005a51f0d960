#include "macro/output/SvgFrame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "macro/output/SvgNumber.h"
#include "core/io/AtomicFile.h"
#include "core/Hinge.h"
#include "macro/output/SvgChart.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

constexpr double kFontTitle = 15, kFontText = 12;
constexpr double kSide = 30;        // px left and right of the drawing: room for support symbols
constexpr double kGlyph = 12;       // px, half-width of a support symbol
constexpr double kHingeRadius = 4;  // px
constexpr const char* kHingeColor = "#D62728";


double textWidth(std::string_view s, double fontSize) {
  int n = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++n;
  return 0.56 * fontSize * n;
}

double stateValue(const Eigen::VectorXd& x, int node, int dof) {
  const Eigen::Index i = static_cast<Eigen::Index>(node) * kNodeDofs + dof;
  return i < x.size() ? x[i] : 0.0;
}

Vec2 unit(const Vec2& v, const Vec2& fallback) {
  const double n = v.norm();
  return n > 0 ? Vec2(v / n) : fallback;
}

// Collects "M a L b" segments of one path; points are in px (y down).
struct Pen {
  std::ostringstream& o;
  void line(const Vec2& a, const Vec2& b) {
    o << "M" << px(a.x()) << ' ' << px(a.y()) << "L" << px(b.x()) << ' ' << px(b.y());
  }
};

void crossedCircle(std::ostringstream& o, const Vec2& p, double r) {
  const double d = r * std::sqrt(0.5);
  o << "<g class=\"hinge-failed\"><circle cx=\"" << px(p.x()) << "\" cy=\"" << px(p.y()) << "\" r=\"" << px(r)
    << "\" fill=\"white\" stroke=\"black\" stroke-width=\"1.3\"/><path stroke=\"black\" stroke-width=\"1.3\" d=\"M"
    << px(p.x() - d) << ' ' << px(p.y() - d) << "L" << px(p.x() + d) << ' ' << px(p.y() + d) << "M"
    << px(p.x() - d) << ' ' << px(p.y() + d) << "L" << px(p.x() + d) << ' ' << px(p.y() - d) << "\"/></g>\n";
}

void activeHinge(std::ostringstream& o, const Vec2& p) {
  o << "<circle class=\"hinge-active\" cx=\"" << px(p.x()) << "\" cy=\"" << px(p.y()) << "\" r=\""
    << px(kHingeRadius) << "\" fill=\"" << kHingeColor << "\" stroke=\"black\" stroke-width=\"0.6\"/>\n";
}

void jointCircle(std::ostringstream& o, const Vec2& p) {
  o << "<circle class=\"joint\" cx=\"" << px(p.x()) << "\" cy=\"" << px(p.y())
    << "\" r=\"3.5\" fill=\"white\" stroke=\"black\" stroke-width=\"1.2\"/>\n";
}

// Hatched support surface: a line through c perpendicular to a (the direction
// away from the structure, px), strokes on the far side.
void hatchedSurface(Pen& base, Pen& hatch, const Vec2& c, const Vec2& a, double half) {
  const Vec2 t(-a.y(), a.x());
  base.line(c - half * t, c + half * t);
  const Vec2 d = (a - t) * (5.5 / std::sqrt(2.0));
  for (double k = -half + 3; k <= half + 1e-9; k += 4) hatch.line(c + k * t, c + k * t + d);
}

// The element list may hold empty slots (setElement grows it): skipped, not dereferenced.
const Element* elementOrNull(const Model& model, int e) { return model.elements()[e].get(); }

}  // namespace

SvgFrame& SvgFrame::setShowNodes(bool show) {
  nodes_ = show;
  return *this;
}
SvgFrame& SvgFrame::setTitle(std::string title) {
  title_ = std::move(title);
  return *this;
}
SvgFrame& SvgFrame::setDisplacementScale(double factor) {
  if (!std::isfinite(factor)) throw std::invalid_argument("SvgFrame: displacement scale must be finite");
  scale_ = factor;
  return *this;
}
SvgFrame& SvgFrame::setMaxSize(double width, double height) {
  if (!(width >= 200 && height >= 150)) throw std::invalid_argument("SvgFrame: size below 200 x 150 px");
  maxWidth_ = width;
  maxHeight_ = height;
  return *this;
}
SvgFrame& SvgFrame::setShowUndeformed(bool show) {
  undeformed_ = show;
  return *this;
}
SvgFrame& SvgFrame::setCurved(bool curved) {
  curved_ = curved;
  return *this;
}
SvgFrame& SvgFrame::setScaleBar(bool show, std::string lengthUnit) {
  scaleBar_ = show;
  unit_ = std::move(lengthUnit);
  return *this;
}
SvgFrame& SvgFrame::setKey(bool show) {
  key_ = show;
  return *this;
}

std::string SvgFrame::svg(const Model& model, const State& state) const {
  const int numNodes = model.numNodes();
  auto deformed = [&](int n) {
    return Vec2(model.coord(n) + scale_ * Vec2(stateValue(state.u, n, 0), stateValue(state.u, n, 1)));
  };
  auto validNode = [&](int n) { return n >= 0 && n < numNodes; };

  // What is drawn: elements with valid nodes, their hinges, joints, supports.
  struct Member {
    int a, b;
    HingeInfo hinge;
    bool hasHinge = false;
  };
  std::vector<Member> members;
  std::vector<char> used(numNodes, 0);
  std::vector<Vec2> awaySum(numNodes, Vec2::Zero());
  for (int e = 0; e < model.numElements(); ++e) {
    const Element* slot = elementOrNull(model, e);
    if (!slot) continue;
    const Element& el = *slot;
    const auto nd = el.nodes();
    if (!validNode(nd[0]) || !validNode(nd[1])) continue;
    Member m{nd[0], nd[1], {}, false};
    if (const auto* h = dynamic_cast<const HingeCarrier*>(&el)) {
      m.hinge = h->hinge();
      m.hasHinge = m.hinge.active || m.hinge.failed;
    }
    members.push_back(m);
    used[nd[0]] = used[nd[1]] = 1;
    const Vec2 dir = unit(model.coord(nd[1]) - model.coord(nd[0]), Vec2::Zero());
    awaySum[nd[0]] -= dir;
    awaySum[nd[1]] += dir;
  }
  auto restrained = [&](int n) {
    const auto& b = model.bound(n);
    return b[0] != 0 || b[1] != 0 || b[2] != 0;
  };

  // World bounding box of everything drawn.
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  auto grow = [&](const Vec2& p) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
    xmin = std::min(xmin, p.x());
    xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y());
    ymax = std::max(ymax, p.y());
  };
  for (int n = 0; n < numNodes; ++n) {
    if (!model.hasCoord(n) || !used[n]) continue;  // nodes no element holds are not drawn
    grow(deformed(n));
    if (undeformed_) grow(model.coord(n));
  }
  if (!(xmin <= xmax)) xmin = xmax = ymin = ymax = 0;
  if (model.ground()) {
    ymin = std::min(ymin, model.ground()->y0);
    ymax = std::max(ymax, model.ground()->y0);
  }
  const double wx = xmax - xmin, wy = ymax - ymin;

  // One scale for both axes, as large as the size limits allow.
  const bool anyActive = std::any_of(members.begin(), members.end(),
                                     [](const Member& m) { return m.hasHinge && !m.hinge.failed; });
  const bool anyFailed = std::any_of(members.begin(), members.end(),
                                     [](const Member& m) { return m.hasHinge && m.hinge.failed; });
  const bool anyJoint = !model.joints().empty();
  const bool showKey = key_ && (anyActive || anyFailed || anyJoint);
  // Key items and the scale bar's text: their widths decide the bottom rows.
  struct KeyItem {
    int kind;  // 0 active hinge, 1 failed hinge, 2 joint
    const char* label;
  };
  std::vector<KeyItem> keyItems;
  if (showKey && anyActive) keyItems.push_back({0, "active hinge"});
  if (showKey && anyFailed) keyItems.push_back({1, "failed hinge"});
  if (showKey && anyJoint) keyItems.push_back({2, "joint"});
  double keyW = 0;
  for (const KeyItem& it : keyItems) keyW += 16 + textWidth(it.label, kFontText) + 14;
  const double extent = std::max(wx, wy);
  const bool bar = scaleBar_ && extent > 0;
  const double barLen = bar ? SvgChart::niceNumber(extent / 5, true) : 0;  // model units
  std::string barLabel, note;
  if (bar) barLabel = formatNumber("%g", barLen) + (unit_.empty() ? "" : " " + unit_);
  if (scale_ != 1) note = "displacements \xC3\x97" + formatNumber("%g", scale_);

  const double top = (title_.empty() ? 0 : 34) + 24;
  double s = 1, width = 0, bottom = 0, barEnd = 0;
  int rows = 0;
  // One scale for both axes, as large as the size limits allow; the key moves to
  // a row of its own when it does not fit beside the scale bar.
  for (int attempt = 0; attempt < 2; ++attempt) {
    const bool firstRow = bar || !note.empty() || !keyItems.empty();
    rows = !firstRow ? 0 : attempt == 0 ? 1 : 2;
    bottom = 30 + 22 * rows + 6;
    const double availW = maxWidth_ - 2 * kSide, availH = maxHeight_ - top - bottom;
    s = 1;
    if (extent > 0) {
      const double sx = wx > 1e-12 * extent ? availW / wx : std::numeric_limits<double>::infinity();
      const double sy = wy > 1e-12 * extent ? availH / wy : std::numeric_limits<double>::infinity();
      s = std::min(sx, sy);
    }
    barEnd = 14;
    if (bar) barEnd += barLen * s + 6 + textWidth(barLabel, kFontText);
    if (!note.empty()) barEnd += (bar ? 16 : 0) + textWidth(note, kFontText);
    const double rowW = rows == 1 ? barEnd + (keyItems.empty() ? 0 : 24 + keyW) : std::max(barEnd, keyW + 24);
    // Canvas: tight around the drawing, wide enough for the title and the bottom row(s).
    width = std::min(maxWidth_, std::max({wx * s + 2 * kSide, textWidth(title_, kFontTitle) + 2 * kSide, rowW + 10}));
    if (rows != 1 || keyItems.empty() || rowW + 10 <= width) break;
  }
  const double height = wy * s + top + bottom;
  const double ox = 0.5 * (width - wx * s);  // drawing centred horizontally
  auto P = [&](const Vec2& x) { return Vec2(ox + (x.x() - xmin) * s, top + (ymax - x.y()) * s); };

  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << px(width) << "\" height=\""
    << px(height) << "\" viewBox=\"0 0 " << px(width) << ' ' << px(height)
    << "\" font-family=\"sans-serif\" font-size=\"" << px(kFontText) << "\">\n";
  if (!title_.empty()) o << "<title>" << xmlEscape(title_) << "</title>\n";
  o << "<rect width=\"" << px(width) << "\" height=\"" << px(height) << "\" fill=\"white\"/>\n";

  if (model.ground()) {
    const double gy = P(Vec2(0, model.ground()->y0)).y();
    std::ostringstream base, hatch;
    Pen b{base}, h{hatch};
    b.line(Vec2(8, gy), Vec2(width - 8, gy));
    for (double x = 12; x <= width - 8; x += 8) h.line(Vec2(x, gy), Vec2(x - 7, gy + 7));
    o << "<g class=\"ground\"><path stroke=\"#555555\" stroke-width=\"0.7\" d=\"" << hatch.str()
      << "\"/><path stroke=\"black\" stroke-width=\"1.3\" d=\"" << base.str() << "\"/></g>\n";
  }

  if (undeformed_) {
    o << "<path class=\"undeformed\" fill=\"none\" stroke=\"#9a9a9a\" stroke-width=\"0.9\" "
         "stroke-dasharray=\"5,3\" d=\"";
    for (const Member& m : members) {
      const Vec2 a = P(model.coord(m.a)), b = P(model.coord(m.b));
      o << "M" << px(a.x()) << ' ' << px(a.y()) << "L" << px(b.x()) << ' ' << px(b.y());
    }
    o << "\"/>\n";
  }

  // Supports, at the deformed node (a prescribed displacement moves the support).
  {
    std::ostringstream base, hatch, fill;
    Pen b{base}, h{hatch};
    for (int n = 0; n < numNodes; ++n) {
      if (!model.hasCoord(n) || !used[n] || !restrained(n)) continue;
      const auto& code = model.bound(n);
      const bool ru = code[0] != 0, rv = code[1] != 0, rr = code[2] != 0;
      const Vec2 c = P(deformed(n));
      if (!std::isfinite(c.x()) || !std::isfinite(c.y())) continue;
      // Away from the structure, in px (y down); straight down when undecided.
      const Vec2 awayWorld = unit(awaySum[n], Vec2(0, -1));
      const Vec2 away(awayWorld.x(), -awayWorld.y());
      const Vec2 vertical(0, away.y() < -0.5 ? -1 : 1);    // below unless the members hang down
      const Vec2 horizontal(away.x() > 0.5 ? 1 : -1, 0);   // left unless the members go left
      const double g = kGlyph;
      if (ru && rv && rr) {  // clamped
        hatchedSurface(b, h, c, away, g);
      } else if (ru && rv) {  // pinned: triangle on a hatched surface
        const Vec2 a = vertical, t(-a.y(), a.x());
        fill << "M" << px(c.x()) << ' ' << px(c.y()) << "L" << px((c + 13 * a + 8 * t).x()) << ' '
             << px((c + 13 * a + 8 * t).y()) << "L" << px((c + 13 * a - 8 * t).x()) << ' '
             << px((c + 13 * a - 8 * t).y()) << "Z";
        hatchedSurface(b, h, c + 13 * a, a, g);
      } else if (ru != rv && !rr) {  // roller: triangle on two wheels
        const Vec2 a = rv ? vertical : horizontal, t(-a.y(), a.x());
        fill << "M" << px(c.x()) << ' ' << px(c.y()) << "L" << px((c + 11 * a + 8 * t).x()) << ' '
             << px((c + 11 * a + 8 * t).y()) << "L" << px((c + 11 * a - 8 * t).x()) << ' '
             << px((c + 11 * a - 8 * t).y()) << "Z";
        for (double k : {-4.5, 4.5}) {
          const Vec2 w = c + 13.2 * a + k * t;
          fill << "M" << px(w.x() - 2.2) << ' ' << px(w.y()) << "a2.2 2.2 0 1 0 4.4 0a2.2 2.2 0 1 0 -4.4 0Z";
        }
        hatchedSurface(b, h, c + 15.5 * a, a, g);
      } else if (ru != rv && rr) {  // sliding clamp: clamped plate on wheels
        const Vec2 a = rv ? vertical : horizontal, t(-a.y(), a.x());
        b.line(c - g * t, c + g * t);
        for (double k : {-6.0, 6.0}) {
          const Vec2 w = c + 2.6 * a + k * t;
          fill << "M" << px(w.x() - 2.2) << ' ' << px(w.y()) << "a2.2 2.2 0 1 0 4.4 0a2.2 2.2 0 1 0 -4.4 0Z";
        }
        hatchedSurface(b, h, c + 5 * a, a, g);
      } else if (rr) {  // rotation only
        fill << "M" << px(c.x() - 3.5) << ' ' << px(c.y() - 3.5) << "h7v7h-7Z";
      }
    }
    o << "<g class=\"supports\"><path stroke=\"#444444\" stroke-width=\"0.7\" d=\"" << hatch.str()
      << "\"/><path stroke=\"black\" stroke-width=\"1.6\" d=\"" << base.str()
      << "\"/><path fill=\"white\" stroke=\"black\" stroke-width=\"1.1\" d=\"" << fill.str() << "\"/></g>\n";
  }

  // Deformed members. World tangents map to px by flipping y.
  auto tangent = [&](const Member& m, int node) -> std::optional<Vec2> {
    if (!curved_) return std::nullopt;
    const Vec2 d = model.coord(m.b) - model.coord(m.a);
    const double phi = std::atan2(d.y(), d.x()) + scale_ * stateValue(state.u, node, 2);
    if (!std::isfinite(phi)) return std::nullopt;
    return Vec2(std::cos(phi), -std::sin(phi));
  };
  auto segment = [&](std::ostringstream& d, const Vec2& p, const Vec2& q, const std::optional<Vec2>& tp,
                     const std::optional<Vec2>& tq) {
    if (!tp && !tq) {
      d << "L" << px(q.x()) << ' ' << px(q.y());
      return;
    }
    const double third = (q - p).norm() / 3;
    const Vec2 c1 = tp ? Vec2(p + third * *tp) : Vec2(p + (q - p) / 3);
    const Vec2 c2 = tq ? Vec2(q - third * *tq) : Vec2(q - (q - p) / 3);
    d << "C" << px(c1.x()) << ' ' << px(c1.y()) << ' ' << px(c2.x()) << ' ' << px(c2.y()) << ' ' << px(q.x())
      << ' ' << px(q.y());
  };
  std::vector<std::pair<Vec2, bool>> hingeMarks;  // position (px), failed
  o << "<g class=\"deformed\" fill=\"none\" stroke=\"black\" stroke-width=\"1.8\" stroke-linecap=\"round\" "
       "stroke-linejoin=\"round\">\n";
  for (std::size_t k = 0; k < members.size(); ++k) {
    const Member& m = members[k];
    const Vec2 a = P(deformed(m.a)), b = P(deformed(m.b));
    if (!a.allFinite() || !b.allFinite()) continue;
    std::ostringstream d;
    d << "M" << px(a.x()) << ' ' << px(a.y());
    if (m.hasHinge) {
      const double pos = std::clamp(m.hinge.position, 0.0, 1.0);
      const Vec2 hp = a + pos * (b - a);
      segment(d, a, hp, tangent(m, m.a), std::nullopt);
      segment(d, hp, b, std::nullopt, tangent(m, m.b));
      hingeMarks.emplace_back(hp, m.hinge.failed);
    } else {
      segment(d, a, b, tangent(m, m.a), tangent(m, m.b));
    }
    o << "<path class=\"member\" d=\"" << d.str() << "\"/>\n";
  }
  o << "</g>\n";

  if (nodes_) {
    o << "<g class=\"nodes\" fill=\"black\">\n";
    for (int n = 0; n < numNodes; ++n) {
      if (!used[n] || !model.hasCoord(n)) continue;
      const Vec2 p = P(deformed(n));
      if (p.allFinite())
        o << "<circle cx=\"" << px(p.x()) << "\" cy=\"" << px(p.y()) << "\" r=\"2.2\"/>\n";
    }
    o << "</g>\n";
  }

  for (const Joint& j : model.joints())
    if (validNode(j.master) && model.hasCoord(j.master)) {
      const Vec2 p = P(deformed(j.master));
      if (p.allFinite()) jointCircle(o, p);
    }
  for (const auto& [p, failed] : hingeMarks) {
    if (failed)
      crossedCircle(o, p, kHingeRadius + 1);
    else
      activeHinge(o, p);
  }

  // Bottom rows: scale bar and displacement factor on the left, symbol key on the right.
  const double rowY = height - 6 - 22 * rows + 11;  // centre line of the first row
  if (bar) {
    const double x0 = 14, x1 = x0 + barLen * s;
    o << "<g class=\"scale-bar\"><path stroke=\"black\" stroke-width=\"1.5\" fill=\"none\" d=\"M" << px(x0) << ' '
      << px(rowY - 4) << "V" << px(rowY + 4) << "M" << px(x0) << ' ' << px(rowY) << "H" << px(x1) << "M"
      << px(x1) << ' ' << px(rowY - 4) << "V" << px(rowY + 4) << "\"/><text x=\"" << px(x1 + 6) << "\" y=\""
      << px(rowY + 4) << "\">" << xmlEscape(barLabel) << "</text></g>\n";
  }
  if (!note.empty())
    o << "<text class=\"scale-note\" x=\"" << px(barEnd - textWidth(note, kFontText)) << "\" y=\"" << px(rowY + 4)
      << "\">" << xmlEscape(note) << "</text>\n";
  if (!keyItems.empty()) {
    const double y = rows == 1 ? rowY : rowY + 22;
    double x = width - 10 - keyW;
    o << "<g class=\"key\">\n";
    for (const KeyItem& it : keyItems) {
      const Vec2 p(x + 6, y);
      if (it.kind == 0) activeHinge(o, p);
      if (it.kind == 1) crossedCircle(o, p, kHingeRadius + 1);
      if (it.kind == 2) jointCircle(o, p);
      o << "<text x=\"" << px(x + 16) << "\" y=\"" << px(y + 4) << "\">" << it.label << "</text>\n";
      x += 16 + textWidth(it.label, kFontText) + 14;
    }
    o << "</g>\n";
  }
  if (!title_.empty()) o << svgTitle(title_, 0.5 * width, 26, kFontTitle, width - 16);
  o << "</svg>\n";
  return o.str();
}

void SvgFrame::save(const std::filesystem::path& path, const Model& model, const State& state) const {
  AtomicFile::write(path, svg(model, state));
}

}  // namespace c2d
