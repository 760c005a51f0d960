#include "macro/studies/CurveOverlay.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "core/io/AtomicFile.h"
#include "macro/deck/Limits.h"
#include "macro/studies/Csv.h"
#include "macro/studies/EnsembleTable.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

const char* kCurvesHeader =
    "run,label,title,written,x_column,y_column,x_label,y_label,x_scale,y_scale,x,y";

}  // namespace

void CurveOverlay::add(int run, const std::string& runLabel, const std::string& title,
                       const std::vector<CurveData>& curves) {
  runs_.push_back({run, runLabel, RunOutputs::displayTitle(title), curves});
}

std::vector<std::filesystem::path> CurveOverlay::write(const std::filesystem::path& outDir,
                                                       const std::string& stem) const {
  struct Group {
    CurveSpec spec;
    std::string title;
    std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> series;
  };
  std::vector<Group> groups;
  for (const Run& r : runs_)
    for (const CurveData& c : r.curves) {
      Group* g = nullptr;
      for (Group& h : groups)
        if (h.spec.sameAs(c.spec)) g = &h;
      if (!g) {
        groups.push_back({c.spec, r.title, {}});
        g = &groups.back();
      }
      g->series.emplace_back(r.label, c.points);
    }
  std::vector<std::filesystem::path> out;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const Group& g = groups[i];
    if (g.series.size() < 2) continue;
    // Two curves of the same columns with other labels or scales: tell the files apart.
    int same = 0;
    for (std::size_t k = 0; k < i; ++k) same += groups[k].spec.fileName() == g.spec.fileName();
    std::string name = stem + '_' + g.spec.fileName();
    if (same) name += '_' + std::to_string(same + 1);
    name += ".svg";
    const std::filesystem::path path = outDir / name;
    AtomicFile::write(path, RunOutputs::curveSvg(g.title, g.spec, g.series));
    out.push_back(path);
  }
  return out;
}

std::string CurveOverlay::csv() const {
  std::string out = std::string(kCurvesHeader) + "\n";
  for (const Run& r : runs_)
    for (const CurveData& c : r.curves) {
      std::string head = std::to_string(r.run);
      for (const std::string& t : {r.label, r.title, c.spec.written, c.spec.xColumn, c.spec.yColumn,
                                   c.spec.xLabel, c.spec.yLabel})
        appendCell(head, csvCell(t));
      appendCell(head, exactNumber(c.spec.xScale));
      appendCell(head, exactNumber(c.spec.yScale));
      // A curve without points keeps one row with empty x, y (it still counts
      // as the run's curve).
      if (c.points.empty()) out += head + ",,\n";
      for (const auto& [x, y] : c.points) {
        out += head;
        appendCell(out, exactNumber(x));
        appendCell(out, exactNumber(y));
        out += '\n';
      }
    }
  return out;
}

void CurveOverlay::addCsv(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != kCurvesHeader)
    throw std::runtime_error("its header is not a curves table's (" + std::string(kCurvesHeader) +
                             ")");
  if (text.back() != '\n') throw std::runtime_error("it ends in the middle of a row");
  int lineNo = 1;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty()) continue;
    const std::vector<std::string> c = splitCsv(line);
    const std::string bad = "line " + std::to_string(lineNo) + " is not a curve point";
    if (c.size() != 12) throw std::runtime_error(bad);
    const auto run = countCell(c[0], 1, DeckLimits::kMaxRuns);
    const auto sx = numberCell(c[8]), sy = numberCell(c[9]);
    // A curve without points keeps one row with empty x, y.
    const bool noPoint = c[10].empty() && c[11].empty();
    double x = 0, y = 0;
    if (!noPoint) {
      const auto px = numberCell(c[10]), py = numberCell(c[11]);
      if (!px || !py) throw std::runtime_error(bad);
      x = *px;
      y = *py;
    }
    if (!run || !sx || !sy) throw std::runtime_error(bad);
    CurveSpec spec;
    spec.written = c[3];
    spec.xColumn = c[4];
    spec.yColumn = c[5];
    spec.xLabel = c[6];
    spec.yLabel = c[7];
    spec.xScale = *sx;
    spec.yScale = *sy;
    if (runs_.empty() || runs_.back().run != *run || runs_.back().label != c[1])
      runs_.push_back({*run, c[1], c[2], {}});
    Run& r = runs_.back();
    if (r.curves.empty() || !r.curves.back().spec.sameAs(spec) ||
        r.curves.back().spec.xColumn != spec.xColumn ||
        r.curves.back().spec.yColumn != spec.yColumn)
      r.curves.push_back({spec, {}});
    if (!noPoint) r.curves.back().points.emplace_back(x, y);
  }
}

void CurveOverlay::sortByRun() {
  std::stable_sort(runs_.begin(), runs_.end(),
                   [](const Run& a, const Run& b) { return a.run < b.run; });
}

}  // namespace c2d
