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

namespace {

// A node's drawn position: its coordinates plus the scaled displacement.
struct Deformed {
  const Model& model;
  const State& state;
  double scale;
  Vec2 operator()(int n) const {
    return Vec2(model.coord(n) + scale * Vec2(stateValue(state.u, n, 0), stateValue(state.u, n, 1)));
  }
};

// An element drawn: its nodes and its hinge (active or failed).
struct Member {
  int a, b;
  HingeInfo hinge;
  bool hasHinge = false;
};

// What is drawn: the elements with valid nodes, the nodes they use, and at
// each node the sum of the directions away from it along its members.
struct DrawnMembers {
  std::vector<Member> members;
  std::vector<char> used;
  std::vector<Vec2> awaySum;
};

bool validNode(const Model& model, int n) { return n >= 0 && n < model.numNodes(); }

DrawnMembers drawnMembers(const Model& model) {
  const int numNodes = model.numNodes();
  DrawnMembers d;
  d.used.assign(numNodes, 0);
  d.awaySum.assign(numNodes, Vec2::Zero());
  for (int e = 0; e < model.numElements(); ++e) {
    const Element* slot = elementOrNull(model, e);
    if (!slot) continue;
    const Element& el = *slot;
    const auto nd = el.nodes();
    if (!validNode(model, nd[0]) || !validNode(model, nd[1])) continue;
    Member m{nd[0], nd[1], {}, false};
    if (const auto* h = dynamic_cast<const HingeCarrier*>(&el)) {
      m.hinge = h->hinge();
      m.hasHinge = m.hinge.active || m.hinge.failed;
    }
    d.members.push_back(m);
    d.used[nd[0]] = d.used[nd[1]] = 1;
    const Vec2 dir = unit(model.coord(nd[1]) - model.coord(nd[0]), Vec2::Zero());
    d.awaySum[nd[0]] -= dir;
    d.awaySum[nd[1]] += dir;
  }
  return d;
}

// The world box of everything drawn: the used nodes deformed (and undeformed
// when shown), the ground.
struct WorldBox {
  double xmin, xmax, ymin, ymax;
};

WorldBox worldBox(const Model& model, const DrawnMembers& drawn, const Deformed& deformed,
                  bool undeformed) {
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  auto grow = [&](const Vec2& p) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
    xmin = std::min(xmin, p.x());
    xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y());
    ymax = std::max(ymax, p.y());
  };
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n) || !drawn.used[n]) continue;  // nodes no element holds are not drawn
    grow(deformed(n));
    if (undeformed) grow(model.coord(n));
  }
  if (!(xmin <= xmax)) xmin = xmax = ymin = ymax = 0;
  if (model.ground()) {
    ymin = std::min(ymin, model.ground()->y0);
    ymax = std::max(ymax, model.ground()->y0);
  }
  return {xmin, xmax, ymin, ymax};
}

// A symbol of the key: 0 active hinge, 1 failed hinge, 2 joint.
struct KeyItem {
  int kind;
  const char* label;
};

std::vector<KeyItem> keyItems(const Model& model, const std::vector<Member>& members, bool key) {
  const bool anyActive = std::any_of(members.begin(), members.end(),
                                     [](const Member& m) { return m.hasHinge && !m.hinge.failed; });
  const bool anyFailed = std::any_of(members.begin(), members.end(),
                                     [](const Member& m) { return m.hasHinge && m.hinge.failed; });
  const bool anyJoint = !model.joints().empty();
  const bool showKey = key && (anyActive || anyFailed || anyJoint);
  std::vector<KeyItem> items;
  if (showKey && anyActive) items.push_back({0, "active hinge"});
  if (showKey && anyFailed) items.push_back({1, "failed hinge"});
  if (showKey && anyJoint) items.push_back({2, "joint"});
  return items;
}

// The picture's settings (SvgFrame's).
struct FrameLook {
  const std::string& title;
  double scale, maxWidth, maxHeight;
  bool scaleBar;
  const std::string& unit;
};

