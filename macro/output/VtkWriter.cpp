#include "macro/output/VtkWriter.h"

#include <charconv>
#include <cstdio>
#include <sstream>
#include <vector>

#include "core/Hinge.h"
#include "macro/output/SvgChart.h"  // xmlEscape
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

// Shortest text that reads back to the same double.
std::string num(double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

double stateValue(const Eigen::VectorXd& x, int node, int dof) {
  const Eigen::Index i = static_cast<Eigen::Index>(node) * kNodeDofs + dof;
  return i < x.size() ? x[i] : 0.0;
}

std::string fileName(const std::filesystem::path& stem, int step) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "_%04d.vtu", step);
  return stem.filename().string() + buf;
}

// The element list may hold empty slots (setElement grows it): skipped, not dereferenced.
const Element* elementOrNull(const Model& model, int e) { return model.elements()[e].get(); }

const char* kPvdHeader =
    "<?xml version=\"1.0\"?>\n"
    "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    "  <Collection>\n";
const char* kPvdFooter =
    "  </Collection>\n"
    "</VTKFile>\n";

}  // namespace

VtkWriter::VtkWriter(std::filesystem::path stem)
    : stem_(std::move(stem)), pvd_(collectionPath(), kPvdHeader, kPvdFooter) {}

std::filesystem::path VtkWriter::collectionPath() const {
  std::filesystem::path p = stem_;
  p += ".pvd";
  return p;
}

std::filesystem::path VtkWriter::stepPath(int step) const {
  return stem_.parent_path() / fileName(stem_, step);
}

std::filesystem::path VtkWriter::write(const Model& model, const State& state, double time) {
  const std::filesystem::path path = stepPath(count_);
  AtomicFile::write(path, unstructuredGrid(model, state));
  // The .pvd sits beside the .vtu files: it names them without a directory.
  pvd_.append("    <DataSet timestep=\"" + timeText(time) + "\" group=\"\" part=\"0\" file=\"" +
              xmlEscape(fileName(stem_, count_)) + "\"/>\n");
  pvd_.sync();
  ++count_;
  return path;
}

std::string VtkWriter::timeText(double t) { return formatNumber("%.12g", t == 0 ? 0.0 : t); }

