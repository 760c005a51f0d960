// ProblemRun's debris report: where the debris of a run with ground contact
// ends up (macro/output/Debris.h), as log lines, <stem>_debris.csv and the picture of
// PLOT,DEBRis.
#include <cstdio>

#include "core/io/AtomicFile.h"
#include "macro/output/SvgDebris.h"
#include "macro/run/ProblemRun.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

std::string shortTime(double t) { return formatNumber("%.4g", t); }

}  // namespace

void ProblemRun::reportDebris() {
  // Where the debris ends up, against the footprint and the site: the log's lines,
  // <stem>_debris.csv (one row), and the picture when PLOT,DEBRis asked for one.
  const DebrisFigures d = watches_.debrisNow(analysis_->state());
  if (d.leftNode < 0) return;
  watches_.setDebris(d);
  log_ << "\n" << debrisLogLines(d);
  const std::filesystem::path csv = options_.outDir / (options_.stem + "_debris.csv");
  const std::vector<std::string> zones = zoneNames(d);
  AtomicFile::write(csv, debrisCsvHeader(zones) + "\n" + debrisCsvRow(d, zones) + "\n");
  log_ << "  debris: " << csv.filename().string() << "\n";
  if (debrisPlot_) plotDebris();
}

void ProblemRun::plotDebris() {
  const State& s = outputState();
  const DebrisFigures d = watches_.debrisNow(s);
  std::string title = RunOutputs::displayTitle(problem_.title);
  if (!options_.label.empty()) title += (title.empty() ? "" : ", ") + options_.label;
  title += (title.empty() ? "" : ": ") + std::string("debris at t = ") + shortTime(s.t);
  const std::filesystem::path path = options_.outDir / (options_.stem + "_debris.svg");
  if (options_.pictures) saveDebrisSvg(path, model_, s, d, title);
  debrisPlot_ = true;
  log_ << "  PLOT   debris: " << path.filename().string() << "\n";
}

}  // namespace c2d
