#include "macro/studies/EnsembleStudy.h"

#include <map>
#include <set>

#include "core/io/AtomicFile.h"
#include "macro/studies/EnsemblePicture.h"
#include "macro/studies/PlanStatistics.h"
#include "macro/studies/Sensitivity.h"

namespace c2d {

EnsembleStudyReport writeEnsembleStudy(const std::filesystem::path& dir, const std::string& stem,
                                       const EnsembleData& data, const std::string& title) {
  EnsembleStudyReport r;
  const std::vector<PlanStats> plans = planStatistics(data);
  const std::filesystem::path plansFile = dir / (stem + "_plans.csv");
  AtomicFile::write(plansFile, plansCsv(data, plans));
  r.files.push_back(plansFile);
  if (!data.drawn.empty()) {
    const std::filesystem::path f = dir / (stem + "_sensitivity.csv");
    AtomicFile::write(f, sensitivityCsv(data));
    r.files.push_back(f);
  }
  std::set<int> sampleSet;
  for (const EnsembleRun& run : data.runs) sampleSet.insert(run.sample);
  const std::string heading = title + (title.empty() ? "" : ": ") + std::to_string(plans.size()) +
                              (plans.size() == 1 ? " plan" : " plans") + " x " +
                              std::to_string(sampleSet.size()) + " samples";
  if (const std::string svg = ensembleSvg(data, plans, heading); !svg.empty()) {
    const std::filesystem::path f = dir / (stem + "_ensemble.svg");
    AtomicFile::write(f, svg);
    r.files.push_back(f);
  }
  std::set<int> samples;
  int failed = 0;
  for (const EnsembleRun& run : data.runs) {
    samples.insert(run.sample);
    failed += !run.ok;
  }
  std::string head = "  ensemble: " + std::to_string(plans.size()) + " plan" +
                     (plans.size() == 1 ? "" : "s") + " x " + std::to_string(samples.size()) +
                     " samples, " + std::to_string(data.runs.size()) + " runs, " +
                     std::to_string(failed) + " failed\n";
  r.summary = head + plansText(plans) + riskText(plans) + bestPlanText(data, plans);
  r.text = r.summary + sensitivityText(data);
  for (const auto& f : r.files) r.text += "  ensemble: " + f.filename().string() + "\n";
  return r;
}

}  // namespace c2d