// The canvas: the scale and place of the drawing, the page's size, the bottom
// rows (scale bar, displacement factor, key) and their widths.
struct Canvas {
  double xmin = 0, ymax = 0;
  double s = 1, width = 0, height = 0, top = 0, bottom = 0, ox = 0;
  int rows = 0;
  bool bar = false;
  double barLen = 0, barEnd = 0, keyW = 0;
  std::string barLabel, note;
  Vec2 P(const Vec2& x) const { return Vec2(ox + (x.x() - xmin) * s, top + (ymax - x.y()) * s); }
};

// One scale for both axes, as large as the size limits allow; the key moves to
// a row of its own when it does not fit beside the scale bar. The canvas is
// tight around the drawing, wide enough for the title and the bottom row(s).
Canvas layoutCanvas(const WorldBox& box, const std::vector<KeyItem>& items, const FrameLook& look) {
  Canvas c;
  c.xmin = box.xmin;
  c.ymax = box.ymax;
  const double wx = box.xmax - box.xmin, wy = box.ymax - box.ymin;
  for (const KeyItem& it : items) c.keyW += 16 + textWidth(it.label, kFontText) + 14;
  const double extent = std::max(wx, wy);
  c.bar = look.scaleBar && extent > 0;
  c.barLen = c.bar ? SvgChart::niceNumber(extent / 5, true) : 0;  // model units
  if (c.bar) c.barLabel = formatNumber("%g", c.barLen) + (look.unit.empty() ? "" : " " + look.unit);
  if (look.scale != 1) c.note = "displacements \xC3\x97" + formatNumber("%g", look.scale);

  c.top = (look.title.empty() ? 0 : 34) + 24;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const bool firstRow = c.bar || !c.note.empty() || !items.empty();
    c.rows = !firstRow ? 0 : attempt == 0 ? 1 : 2;
    c.bottom = 30 + 22 * c.rows + 6;
    const double availW = look.maxWidth - 2 * kSide, availH = look.maxHeight - c.top - c.bottom;
    c.s = 1;
    if (extent > 0) {
      const double sx = wx > 1e-12 * extent ? availW / wx : std::numeric_limits<double>::infinity();
      const double sy = wy > 1e-12 * extent ? availH / wy : std::numeric_limits<double>::infinity();
      c.s = std::min(sx, sy);
    }
    c.barEnd = 14;
    if (c.bar) c.barEnd += c.barLen * c.s + 6 + textWidth(c.barLabel, kFontText);
    if (!c.note.empty()) c.barEnd += (c.bar ? 16 : 0) + textWidth(c.note, kFontText);
    const double rowW = c.rows == 1 ? c.barEnd + (items.empty() ? 0 : 24 + c.keyW)
                                    : std::max(c.barEnd, c.keyW + 24);
    c.width = std::min(look.maxWidth, std::max({wx * c.s + 2 * kSide,
                                                textWidth(look.title, kFontTitle) + 2 * kSide, rowW + 10}));
    if (c.rows != 1 || items.empty() || rowW + 10 <= c.width) break;
  }
  c.height = wy * c.s + c.top + c.bottom;
  c.ox = 0.5 * (c.width - wx * c.s);  // drawing centred horizontally
  return c;
}

void writeHead(std::ostringstream& o, const Canvas& c, const std::string& title) {
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << px(c.width) << "\" height=\""
    << px(c.height) << "\" viewBox=\"0 0 " << px(c.width) << ' ' << px(c.height)
    << "\" font-family=\"sans-serif\" font-size=\"" << px(kFontText) << "\">\n";
  if (!title.empty()) o << "<title>" << xmlEscape(title) << "</title>\n";
  o << "<rect width=\"" << px(c.width) << "\" height=\"" << px(c.height) << "\" fill=\"white\"/>\n";
}

