#pragma once
// [ext] The protected zones of a plan judged over its runs (SITE's zones,
// macro/output/DebrisZones.h): per zone the share of runs whose debris bed hit it with
// its 95 % Wilson interval, the mass there, the exact upper bound on the
// probability of a hit at the site's confidence and the runs without a hit that
// would show it below the site's risk level (BinomialBound.h), and the share of
// runs with flying fragments in it. Across the zones: the share of runs that
// hit any, the mean mass in them and the 95 % reach toward the protected sides,
// on which the plans are ranked.
#include <string>
#include <vector>

#include "macro/studies/EnsembleTable.h"

namespace c2d {

struct ZoneStats {
  std::string name;
  int runs = 0, hits = 0, flyrockRuns = 0;
  double p = 0, lo = 0, hi = 1;              // share hit, 95 % Wilson
  double massMedian = 0, massMax = 0;        // the bed's mass there (t)
  double bound = 1;                          // exact upper bound at the confidence
  long long needed = -1;                     // runs that would show p < level (-1: none)
  bool shown = false;                        // bound < level now
  double pFlyrock = 0, pFlyrockLo = 0, pFlyrockHi = 1;
};

struct ProtectedStats {
  std::vector<ZoneStats> zones;
  int runs = 0, anyHits = 0;
  double pAny = 0, pAnyLo = 0, pAnyHi = 1;
  double meanMass = 0;        // mean over the runs of the mass in every zone
  double medianReach95 = 0;   // median of the 95 % reach toward the protected sides
  double level = 0.01, confidence = 0.95;
};

// The 95 % reach of a run toward the sides that are protected zones ("left",
// "right"), or toward either side when neither is.
double protectedReach95(const EnsembleRun& r, const std::vector<std::string>& zones);
// The run's debris hit some protected zone.
bool hitsProtected(const EnsembleRun& r, const std::vector<std::string>& zones);

// The statistics of the runs (those with debris figures) for the table's zones.
ProtectedStats protectedStatistics(const std::vector<std::string>& zones,
                                   const std::vector<const EnsembleRun*>& runs);

}  // namespace c2d
