#include "macro/studies/ZoneStatistics.h"

#include <algorithm>
#include <cmath>

#include "macro/studies/BinomialBound.h"
#include "macro/studies/Statistics.h"

namespace c2d {

namespace {

bool has(const std::vector<std::string>& zones, const char* name) {
  return std::find(zones.begin(), zones.end(), name) != zones.end();
}

double figureOr(const EnsembleRun& r, const std::string& name, double dflt) {
  const double v = r.figure(name);
  return std::isnan(v) ? dflt : v;
}

}  // namespace

double protectedReach95(const EnsembleRun& r, const std::vector<std::string>& zones) {
  const bool left = has(zones, "left"), right = has(zones, "right");
  if (left == right) return std::max(r.figure("left95"), r.figure("right95"));
  return left ? r.figure("left95") : r.figure("right95");
}

bool hitsProtected(const EnsembleRun& r, const std::vector<std::string>& zones) {
  return std::any_of(zones.begin(), zones.end(),
                     [&](const std::string& z) { return figureOr(r, "hit_" + z, 0) > 0; });
}

ProtectedStats protectedStatistics(const std::vector<std::string>& zones,
                                   const std::vector<const EnsembleRun*>& runs) {
  ProtectedStats s;
  s.runs = static_cast<int>(runs.size());
  for (const EnsembleRun* r : runs) {
    const double level = r->figure("risk_level"), confidence = r->figure("risk_confidence");
    if (!std::isnan(level) && !std::isnan(confidence)) {
      s.level = level;
      s.confidence = confidence;
      break;
    }
  }
  std::vector<double> reach;
  for (const EnsembleRun* r : runs) {
    s.anyHits += hitsProtected(*r, zones);
    for (const std::string& z : zones) s.meanMass += figureOr(*r, "mass_" + z, 0);
    reach.push_back(protectedReach95(*r, zones));
  }
  if (s.runs == 0) return s;
  s.meanMass /= s.runs;
  s.medianReach95 = quantile(reach, 0.5);
  s.pAny = static_cast<double>(s.anyHits) / s.runs;
  std::tie(s.pAnyLo, s.pAnyHi) = wilsonInterval(s.anyHits, s.runs);
  for (const std::string& name : zones) {
    ZoneStats z;
    z.name = name;
    std::vector<double> mass;
    for (const EnsembleRun* r : runs) {
      const double m = r->figure("mass_" + name);
      if (std::isnan(m)) continue;  // the run's site had no such zone
      ++z.runs;
      mass.push_back(m);
      z.hits += figureOr(*r, "hit_" + name, 0) > 0;
      z.flyrockRuns += figureOr(*r, "flyrock_count_" + name, 0) > 0;
    }
    if (z.runs > 0) {
      z.p = static_cast<double>(z.hits) / z.runs;
      std::tie(z.lo, z.hi) = wilsonInterval(z.hits, z.runs);
      z.massMedian = quantile(mass, 0.5);
      z.massMax = *std::max_element(mass.begin(), mass.end());
      z.pFlyrock = static_cast<double>(z.flyrockRuns) / z.runs;
      std::tie(z.pFlyrockLo, z.pFlyrockHi) = wilsonInterval(z.flyrockRuns, z.runs);
    }
    z.bound = clopperPearsonUpper(z.hits, z.runs, s.confidence);
    z.shown = z.bound < s.level;
    z.needed = runsToShowBelow(z.hits, z.runs, s.level, s.confidence);
    s.zones.push_back(std::move(z));
  }
  return s;
}

}  // namespace c2d