void drawGround(std::ostringstream& o, const Canvas& c, const Model& model) {
  if (!model.ground()) return;
  const double gy = c.P(Vec2(0, model.ground()->y0)).y();
  std::ostringstream base, hatch;
  Pen b{base}, h{hatch};
  b.line(Vec2(8, gy), Vec2(c.width - 8, gy));
  for (double x = 12; x <= c.width - 8; x += 8) h.line(Vec2(x, gy), Vec2(x - 7, gy + 7));
  o << "<g class=\"ground\"><path stroke=\"#555555\" stroke-width=\"0.7\" d=\"" << hatch.str()
    << "\"/><path stroke=\"black\" stroke-width=\"1.3\" d=\"" << base.str() << "\"/></g>\n";
}

void drawUndeformed(std::ostringstream& o, const Canvas& c, const Model& model,
                    const std::vector<Member>& members) {
  o << "<path class=\"undeformed\" fill=\"none\" stroke=\"#9a9a9a\" stroke-width=\"0.9\" "
       "stroke-dasharray=\"5,3\" d=\"";
  for (const Member& m : members) {
    const Vec2 a = c.P(model.coord(m.a)), b = c.P(model.coord(m.b));
    o << "M" << px(a.x()) << ' ' << px(a.y()) << "L" << px(b.x()) << ' ' << px(b.y());
  }
  o << "\"/>\n";
}

// A wheel of a roller support at w.
void wheel(std::ostringstream& fill, const Vec2& w) {
  fill << "M" << px(w.x() - 2.2) << ' ' << px(w.y()) << "a2.2 2.2 0 1 0 4.4 0a2.2 2.2 0 1 0 -4.4 0Z";
}

// A triangle from c to the side at distance depth along a.
void supportTriangle(std::ostringstream& fill, const Vec2& c, const Vec2& a, const Vec2& t,
                     double depth) {
  fill << "M" << px(c.x()) << ' ' << px(c.y()) << "L" << px((c + depth * a + 8 * t).x()) << ' '
       << px((c + depth * a + 8 * t).y()) << "L" << px((c + depth * a - 8 * t).x()) << ' '
       << px((c + depth * a - 8 * t).y()) << "Z";
}

// One node's support symbol at c (px) from its restraint code; away: the
// direction away from the structure, in px (y down).
void supportSymbol(Pen& b, Pen& h, std::ostringstream& fill, const Vec2& c,
                   const std::array<int, kNodeDofs>& code, const Vec2& away) {
  const bool ru = code[0] != 0, rv = code[1] != 0, rr = code[2] != 0;
  const Vec2 vertical(0, away.y() < -0.5 ? -1 : 1);    // below unless the members hang down
  const Vec2 horizontal(away.x() > 0.5 ? 1 : -1, 0);   // left unless the members go left
  const double g = kGlyph;
  if (ru && rv && rr) {  // clamped
    hatchedSurface(b, h, c, away, g);
  } else if (ru && rv) {  // pinned: triangle on a hatched surface
    const Vec2 a = vertical, t(-a.y(), a.x());
    supportTriangle(fill, c, a, t, 13);
    hatchedSurface(b, h, c + 13 * a, a, g);
  } else if (ru != rv && !rr) {  // roller: triangle on two wheels
    const Vec2 a = rv ? vertical : horizontal, t(-a.y(), a.x());
    supportTriangle(fill, c, a, t, 11);
    for (double k : {-4.5, 4.5}) wheel(fill, c + 13.2 * a + k * t);
    hatchedSurface(b, h, c + 15.5 * a, a, g);
  } else if (ru != rv && rr) {  // sliding clamp: clamped plate on wheels
    const Vec2 a = rv ? vertical : horizontal, t(-a.y(), a.x());
    b.line(c - g * t, c + g * t);
    for (double k : {-6.0, 6.0}) wheel(fill, c + 2.6 * a + k * t);
    hatchedSurface(b, h, c + 5 * a, a, g);
  } else if (rr) {  // rotation only
    fill << "M" << px(c.x() - 3.5) << ' ' << px(c.y() - 3.5) << "h7v7h-7Z";
  }
}