namespace {

// A line cell: its two nodes and its element.
struct GridCell {
  std::array<int, 2> nodes;
  const Element* element;
};

// The elements whose nodes exist, in element order.
std::vector<GridCell> gridCells(const Model& model) {
  const int numNodes = model.numNodes();
  std::vector<GridCell> cells;
  for (int e = 0; e < model.numElements(); ++e) {
    const Element* el = elementOrNull(model, e);
    if (!el) continue;
    const auto nd = el->nodes();
    if (nd[0] < 0 || nd[0] >= numNodes || nd[1] < 0 || nd[1] >= numNodes) continue;
    cells.push_back({nd, el});
  }
  return cells;
}

void openArray(std::ostringstream& o, const char* type, const char* name, int components) {
  o << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\"";
  if (components > 1) o << " NumberOfComponents=\"" << components << "\"";
  o << " format=\"ascii\">\n";
}

const char* const kCloseArray = "        </DataArray>\n";

// The nodes' displacement, rotation, velocity and joint flag.
void writePointData(std::ostringstream& o, const Model& model, const State& state) {
  const int numNodes = model.numNodes();
  std::vector<char> inJoint(numNodes, 0);
  for (const Joint& j : model.joints())
    for (int n : {j.master, j.slave})
      if (n >= 0 && n < numNodes) inJoint[n] = 1;
  o << "      <PointData Vectors=\"displacement\" Scalars=\"rotation\">\n";
  openArray(o, "Float64", "displacement", 3);
  for (int n = 0; n < numNodes; ++n)
    o << num(stateValue(state.u, n, 0)) << ' ' << num(stateValue(state.u, n, 1)) << " 0\n";
  o << kCloseArray;
  openArray(o, "Float64", "rotation", 1);
  for (int n = 0; n < numNodes; ++n) o << num(stateValue(state.u, n, 2)) << '\n';
  o << kCloseArray;
  openArray(o, "Float64", "velocity", 3);
  for (int n = 0; n < numNodes; ++n)
    o << num(stateValue(state.v, n, 0)) << ' ' << num(stateValue(state.v, n, 1)) << " 0\n";
  o << kCloseArray;
  openArray(o, "UInt8", "joint", 1);
  for (int n = 0; n < numNodes; ++n) o << int(inJoint[n]) << '\n';
  o << kCloseArray;
  o << "      </PointData>\n";
}

// The cells' section forces, material and hinge (state 0 none, 1 active, 2
// failed; its jump and position).
void writeCellData(std::ostringstream& o, const std::vector<GridCell>& cells) {
  o << "      <CellData Scalars=\"M\">\n";
  std::vector<SectionForces> forces;
  std::vector<HingeInfo> hinges;
  std::vector<int> hingeState;
  for (const GridCell& c : cells) {
    forces.push_back(c.element->sectionForces());
    const auto* h = dynamic_cast<const HingeCarrier*>(c.element);
    hinges.push_back(h ? h->hinge() : HingeInfo{});
    const HingeInfo& hi = hinges.back();
    hingeState.push_back(hi.failed ? 2 : hi.active ? 1 : 0);
  }
  auto cellColumn = [&](const char* type, const char* name, auto value) {
    openArray(o, type, name, 1);
    for (std::size_t k = 0; k < cells.size(); ++k) o << value(k) << '\n';
    o << kCloseArray;
  };
  cellColumn("Float64", "N", [&](std::size_t k) { return num(forces[k].N); });
  cellColumn("Float64", "V", [&](std::size_t k) { return num(forces[k].V); });
  cellColumn("Float64", "M", [&](std::size_t k) { return num(forces[k].M); });
  cellColumn("Int32", "material", [&](std::size_t k) { return cells[k].element->materialNumber(); });
  cellColumn("Int32", "hinge_state", [&](std::size_t k) { return hingeState[k]; });
  cellColumn("Float64", "hinge_jump", [&](std::size_t k) { return num(hingeState[k] ? hinges[k].jump : 0.0); });
  cellColumn("Float64", "hinge_position",
             [&](std::size_t k) { return num(hingeState[k] ? hinges[k].position : 0.0); });
  o << "      </CellData>\n";
}

// The deformed positions.
void writePoints(std::ostringstream& o, const Model& model, const State& state) {
  o << "      <Points>\n";
  o << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int n = 0; n < model.numNodes(); ++n) {
    const Vec2& x = model.coord(n);
    o << num(x.x() + stateValue(state.u, n, 0)) << ' ' << num(x.y() + stateValue(state.u, n, 1))
      << " 0\n";
  }
  o << kCloseArray << "      </Points>\n";
}

// The line cells: connectivity, offsets, types.
void writeCells(std::ostringstream& o, const std::vector<GridCell>& cells) {
  o << "      <Cells>\n";
  openArray(o, "Int64", "connectivity", 1);
  for (const GridCell& c : cells) o << c.nodes[0] << ' ' << c.nodes[1] << '\n';
  o << kCloseArray;
  openArray(o, "Int64", "offsets", 1);
  for (std::size_t k = 0; k < cells.size(); ++k) o << 2 * (k + 1) << '\n';
  o << kCloseArray;
  openArray(o, "UInt8", "types", 1);
  for (std::size_t k = 0; k < cells.size(); ++k) o << "3\n";  // VTK_LINE
  o << kCloseArray;
  o << "      </Cells>\n";
}

}  // namespace

std::string VtkWriter::unstructuredGrid(const Model& model, const State& state) {
  const std::vector<GridCell> cells = gridCells(model);
  std::ostringstream o;
  o << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <UnstructuredGrid>\n"
    << "    <Piece NumberOfPoints=\"" << model.numNodes() << "\" NumberOfCells=\"" << cells.size()
    << "\">\n";
  writePointData(o, model, state);
  writeCellData(o, cells);
  writePoints(o, model, state);
  writeCells(o, cells);
  o << "    </Piece>\n"
    << "  </UnstructuredGrid>\n"
    << "</VTKFile>\n";
  return o.str();
}

}  // namespace c2d
