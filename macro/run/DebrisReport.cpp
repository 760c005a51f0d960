#include "macro/run/DebrisReport.h"

#include <cstdio>
#include <utility>

#include "core/io/AtomicFile.h"
#include "macro/output/NumberText.h"
#include "macro/output/SvgDebris.h"
#include "macro/run/RunOutputs.h"

namespace c2d {

namespace {

std::string shortTime(double t) { return formatNumber("%.4g", t); }

}  // namespace

DebrisReport::DebrisReport(const RunOptions& options, std::string problemTitle)
    : outDir_(options.outDir),
      stem_(options.stem),
      label_(options.label),
      problemTitle_(std::move(problemTitle)),
      pictures_(options.pictures) {}

bool DebrisReport::write(std::ostream& log, const DebrisFigures& d) const {
  log << "\n" << debrisLogLines(d);
  const std::filesystem::path csv = outDir_ / (stem_ + "_debris.csv");
  const std::vector<std::string> zones = zoneNames(d);
  AtomicFile::write(csv, debrisCsvHeader(zones) + "\n" + debrisCsvRow(d, zones) + "\n");
  log << "  debris: " << csv.filename().string() << "\n";
  return plotted_;
}

void DebrisReport::plot(std::ostream& log, const Model& model, const State& s,
                        const DebrisFigures& d) {
  std::string title = RunOutputs::displayTitle(problemTitle_);
  if (!label_.empty()) title += (title.empty() ? "" : ", ") + label_;
  title += (title.empty() ? "" : ": ") + std::string("debris at t = ") + shortTime(s.t);
  const std::filesystem::path path = outDir_ / (stem_ + "_debris.svg");
  if (pictures_) saveDebrisSvg(path, model, s, d, title);
  plotted_ = true;
  log << "  PLOT   debris: " << path.filename().string() << "\n";
}

}  // namespace c2d