// Supports, at the deformed node (a prescribed displacement moves the support).
void drawSupports(std::ostringstream& o, const Canvas& c, const Model& model,
                  const DrawnMembers& drawn, const Deformed& deformed) {
  std::ostringstream base, hatch, fill;
  Pen b{base}, h{hatch};
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!model.hasCoord(n) || !drawn.used[n]) continue;
    const auto& code = model.bound(n);
    if (!(code[0] != 0 || code[1] != 0 || code[2] != 0)) continue;
    const Vec2 p = c.P(deformed(n));
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) continue;
    // Away from the structure, in px (y down); straight down when undecided.
    const Vec2 awayWorld = unit(drawn.awaySum[n], Vec2(0, -1));
    supportSymbol(b, h, fill, p, code, Vec2(awayWorld.x(), -awayWorld.y()));
  }
  o << "<g class=\"supports\"><path stroke=\"#444444\" stroke-width=\"0.7\" d=\"" << hatch.str()
    << "\"/><path stroke=\"black\" stroke-width=\"1.6\" d=\"" << base.str()
    << "\"/><path fill=\"white\" stroke=\"black\" stroke-width=\"1.1\" d=\"" << fill.str() << "\"/></g>\n";
}

// A member's tangent at one of its nodes, in px (world tangents map to px by
// flipping y): the chord turned by the node's scaled rotation; none when the
// members are drawn straight.
std::optional<Vec2> memberTangent(const Model& model, const State& state, const Member& m, int node,
                                  bool curved, double scale) {
  if (!curved) return std::nullopt;
  const Vec2 d = model.coord(m.b) - model.coord(m.a);
  const double phi = std::atan2(d.y(), d.x()) + scale * stateValue(state.u, node, 2);
  if (!std::isfinite(phi)) return std::nullopt;
  return Vec2(std::cos(phi), -std::sin(phi));
}

// A piece from p to q: a cubic leaving along the tangents given, else a line.
void curveSegment(std::ostringstream& d, const Vec2& p, const Vec2& q, const std::optional<Vec2>& tp,
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
}

// The deformed members, kinked at their hinges; returns the hinges' marks
// (position in px, failed).
std::vector<std::pair<Vec2, bool>> drawDeformed(std::ostringstream& o, const Canvas& c,
                                                const Deformed& deformed,
                                                const std::vector<Member>& members, bool curved) {
  auto tangent = [&](const Member& m, int node) {
    return memberTangent(deformed.model, deformed.state, m, node, curved, deformed.scale);
  };
  std::vector<std::pair<Vec2, bool>> hingeMarks;
  o << "<g class=\"deformed\" fill=\"none\" stroke=\"black\" stroke-width=\"1.8\" stroke-linecap=\"round\" "
       "stroke-linejoin=\"round\">\n";
  for (const Member& m : members) {
    const Vec2 a = c.P(deformed(m.a)), b = c.P(deformed(m.b));
    if (!a.allFinite() || !b.allFinite()) continue;
    std::ostringstream d;
    d << "M" << px(a.x()) << ' ' << px(a.y());
    if (m.hasHinge) {
      const double pos = std::clamp(m.hinge.position, 0.0, 1.0);
      const Vec2 hp = a + pos * (b - a);
      curveSegment(d, a, hp, tangent(m, m.a), std::nullopt);
      curveSegment(d, hp, b, std::nullopt, tangent(m, m.b));
      hingeMarks.emplace_back(hp, m.hinge.failed);
    } else {
      curveSegment(d, a, b, tangent(m, m.a), tangent(m, m.b));
    }
    o << "<path class=\"member\" d=\"" << d.str() << "\"/>\n";
  }
  o << "</g>\n";
  return hingeMarks;
}

void drawNodes(std::ostringstream& o, const Canvas& c, const Model& model,
               const DrawnMembers& drawn, const Deformed& deformed) {
  o << "<g class=\"nodes\" fill=\"black\">\n";
  for (int n = 0; n < model.numNodes(); ++n) {
    if (!drawn.used[n] || !model.hasCoord(n)) continue;
    const Vec2 p = c.P(deformed(n));
    if (p.allFinite()) o << "<circle cx=\"" << px(p.x()) << "\" cy=\"" << px(p.y()) << "\" r=\"2.2\"/>\n";
  }
  o << "</g>\n";
}

