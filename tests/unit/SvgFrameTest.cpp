// SvgFrame: well-formed SVG, one path per element, equal scaling of x and y,
// deformed positions from the state, hinge and joint symbols where they belong,
// supports from the restraint codes, ground, and curves leaving nodes at the
// nodal rotation.
#include "macro/output/SvgFrame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "tests/unit/OutputTestSupport.h"

namespace c2d {
namespace {

using testing::ReportingElement;
using testing::XmlNode;
using testing::XmlReader;

// Portal frame: columns 0-1 and 3-2 of height 3, beam 1-2 of length 4.
Model portal() {
  Model m;
  m.addNode(Vec2(0, 0));
  m.addNode(Vec2(0, 3));
  m.addNode(Vec2(4, 3));
  m.addNode(Vec2(4, 0));
  m.setElement(0, std::make_unique<ReportingElement>(0, 1, 1));
  m.setElement(1, std::make_unique<ReportingElement>(1, 2, 2));
  m.setElement(2, std::make_unique<ReportingElement>(3, 2, 1));
  m.bound(0) = {1, 1, 1};  // clamped
  m.bound(3) = {1, 1, 0};  // pinned
  return m;
}

ReportingElement& reporting(Model& m, int e) { return dynamic_cast<ReportingElement&>(m.element(e)); }

struct Segment {
  Vec2 a, b;
};

// Vertices of a path of absolute M/L commands.
std::vector<Vec2> vertices(const XmlNode& path) {
  std::istringstream in(path.attr("d"));
  std::vector<Vec2> v;
  char c;
  Vec2 p;
  while (in >> c >> p.x() >> p.y()) {
    EXPECT_TRUE(c == 'M' || c == 'L') << c;
    v.push_back(p);
  }
  return v;
}

// A straight member path "M x y L x y".
Segment straight(const XmlNode& path) {
  std::istringstream in(path.attr("d"));
  char m, l;
  Segment s;
  in >> m >> s.a.x() >> s.a.y() >> l >> s.b.x() >> s.b.y();
  EXPECT_EQ(m, 'M');
  EXPECT_EQ(l, 'L');
  EXPECT_TRUE(in.eof() || (in >> std::ws).eof()) << path.attr("d");
  return s;
}

Vec2 circleCentre(const XmlNode& c) { return Vec2(std::stod(c.attr("cx")), std::stod(c.attr("cy"))); }

TEST(SvgFrame, WellFormedWithOnePathPerElement) {
  Model m = portal();
  State st;
  st.resize(m.numNodes());
  const XmlNode root = XmlReader::parse(SvgFrame().setTitle("portal, t = 1.25 s").svg(m, st));
  EXPECT_EQ(root.name, "svg");
  EXPECT_EQ(root.attr("version"), "1.1");
  EXPECT_EQ(root.attr("font-family"), "sans-serif");
  EXPECT_TRUE(root.has("viewBox"));
  EXPECT_EQ(root.all("path", "member").size(), 3u);
  const auto undeformed = root.all("path", "undeformed");
  ASSERT_EQ(undeformed.size(), 1u);
  const std::string d = undeformed[0]->attr("d");
  EXPECT_EQ(std::count(d.begin(), d.end(), 'M'), 3);
  EXPECT_EQ(undeformed[0]->attr("stroke-dasharray"), "5,3");
  bool title = false;
  for (const XmlNode* t : root.all("text", "title")) title = title || t->text == "portal, t = 1.25 s";
  EXPECT_TRUE(title);
  EXPECT_TRUE(root.all("g", "key").empty());  // nothing to explain
  EXPECT_TRUE(root.all("g", "ground").empty());
}

TEST(SvgFrame, LongTitleFitsInThePicture) {
  Model m = portal();
  State st;
  st.resize(m.numNodes());
  const std::string title =
      "six-story two-bay frame, 288 elements: collapse with the energy decaying scheme (alpha = 0.1, "
      "beta = 0.1), gravity and ground contact (ks = -393, Mu = 120): step 4267, t = 158.25";
  const XmlNode root = XmlReader::parse(SvgFrame().setTitle(title).svg(m, st));
  const auto t = root.all("text", "title");
  ASSERT_EQ(t.size(), 1u);
  const double w = t[0]->has("textLength") ? std::stod(t[0]->attr("textLength"))
                                           : 0.56 * std::stod(t[0]->attr("font-size")) * title.size();
  const double x = std::stod(t[0]->attr("x")), width = std::stod(root.attr("width"));
  EXPECT_GE(x - 0.5 * w, 0.0);
  EXPECT_LE(x + 0.5 * w, width);
}

TEST(SvgFrame, EqualScalingOfBothAxes) {
  Model m = portal();
  State st;
  st.resize(m.numNodes());
  const XmlNode root = XmlReader::parse(SvgFrame().setCurved(false).svg(m, st));
  const auto members = root.all("path", "member");
  ASSERT_EQ(members.size(), 3u);
  const Segment column = straight(*members[0]), beam = straight(*members[1]);
  EXPECT_NEAR(column.a.x(), column.b.x(), 0.011);  // vertical stays vertical
  EXPECT_NEAR(beam.a.y(), beam.b.y(), 0.011);
  EXPECT_GT(column.a.y(), column.b.y());  // y up in the model, down in SVG
  const double columnPx = (column.b - column.a).norm(), beamPx = (beam.b - beam.a).norm();
  EXPECT_NEAR(columnPx / beamPx, 3.0 / 4.0, 1e-3);
  // The drawing fills the default 640 x 600 box in its limiting direction.
  EXPECT_GT(beamPx, 400);
}

TEST(SvgFrame, DeformedPositionsAreCoordinatesPlusScaledDisplacements) {
  Model m = portal();
  State st;
  st.resize(m.numNodes());
  st.u[1 * 3 + 0] = 0.05;   // sway of node 1
  st.u[2 * 3 + 0] = 0.05;   // and node 2
  st.u[2 * 3 + 1] = -0.02;  // node 2 sags
  const XmlNode plain = XmlReader::parse(SvgFrame().setCurved(false).setShowUndeformed(false).svg(m, st));
  const XmlNode scaled =
      XmlReader::parse(SvgFrame().setCurved(false).setShowUndeformed(false).setDisplacementScale(10).svg(m, st));
  // Pixels per metre from the bottom of the left column to the bottom of the right one.
  auto pixelsPerMetre = [](const XmlNode& root) {
    const auto mem = root.all("path", "member");
    return (straight(*mem[2]).a - straight(*mem[0]).a).norm() / 4.0;
  };
  for (const XmlNode* root : {&plain, &scaled}) {
    const double factor = root == &plain ? 1 : 10;
    const double s = pixelsPerMetre(*root);
    const auto mem = root->all("path", "member");
    const Segment col = straight(*mem[0]), right = straight(*mem[2]);
    const Vec2 top1 = col.b, top2 = right.b, base0 = col.a;
    EXPECT_NEAR((top1.x() - base0.x()) / s, factor * 0.05, 2e-4 * factor);
    EXPECT_NEAR((base0.y() - top1.y()) / s, 3.0, 2e-3);
    EXPECT_NEAR((top2.x() - base0.x()) / s, 4 + factor * 0.05, 2e-3);
    EXPECT_NEAR((base0.y() - top2.y()) / s, 3.0 - factor * 0.02, 2e-3);
  }
  bool note = false;
  for (const XmlNode* t : scaled.all("text", "scale-note")) note = note || t->text == "displacements ×10";
  EXPECT_TRUE(note);
}

TEST(SvgFrame, HingeSymbolsSitOnTheDeformedElement) {
  Model m = portal();
  reporting(m, 1).hingeInfo = {true, false, 0.25, 0.01, 100, 0.01};  // active, a quarter along the beam
  reporting(m, 2).hingeInfo = {true, true, 1.0, 0.08, 0, 0.08};      // failed, at the top of the right column
  State st;
  st.resize(m.numNodes());
  st.u[1 * 3 + 0] = 0.1;
  st.u[2 * 3 + 0] = 0.1;
  const XmlNode root = XmlReader::parse(SvgFrame().setCurved(false).svg(m, st));
  // An element with a hinge is drawn through the hinge point.
  const auto beam = vertices(*root.all("path", "member")[1]);
  ASSERT_EQ(beam.size(), 3u);
  const Vec2 a = beam[0], h = beam[1], b = beam[2];
  EXPECT_NEAR((h - (a + 0.25 * (b - a))).norm(), 0, 0.02);

  std::vector<const XmlNode*> active, failed;
  for (const XmlNode& child : root.children) {  // the key's samples are inside <g class="key">
    if (child.name == "circle" && child.attr("class") == "hinge-active") active.push_back(&child);
    if (child.name == "g" && child.attr("class") == "hinge-failed") failed.push_back(&child);
  }
  ASSERT_EQ(active.size(), 1u);
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_NEAR((circleCentre(*active[0]) - h).norm(), 0, 0.02);
  EXPECT_EQ(active[0]->attr("fill"), "#D62728");
  const auto right = vertices(*root.all("path", "member")[2]);
  ASSERT_EQ(right.size(), 3u);
  EXPECT_NEAR((circleCentre(*failed[0]->all("circle")[0]) - right.back()).norm(), 0, 0.02);
  // The key explains both symbols.
  const auto key = root.all("g", "key");
  ASSERT_EQ(key.size(), 1u);
  std::vector<std::string> labels;
  for (const XmlNode* t : key[0]->all("text")) labels.push_back(t->text);
  EXPECT_EQ(labels, (std::vector<std::string>{"active hinge", "failed hinge"}));
}

TEST(SvgFrame, JointsAreOpenCirclesAtTheMasterNode) {
  Model m = portal();
  const int slave = m.addNode(m.coord(2));
  m.element(2).setNodes({3, slave});
  m.joints().push_back({2, slave, JointForm::Condensed});
  State st;
  st.resize(m.numNodes());
  const XmlNode root = XmlReader::parse(SvgFrame().setCurved(false).svg(m, st));
  std::vector<const XmlNode*> joints;
  for (const XmlNode& child : root.children)
    if (child.name == "circle" && child.attr("class") == "joint") joints.push_back(&child);
  ASSERT_EQ(joints.size(), 1u);
  EXPECT_EQ(joints[0]->attr("fill"), "white");
  const Segment beam = straight(*root.all("path", "member")[1]);
  EXPECT_NEAR((circleCentre(*joints[0]) - beam.b).norm(), 0, 0.02);
}

TEST(SvgFrame, SupportsFollowTheRestraintCodes) {
  // Closed shapes in the supports' fill path: a pin is one triangle, a roller a
  // triangle and two wheels, a clamp none (a hatched line).
  auto closedShapes = [](const Model& m) {
    State st;
    st.resize(m.numNodes());
    const XmlNode root = XmlReader::parse(SvgFrame().svg(m, st));
    const auto g = root.all("g", "supports");
    EXPECT_EQ(g.size(), 1u);
    const std::string d = g[0]->all("path")[2]->attr("d");
    return std::count(d.begin(), d.end(), 'Z');
  };
  Model m = portal();
  EXPECT_EQ(closedShapes(m), 1);
  m.bound(3) = {0, 1, 0};
  EXPECT_EQ(closedShapes(m), 3);
  m.bound(3) = {1, 1, 1};
  EXPECT_EQ(closedShapes(m), 0);
  m.bound(0) = {0, 0, 0};
  m.bound(3) = {0, 0, 0};
  State st;
  st.resize(m.numNodes());
  const XmlNode bare = XmlReader::parse(SvgFrame().svg(m, st));
  for (const XmlNode* p : bare.all("g", "supports")[0]->all("path")) EXPECT_EQ(p->attr("d"), "");
}

TEST(SvgFrame, GroundLineAtItsLevel) {
  Model m = portal();
  m.ground() = Ground{-1.0, 1e6, 0};
  State st;
  st.resize(m.numNodes());
  const XmlNode root = XmlReader::parse(SvgFrame().setCurved(false).svg(m, st));
  const auto g = root.all("g", "ground");
  ASSERT_EQ(g.size(), 1u);
  const auto paths = g[0]->all("path");
  ASSERT_EQ(paths.size(), 2u);
  const Segment line = straight(*paths[1]);
  const Segment column = straight(*root.all("path", "member")[0]);
  const double s = (column.a - column.b).norm() / 3.0;
  EXPECT_NEAR(line.a.y(), line.b.y(), 1e-9);
  EXPECT_NEAR((line.a.y() - column.a.y()) / s, 1.0, 1e-3);  // one metre below the column base
  const std::string hatch = paths[0]->attr("d");
  EXPECT_GT(std::count(hatch.begin(), hatch.end(), 'M'), 20);
}

TEST(SvgFrame, CurvesLeaveNodesAtTheNodalRotation) {
  Model m;
  m.addNode(Vec2(0, 0));
  m.addNode(Vec2(2, 0));
  m.setElement(0, std::make_unique<ReportingElement>(0, 1, 1));
  State st;
  st.resize(2);
  st.u[1 * 3 + 1] = -0.2;
  st.u[1 * 3 + 2] = -0.15;  // end rotation, clockwise
  const XmlNode root = XmlReader::parse(SvgFrame().setScaleBar(false).svg(m, st));
  std::istringstream in(root.all("path", "member")[0]->attr("d"));
  char c;
  Vec2 a, c1, c2, b;
  in >> c >> a.x() >> a.y() >> c;
  ASSERT_EQ(c, 'C');
  in >> c1.x() >> c1.y() >> c2.x() >> c2.y() >> b.x() >> b.y();
  // Start: zero rotation, the tangent along the undeformed axis.
  EXPECT_NEAR(c1.y(), a.y(), 0.011);
  EXPECT_NEAR((c1 - a).norm(), (b - a).norm() / 3, 0.02);
  // End: tangent at -0.15 rad (y flipped in SVG).
  const Vec2 t = (b - c2).normalized();
  EXPECT_NEAR(std::atan2(-t.y(), t.x()), -0.15, 1e-3);
}

TEST(SvgFrame, SaveWritesTheSameText) {
  testing::DeckTempDir dir;
  Model m = portal();
  State st;
  st.resize(m.numNodes());
  SvgFrame f;
  f.setTitle("saved");
  f.save(dir / "frame.svg", m, st);
  EXPECT_EQ(testing::readText(dir / "frame.svg"), f.svg(m, st));
}

}  // namespace
}  // namespace c2d
