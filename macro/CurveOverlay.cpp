#include "macro/CurveOverlay.h"

#include "core/AtomicFile.h"

namespace c2d {

void CurveOverlay::add(const std::string& runLabel, const std::string& title,
                       const std::vector<CurveData>& curves) {
  for (const CurveData& c : curves) {
    Group* g = nullptr;
    for (Group& h : groups_)
      if (h.spec.sameAs(c.spec)) g = &h;
    if (!g) {
      groups_.push_back({c.spec, RunOutputs::displayTitle(title), {}});
      g = &groups_.back();
    }
    g->series.emplace_back(runLabel, c.points);
  }
}

std::vector<std::filesystem::path> CurveOverlay::write(const std::filesystem::path& outDir,
                                                       const std::string& stem) const {
  std::vector<std::filesystem::path> out;
  for (std::size_t i = 0; i < groups_.size(); ++i) {
    const Group& g = groups_[i];
    if (g.series.size() < 2) continue;
    // Two curves of the same columns with other labels or scales: tell the files apart.
    int same = 0;
    for (std::size_t k = 0; k < i; ++k) same += groups_[k].spec.fileName() == g.spec.fileName();
    std::string name = stem + '_' + g.spec.fileName();
    if (same) name += '_' + std::to_string(same + 1);
    name += ".svg";
    const std::filesystem::path path = outDir / name;
    AtomicFile::write(path, RunOutputs::curveSvg(g.title, g.spec, g.series));
    out.push_back(path);
  }
  return out;
}

}  // namespace c2d
