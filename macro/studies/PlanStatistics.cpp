#include "macro/studies/PlanStatistics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "macro/studies/Csv.h"
#include "macro/studies/Statistics.h"
#include "macro/output/NumberText.h"

namespace c2d {

const std::vector<std::string> kPlanFigures = {"left",     "right",  "left95",      "right95",
                                               "centroid", "height", "outside_mass"};

namespace {

std::string num(double v) { return std::isnan(v) ? std::string() : formatNumber("%.6e", v); }

std::string share(double v) { return formatNumber("%.6g", v); }

double reach95(const EnsembleRun& r) { return std::max(r.figure("left95"), r.figure("right95")); }

}  // namespace

std::vector<PlanStats> planStatistics(const EnsembleData& data) {
  std::map<int, std::vector<const EnsembleRun*>> byPlan;
  for (const EnsembleRun& r : data.runs) byPlan[r.plan].push_back(&r);
  std::vector<PlanStats> out;
  for (const auto& [plan, runs] : byPlan) {
    PlanStats s;
    s.plan = plan;
    s.swept = runs.front()->swept;
    SweepValues values;
    for (std::size_t i = 0; i < data.swept.size() && i < s.swept.size(); ++i)
      values.emplace_back(data.swept[i], s.swept[i]);
    s.name = runs.front()->name;
    s.label = !s.name.empty()   ? s.name
              : values.empty() ? "plan " + std::to_string(plan)
                               : sweepLabel(values);
    s.samples = static_cast<int>(runs.size());
    std::vector<const EnsembleRun*> debris;
    for (const EnsembleRun* r : runs) {
      if (!r->ok) ++s.failed;
      if (r->ok && r->debris) debris.push_back(r);
    }
    s.debrisRuns = static_cast<int>(debris.size());
    for (const std::string& f : kPlanFigures) {
      std::vector<double> v;
      for (const EnsembleRun* r : debris) v.push_back(r->figure(f));
      std::array<double, 5> q{NAN, NAN, NAN, NAN, NAN};
      if (!v.empty())
        q = {*std::min_element(v.begin(), v.end()), quantile(v, 0.1), quantile(v, 0.5),
             quantile(v, 0.9), *std::max_element(v.begin(), v.end())};
      s.quantiles.push_back(q);
    }
    std::vector<double> reach;
    for (const EnsembleRun* r : debris) {
      reach.push_back(reach95(*r));
      s.site = s.site || r->site != "none";
      s.outside += r->outside();
      s.moving += !r->atRest;
      s.verdicts += !r->verdict.empty();
      s.felled += r->felled();
    }
    s.protection = protectedStatistics(data.zones, debris);
    if (s.verdicts > 0) {
      s.pFelled = static_cast<double>(s.felled) / s.verdicts;
      std::tie(s.pFelledLo, s.pFelledHi) = wilsonInterval(s.felled, s.verdicts);
    }
    s.medianReach95 = reach.empty() ? NAN : quantile(reach, 0.5);
    const int n = s.debrisRuns;
    if (n > 0) {
      s.pOutside = static_cast<double>(s.outside) / n;
      std::tie(s.pOutsideLo, s.pOutsideHi) = wilsonInterval(s.outside, n);
      s.pMoving = static_cast<double>(s.moving) / n;
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::string plansCsv(const EnsembleData& data, const std::vector<PlanStats>& plans) {
  std::string out = data.named ? "plan,name" : "plan";
  for (const std::string& n : data.swept) appendCell(out, csvCell(n));
  out += ",samples,failed";
  for (const std::string& f : kPlanFigures)
    for (const char* q : {"_min", "_p10", "_median", "_p90", "_max"}) appendCell(out, f + q);
  out += ",p_outside,p_outside_lo,p_outside_hi,p_moving,p_felled,p_felled_lo,p_felled_hi";
  for (const std::string& z : data.zones)
    for (const std::string& c :
         {"p_" + z, "p_" + z + "_lo", "p_" + z + "_hi", "mass_" + z + "_median",
          "mass_" + z + "_max", "p_" + z + "_bound", "runs_" + z + "_needed", "p_flyrock_" + z,
          "p_flyrock_" + z + "_lo", "p_flyrock_" + z + "_hi"})
      appendCell(out, csvCell(c));
  if (!data.zones.empty()) out += ",p_protected,p_protected_lo,p_protected_hi,protected_mass_mean";
  out += '\n';
  for (const PlanStats& s : plans) {
    out += std::to_string(s.plan);
    if (data.named) appendCell(out, csvCell(s.name));
    for (double v : s.swept) appendCell(out, exactSweepValue(v));
    appendCell(out, std::to_string(s.samples));
    appendCell(out, std::to_string(s.failed));
    for (const auto& q : s.quantiles)
      for (double v : q) appendCell(out, num(v));
    const bool known = s.site && s.debrisRuns > 0;
    for (double v : {s.pOutside, s.pOutsideLo, s.pOutsideHi})
      appendCell(out, known ? share(v) : "");
    appendCell(out, s.debrisRuns > 0 ? share(s.pMoving) : "");
    for (double v : {s.pFelled, s.pFelledLo, s.pFelledHi})
      appendCell(out, s.verdicts > 0 ? share(v) : "");
    const ProtectedStats& g = s.protection;
    for (const ZoneStats& z : g.zones) {
      const bool any = z.runs > 0;
      for (double v : {z.p, z.lo, z.hi}) appendCell(out, any ? share(v) : "");
      for (double v : {z.massMedian, z.massMax}) appendCell(out, any ? num(v) : "");
      appendCell(out, any ? share(z.bound) : "");
      appendCell(out, z.needed >= 0 ? std::to_string(z.needed) : "");
      for (double v : {z.pFlyrock, z.pFlyrockLo, z.pFlyrockHi}) appendCell(out, any ? share(v) : "");
    }
    if (!data.zones.empty()) {
      for (double v : {g.pAny, g.pAnyLo, g.pAnyHi}) appendCell(out, g.runs > 0 ? share(v) : "");
      appendCell(out, g.runs > 0 ? num(g.meanMass) : "");
    }
    out += '\n';
  }
  return out;
}

namespace {

// A share with its interval: "0.150 [0.052, 0.360]".
std::string shareText(double p, double lo, double hi) {
  char b[64];
  std::snprintf(b, sizeof b, "%.3f [%.3f, %.3f]", p, lo, hi);
  return b;
}

std::string tripleText(const std::array<double, 5>& q) {
  char b[64];
  std::snprintf(b, sizeof b, "%.3g / %.3g / %.3g", q[1], q[2], q[3]);
  return std::isnan(q[2]) ? "-" : b;
}

// A table of text columns, each as wide as its widest cell.
struct TextColumn {
  std::string head;
  std::vector<std::string> cells;
  bool left = true;
};

std::string formatColumns(const std::vector<TextColumn>& cols, std::size_t rows) {
  std::vector<std::size_t> w;
  for (const TextColumn& c : cols) {
    std::size_t width = c.head.size();
    for (const std::string& t : c.cells) width = std::max(width, t.size());
    w.push_back(width);
  }
  auto pad = [](const std::string& t, std::size_t width, bool left) {
    const std::string fill(width > t.size() ? width - t.size() : 0, ' ');
    return left ? t + fill : fill + t;
  };
  std::string out;
  for (std::size_t r = 0; r <= rows; ++r) {
    std::string line = " ";
    for (std::size_t c = 0; c < cols.size(); ++c) {
      line += ' ';
      line += pad(r == 0 ? cols[c].head : cols[c].cells[r - 1], w[c], cols[c].left);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + "\n";
  }
  return out;
}

}  // namespace

std::string plansText(const std::vector<PlanStats>& plans) {
  const bool verdicts = std::any_of(plans.begin(), plans.end(),
                                    [](const PlanStats& s) { return s.verdicts > 0; });
  std::vector<TextColumn> cols = {{"plan", {}, false}, {"", {}}, {"runs", {}, false},
                                  {"failed", {}, false}, {"p_outside [95 % Wilson]", {}}};
  if (verdicts) cols.push_back({"p_felled [95 % Wilson]", {}});
  cols.push_back({"p_moving", {}, false});
  cols.push_back({"left95 (m) p10/median/p90", {}});
  cols.push_back({"right95 (m) p10/median/p90", {}});
  cols.push_back({"centroid (m) p10/median/p90", {}});
  // Every protected zone's share hit (the names from the first plan with zones).
  std::vector<std::string> zones;
  for (const PlanStats& s : plans)
    if (zones.empty())
      for (const ZoneStats& z : s.protection.zones) zones.push_back(z.name);
  for (const std::string& z : zones) cols.push_back({"p_" + z + " [95 % Wilson]", {}});
  for (const PlanStats& s : plans) {
    const bool runs = s.debrisRuns > 0;
    char m[16];
    std::snprintf(m, sizeof m, "%.3f", s.pMoving);
    std::vector<std::string> row = {
        std::to_string(s.plan), s.label, std::to_string(s.samples), std::to_string(s.failed),
        s.site && runs ? shareText(s.pOutside, s.pOutsideLo, s.pOutsideHi) : "-"};
    if (verdicts)
      row.push_back(s.verdicts > 0 ? shareText(s.pFelled, s.pFelledLo, s.pFelledHi) : "-");
    row.push_back(runs ? m : "-");
    for (int f : {2, 3, 4}) row.push_back(tripleText(s.quantiles[f]));
    for (const std::string& name : zones) {
      const auto& zs = s.protection.zones;
      const auto z = std::find_if(zs.begin(), zs.end(),
                                  [&](const ZoneStats& x) { return x.name == name; });
      row.push_back(z != zs.end() && z->runs > 0 ? shareText(z->p, z->lo, z->hi) : "-");
    }
    for (std::size_t c = 0; c < cols.size(); ++c) cols[c].cells.push_back(row[c]);
  }
  return formatColumns(cols, plans.size());
}

std::string riskText(const std::vector<PlanStats>& plans) {
  std::string out;
  char buf[512];
  for (const PlanStats& s : plans) {
    const ProtectedStats& g = s.protection;
    for (const ZoneStats& z : g.zones) {
      if (out.empty()) {
        std::snprintf(buf, sizeof buf,
                      "  protected zones: is a hit shown less likely than %.3g at %.3g %% "
                      "confidence? (the exact binomial upper bound, Clopper-Pearson)\n",
                      g.level, 100 * g.confidence);
        out += buf;
      }
      std::string more;
      if (z.shown)
        more = "shown";
      else if (z.needed < 0)
        more = "NOT shown; no number of runs would show it";
      else
        more = "NOT shown; " + std::to_string(z.needed) + " runs with no more hits would (" +
               std::to_string(z.needed - z.runs) + " more)";
      std::snprintf(buf, sizeof buf, "    plan %d, %s: hit in %d of %d runs, p <= %.3g: %s\n",
                    s.plan, z.name.c_str(), z.hits, z.runs, z.bound, more.c_str());
      out += buf;
    }
  }
  return out;
}

namespace {

// What the ranking judges: with protected zones, the share of runs hitting any,
// the mean mass in them and the 95 % reach toward the protected sides; with a
// site but no zones (a table of an older program), p_outside and reach95.
struct Ranking {
  const EnsembleData& data;
  bool zones, site;
  double share(const PlanStats& s) const { return zones ? s.protection.pAny : s.pOutside; }
  double mass(const PlanStats& s) const { return zones ? s.protection.meanMass : 0.0; }
  double reach(const PlanStats& s) const {
    return zones ? s.protection.medianReach95 : s.medianReach95;
  }
  bool hit(const EnsembleRun& r) const {
    return zones ? hitsProtected(r, data.zones) : r.outside();
  }
  double reach(const EnsembleRun& r) const {
    return zones ? protectedReach95(r, data.zones) : reach95(r);
  }
  const char* shareName() const { return zones ? "p_protected" : "p_outside"; }
  bool before(const PlanStats& a, const PlanStats& b) const {
    if ((zones || site) && share(a) != share(b)) return share(a) < share(b);
    if (zones && mass(a) != mass(b)) return mass(a) < mass(b);
    return reach(a) < reach(b);
  }
};

std::string leadText(const Ranking& rank, const PlanStats& best, const PlanStats& next) {
  const EnsembleData& data = rank.data;
  char buf[512];
  std::string out;
  // The pairs: sample k of both plans, both with debris figures.
  std::map<int, const EnsembleRun*> a, b;
  for (const EnsembleRun& r : data.runs) {
    if (!r.ok || !r.debris) continue;
    if (r.plan == best.plan) a[r.sample] = &r;
    if (r.plan == next.plan) b[r.sample] = &r;
  }
  std::vector<double> diff;
  int onlyBest = 0, onlyNext = 0;
  for (const auto& [k, ra] : a) {
    const auto it = b.find(k);
    if (it == b.end()) continue;
    diff.push_back(rank.reach(*it->second) - rank.reach(*ra));
    onlyBest += rank.hit(*ra) && !rank.hit(*it->second);
    onlyNext += !rank.hit(*ra) && rank.hit(*it->second);
  }
  const int m = static_cast<int>(diff.size());
  std::snprintf(buf, sizeof buf, "  its lead over plan %d (%s) on %d paired runs:\n", next.plan,
                next.label.c_str(), m);
  out += buf;
  // The verdict of a test: significant, or the samples that would tell.
  auto verdict = [&](const PairedTest& t) {
    if (m < 2) return std::string(": too few pairs to judge\n");
    if (t.significant()) return std::string(": significant\n");
    // A lead far below the scatter (or none): more samples would not tell.
    if (!std::isfinite(t.samplesNeeded) || t.samplesNeeded > 100.0 * m)
      return std::string(": not significant; the two cannot be told apart (the difference is far "
                         "below the scatter)\n");
    char more[96];
    std::snprintf(more, sizeof more,
                  ": not significant; about %.0f samples per plan would tell them apart\n",
                  std::ceil(std::max(t.samplesNeeded, static_cast<double>(m) + 1)));
    return std::string(more);
  };
  // The share hit (or outside) decides first; the reach is compared in every case.
  if ((rank.zones || rank.site) && rank.share(best) < rank.share(next)) {
    const PairedTest share = mcNemarTest(onlyBest, onlyNext, m);
    std::snprintf(buf, sizeof buf,
                  "    %s %.3f against %.3f (%s in one plan only: %d and %d runs; "
                  "McNemar p = %.2g)",
                  rank.shareName(), rank.share(best), rank.share(next),
                  rank.zones ? "a protected zone hit" : "outside", onlyBest, onlyNext, share.p);
    out += buf;
    out += verdict(share);
  }
  const PairedTest reach = pairedTTest(diff);
  std::snprintf(buf, sizeof buf, "    reach95%s %.3g m %s on average (paired t = %.3g, p = %.2g)",
                rank.zones ? " toward the protected sides" : "", std::abs(reach.effect),
                reach.effect >= 0 ? "less" : "more", reach.statistic, reach.p);
  out += buf;
  out += verdict(reach);
  return out;
}

}  // namespace

std::string bestPlanText(const EnsembleData& data, const std::vector<PlanStats>& plans) {
  std::vector<const PlanStats*> ranked;
  for (const PlanStats& s : plans)
    if (s.debrisRuns > 0) ranked.push_back(&s);
  if (ranked.empty()) return {};
  const bool site =
      std::any_of(ranked.begin(), ranked.end(), [](const PlanStats* s) { return s->site; });
  const Ranking rank{data, !data.zones.empty(), site};
  std::stable_sort(ranked.begin(), ranked.end(),
                   [&](const PlanStats* a, const PlanStats* b) { return rank.before(*a, *b); });
  const PlanStats& best = *ranked.front();
  char buf[512];
  std::string out;
  std::snprintf(buf, sizeof buf, "  best plan: %d (%s): ", best.plan, best.label.c_str());
  out += buf;
  if (rank.zones) {
    const ProtectedStats& g = best.protection;
    std::snprintf(buf, sizeof buf,
                  "p_protected %.3f [%.3f, %.3f], mean mass in the protected zones %.3g t, "
                  "median reach95 toward the protected sides %.3g m (the least p_protected, "
                  "then mass, then reach)\n",
                  g.pAny, g.pAnyLo, g.pAnyHi, g.meanMass, g.medianReach95);
    out += buf;
  } else {
    if (site) {
      std::snprintf(buf, sizeof buf, "p_outside %.3f [%.3f, %.3f], ", best.pOutside,
                    best.pOutsideLo, best.pOutsideHi);
      out += buf;
    }
    std::snprintf(buf, sizeof buf, "median reach95 %.3g m (the least %s)\n", best.medianReach95,
                  site ? "p_outside, then reach" : "reach");
    out += buf;
  }
  if (ranked.size() < 2) return out;
  return out + leadText(rank, best, *ranked[1]);
}

}  // namespace c2d
