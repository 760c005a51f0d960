// VtkWriter: the .vtu holds one VTK_LINE cell per element with the element's
// nodes, deformed points and nodal values equal to the state (shortest
// round-trip printing: equal to the last bit), section forces and hinge states
// per cell, joint flags; the .pvd lists every written step with its time and is
// complete after each write.
#include "macro/output/VtkWriter.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <vector>

#include "tests/unit/OutputTestSupport.h"

namespace c2d {
namespace {

namespace fs = std::filesystem;
using testing::numbers;
using testing::ReportingElement;
using testing::XmlNode;
using testing::XmlReader;

struct Fixture {
  Model model;
  State state;
};

// Column 0-1, beam 1-2, and a beam 4-3 hinged to node 2 by a joint (4 is the slave).
Fixture sample() {
  Fixture f;
  Model& m = f.model;
  m.addNode(Vec2(0, 0));
  m.addNode(Vec2(0, 3.5));
  m.addNode(Vec2(5, 3.5));
  m.addNode(Vec2(10, 3.5));
  m.addNode(Vec2(5, 3.5));
  auto e0 = std::make_unique<ReportingElement>(0, 1, 1);
  e0->forces = {-123.456789, 7.25, 1.0 / 3.0};
  auto e1 = std::make_unique<ReportingElement>(1, 2, 2);
  e1->forces = {1e-17, -2.5e6, -98.7654321};
  e1->hingeInfo = {true, false, 0.1, 0.0123, 250, 0.0123};
  auto e2 = std::make_unique<ReportingElement>(4, 3, 2);
  e2->hingeInfo = {true, true, 0.9, -0.3, 0, 0.3};
  m.setElement(0, std::move(e0));
  m.setElement(1, std::move(e1));
  m.setElement(2, std::move(e2));
  m.joints().push_back({2, 4, JointForm::Condensed});
  f.state.resize(m.numNodes());
  for (int i = 0; i < f.state.u.size(); ++i) {
    f.state.u[i] = 0.001 * (i + 1) / 7.0 * (i % 2 ? -1 : 1);
    f.state.v[i] = 0.1 * std::sqrt(i + 2.0);
  }
  return f;
}

const XmlNode& dataArray(const XmlNode& section, const std::string& name) {
  for (const XmlNode& c : section.children)
    if (c.name == "DataArray" && c.attr("Name") == name) return c;
  throw std::runtime_error("no DataArray " + name);
}

const XmlNode& child(const XmlNode& n, const std::string& name) {
  for (const XmlNode& c : n.children)
    if (c.name == name) return c;
  throw std::runtime_error("no <" + name + "> in <" + n.name + ">");
}

TEST(VtkWriter, OneLineCellPerElementWithItsNodes) {
  const Fixture f = sample();
  const XmlNode root = XmlReader::parse(VtkWriter::unstructuredGrid(f.model, f.state));
  EXPECT_EQ(root.name, "VTKFile");
  EXPECT_EQ(root.attr("type"), "UnstructuredGrid");
  const XmlNode& piece = child(child(root, "UnstructuredGrid"), "Piece");
  EXPECT_EQ(piece.attr("NumberOfPoints"), "5");
  EXPECT_EQ(piece.attr("NumberOfCells"), "3");
  const XmlNode& cells = child(piece, "Cells");
  EXPECT_EQ(numbers(dataArray(cells, "connectivity").text), (std::vector<double>{0, 1, 1, 2, 4, 3}));
  EXPECT_EQ(numbers(dataArray(cells, "offsets").text), (std::vector<double>{2, 4, 6}));
  EXPECT_EQ(numbers(dataArray(cells, "types").text), (std::vector<double>{3, 3, 3}));
}

TEST(VtkWriter, PointValuesEqualTheState) {
  const Fixture f = sample();
  const XmlNode root = XmlReader::parse(VtkWriter::unstructuredGrid(f.model, f.state));
  const XmlNode& piece = child(child(root, "UnstructuredGrid"), "Piece");
  const XmlNode& pd = child(piece, "PointData");
  const auto disp = numbers(dataArray(pd, "displacement").text);
  const auto rot = numbers(dataArray(pd, "rotation").text);
  const auto vel = numbers(dataArray(pd, "velocity").text);
  const auto joint = numbers(dataArray(pd, "joint").text);
  const auto pts = numbers(child(child(piece, "Points"), "DataArray").text);
  EXPECT_EQ(dataArray(pd, "displacement").attr("NumberOfComponents"), "3");
  ASSERT_EQ(disp.size(), 15u);
  ASSERT_EQ(rot.size(), 5u);
  ASSERT_EQ(vel.size(), 15u);
  ASSERT_EQ(pts.size(), 15u);
  for (int n = 0; n < 5; ++n) {
    EXPECT_EQ(disp[3 * n], f.state.u[3 * n]);
    EXPECT_EQ(disp[3 * n + 1], f.state.u[3 * n + 1]);
    EXPECT_EQ(disp[3 * n + 2], 0.0);
    EXPECT_EQ(rot[n], f.state.u[3 * n + 2]);
    EXPECT_EQ(vel[3 * n], f.state.v[3 * n]);
    EXPECT_EQ(vel[3 * n + 1], f.state.v[3 * n + 1]);
    EXPECT_EQ(vel[3 * n + 2], 0.0);
    EXPECT_EQ(pts[3 * n], f.model.coord(n).x() + f.state.u[3 * n]);
    EXPECT_EQ(pts[3 * n + 1], f.model.coord(n).y() + f.state.u[3 * n + 1]);
    EXPECT_EQ(pts[3 * n + 2], 0.0);
  }
  EXPECT_EQ(joint, (std::vector<double>{0, 0, 1, 0, 1}));
}

TEST(VtkWriter, CellValuesEqualTheElementReports) {
  const Fixture f = sample();
  const XmlNode root = XmlReader::parse(VtkWriter::unstructuredGrid(f.model, f.state));
  const XmlNode& cd = child(child(child(root, "UnstructuredGrid"), "Piece"), "CellData");
  const auto N = numbers(dataArray(cd, "N").text), V = numbers(dataArray(cd, "V").text),
             M = numbers(dataArray(cd, "M").text);
  ASSERT_EQ(N.size(), 3u);
  for (int e = 0; e < 3; ++e) {
    const SectionForces s = f.model.element(e).sectionForces();
    EXPECT_EQ(N[e], s.N);
    EXPECT_EQ(V[e], s.V);
    EXPECT_EQ(M[e], s.M);
  }
  EXPECT_EQ(numbers(dataArray(cd, "material").text), (std::vector<double>{1, 2, 2}));
  EXPECT_EQ(numbers(dataArray(cd, "hinge_state").text), (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(numbers(dataArray(cd, "hinge_jump").text), (std::vector<double>{0, 0.0123, -0.3}));
  EXPECT_EQ(numbers(dataArray(cd, "hinge_position").text), (std::vector<double>{0, 0.1, 0.9}));
}

TEST(VtkWriter, EmptySlotsAndMissingStateAreTolerated) {
  Fixture f = sample();
  f.model.setElement(5, std::make_unique<ReportingElement>(0, 2, 3));  // slots 3 and 4 stay empty
  State empty;  // never resized: every nodal value reads as zero
  const XmlNode root = XmlReader::parse(VtkWriter::unstructuredGrid(f.model, empty));
  const XmlNode& piece = child(child(root, "UnstructuredGrid"), "Piece");
  EXPECT_EQ(piece.attr("NumberOfCells"), "4");
  EXPECT_EQ(numbers(dataArray(child(piece, "Cells"), "connectivity").text),
            (std::vector<double>{0, 1, 1, 2, 4, 3, 0, 2}));
  for (double d : numbers(dataArray(child(piece, "PointData"), "displacement").text)) EXPECT_EQ(d, 0.0);
  const auto pts = numbers(child(child(piece, "Points"), "DataArray").text);
  EXPECT_EQ(pts[3 * 3], 10.0);
}

TEST(VtkWriter, SeriesFilesAndCollectionValidAfterEveryStep) {
  testing::DeckTempDir dir;
  Fixture f = sample();
  VtkWriter writer(dir / "collapse");
  const std::vector<double> times = {0.0, 0.5, 1.25};
  for (std::size_t k = 0; k < times.size(); ++k) {
    f.state.u[3] = 0.01 * static_cast<double>(k);
    const fs::path vtu = writer.write(f.model, f.state, times[k]);
    EXPECT_EQ(vtu.filename().string(), "collapse_000" + std::to_string(k) + ".vtu");
    EXPECT_EQ(testing::readText(vtu), VtkWriter::unstructuredGrid(f.model, f.state));
    // The collection so far (under .part: the run is not complete) lists
    // exactly the steps written so far.
    EXPECT_FALSE(fs::exists(dir / "collapse.pvd"));
    const XmlNode pvd = XmlReader::parse(testing::readText(dir / "collapse.pvd.part"));
    EXPECT_EQ(pvd.attr("type"), "Collection");
    const auto sets = pvd.all("DataSet");
    ASSERT_EQ(sets.size(), k + 1);
    for (std::size_t j = 0; j <= k; ++j) {
      EXPECT_EQ(std::stod(sets[j]->attr("timestep")), times[j]);
      EXPECT_EQ(sets[j]->attr("file"), "collapse_000" + std::to_string(j) + ".vtu");
      EXPECT_TRUE(fs::exists(dir / sets[j]->attr("file")));
    }
  }
  EXPECT_EQ(writer.numWritten(), 3);
  EXPECT_EQ(writer.collectionPath(), dir / "collapse.pvd");
  writer.finish();
  const XmlNode done = XmlReader::parse(testing::readText(dir / "collapse.pvd"));
  EXPECT_EQ(done.all("DataSet").size(), 3u);
  for (const auto& entry : fs::directory_iterator(dir.path()))
    EXPECT_NE(entry.path().extension(), ".part") << entry.path();
}

TEST(VtkWriter, KeptCollectionOfAFailedRun) {
  testing::DeckTempDir dir;
  Fixture f = sample();
  VtkWriter writer(dir / "c");
  writer.write(f.model, f.state, 0);
  writer.write(f.model, f.state, 0.5);
  EXPECT_EQ(writer.keep("failed"), dir / "c.failed.pvd");
  const XmlNode pvd = XmlReader::parse(testing::readText(dir / "c.failed.pvd"));
  EXPECT_EQ(pvd.all("DataSet").size(), 2u);
  EXPECT_FALSE(fs::exists(dir / "c.pvd"));
  EXPECT_FALSE(fs::exists(dir / "c.pvd.part"));
}

TEST(VtkWriter, TimesWithoutRoundingNoise) {
  // Times reached by adding steps: printed as the deck's numbers.
  EXPECT_EQ(VtkWriter::timeText(0.1 + 0.2), "0.3");
  double t = 0;
  for (int i = 0; i < 1000; ++i) t += 0.01;
  EXPECT_EQ(VtkWriter::timeText(t), "10");
  EXPECT_EQ(VtkWriter::timeText(158.25), "158.25");
  EXPECT_EQ(VtkWriter::timeText(1e-9), "1e-09");
  EXPECT_EQ(VtkWriter::timeText(-0.0), "0");
}

}  // namespace
}  // namespace c2d