// The joints' circles at their master nodes, then the hinges' marks.
void drawJointsAndHinges(std::ostringstream& o, const Canvas& c, const Model& model,
                         const Deformed& deformed,
                         const std::vector<std::pair<Vec2, bool>>& hingeMarks) {
  for (const Joint& j : model.joints())
    if (validNode(model, j.master) && model.hasCoord(j.master)) {
      const Vec2 p = c.P(deformed(j.master));
      if (p.allFinite()) jointCircle(o, p);
    }
  for (const auto& [p, failed] : hingeMarks) {
    if (failed)
      crossedCircle(o, p, kHingeRadius + 1);
    else
      activeHinge(o, p);
  }
}

// Bottom rows: scale bar and displacement factor on the left, symbol key on the right.
void drawBottomRows(std::ostringstream& o, const Canvas& c, const std::vector<KeyItem>& items) {
  const double rowY = c.height - 6 - 22 * c.rows + 11;  // centre line of the first row
  if (c.bar) {
    const double x0 = 14, x1 = x0 + c.barLen * c.s;
    o << "<g class=\"scale-bar\"><path stroke=\"black\" stroke-width=\"1.5\" fill=\"none\" d=\"M" << px(x0) << ' '
      << px(rowY - 4) << "V" << px(rowY + 4) << "M" << px(x0) << ' ' << px(rowY) << "H" << px(x1) << "M"
      << px(x1) << ' ' << px(rowY - 4) << "V" << px(rowY + 4) << "\"/><text x=\"" << px(x1 + 6) << "\" y=\""
      << px(rowY + 4) << "\">" << xmlEscape(c.barLabel) << "</text></g>\n";
  }
  if (!c.note.empty())
    o << "<text class=\"scale-note\" x=\"" << px(c.barEnd - textWidth(c.note, kFontText)) << "\" y=\""
      << px(rowY + 4) << "\">" << xmlEscape(c.note) << "</text>\n";
  if (items.empty()) return;
  const double y = c.rows == 1 ? rowY : rowY + 22;
  double x = c.width - 10 - c.keyW;
  o << "<g class=\"key\">\n";
  for (const KeyItem& it : items) {
    const Vec2 p(x + 6, y);
    if (it.kind == 0) activeHinge(o, p);
    if (it.kind == 1) crossedCircle(o, p, kHingeRadius + 1);
    if (it.kind == 2) jointCircle(o, p);
    o << "<text x=\"" << px(x + 16) << "\" y=\"" << px(y + 4) << "\">" << it.label << "</text>\n";
    x += 16 + textWidth(it.label, kFontText) + 14;
  }
  o << "</g>\n";
}

}  // namespace

std::string SvgFrame::svg(const Model& model, const State& state) const {
  const Deformed deformed{model, state, scale_};
  const DrawnMembers drawn = drawnMembers(model);
  const std::vector<KeyItem> items = keyItems(model, drawn.members, key_);
  const FrameLook look{title_, scale_, maxWidth_, maxHeight_, scaleBar_, unit_};
  const Canvas c = layoutCanvas(worldBox(model, drawn, deformed, undeformed_), items, look);

  std::ostringstream o;
  writeHead(o, c, title_);
  drawGround(o, c, model);
  if (undeformed_) drawUndeformed(o, c, model, drawn.members);
  drawSupports(o, c, model, drawn, deformed);
  const auto hingeMarks = drawDeformed(o, c, deformed, drawn.members, curved_);
  if (nodes_) drawNodes(o, c, model, drawn, deformed);
  drawJointsAndHinges(o, c, model, deformed, hingeMarks);
  drawBottomRows(o, c, items);
  if (!title_.empty()) o << svgTitle(title_, 0.5 * c.width, 26, kFontTitle, c.width - 16);
  o << "</svg>\n";
  return o.str();
}

void SvgFrame::save(const std::filesystem::path& path, const Model& model, const State& state) const {
  AtomicFile::write(path, svg(model, state));
}

}  // namespace c2d
