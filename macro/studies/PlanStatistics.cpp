#include "macro/studies/PlanStatistics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "macro/studies/Csv.h"
#include "macro/studies/Statistics.h"

namespace c2d {

const std::vector<std::string> kPlanFigures = {"left",     "right",  "left95",      "right95",
                                               "centroid", "height", "outside_mass"};

namespace {

std::string num(double v) {
  if (std::isnan(v)) return {};
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6e", v);
  return buf;
}

std::string share(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

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
  out += ",p_outside,p_outside_lo,p_outside_hi,p_moving\n";
  for (const PlanStats& s : plans) {
    out += std::to_string(s.plan);
    if (data.named) appendCell(out, csvCell(s.name));
    for (double v : s.swept) appendCell(out, formatSweepValue(v));
    appendCell(out, std::to_string(s.samples));
    appendCell(out, std::to_string(s.failed));
    for (const auto& q : s.quantiles)
      for (double v : q) appendCell(out, num(v));
    const bool known = s.site && s.debrisRuns > 0;
    for (double v : {s.pOutside, s.pOutsideLo, s.pOutsideHi})
      appendCell(out, known ? share(v) : "");
    appendCell(out, s.debrisRuns > 0 ? share(s.pMoving) : "");
    out += '\n';
  }
  return out;
}

std::string plansText(const std::vector<PlanStats>& plans) {
  std::size_t w = 5;
  for (const PlanStats& s : plans) w = std::max(w, s.label.size());
  char buf[512];
  std::string out;
  std::snprintf(buf, sizeof buf, "  %4s  %-*s %5s %6s  %-22s %8s  %-26s %-26s %-26s\n", "plan",
                static_cast<int>(w), "", "runs", "failed", "p_outside [95 % Wilson]", "p_moving",
                "right (m) p10/median/p90", "right95 (m)", "centroid (m)");
  out += buf;
  auto triple = [](const std::array<double, 5>& q) {
    char b[64];
    std::snprintf(b, sizeof b, "%.3g / %.3g / %.3g", q[1], q[2], q[3]);
    return std::string(std::isnan(q[2]) ? "-" : b);
  };
  for (const PlanStats& s : plans) {
    char p[64] = "-";
    if (s.site && s.debrisRuns > 0)
      std::snprintf(p, sizeof p, "%.3f [%.3f, %.3f]", s.pOutside, s.pOutsideLo, s.pOutsideHi);
    char m[16] = "-";
    if (s.debrisRuns > 0) std::snprintf(m, sizeof m, "%.3f", s.pMoving);
    std::snprintf(buf, sizeof buf, "  %4d  %-*s %5d %6d  %-22s %8s  %-26s %-26s %-26s\n", s.plan,
                  static_cast<int>(w), s.label.c_str(), s.samples, s.failed, p, m,
                  triple(s.quantiles[1]).c_str(), triple(s.quantiles[3]).c_str(),
                  triple(s.quantiles[4]).c_str());
    out += buf;
  }
  return out;
}

std::string bestPlanText(const EnsembleData& data, const std::vector<PlanStats>& plans) {
  std::vector<const PlanStats*> ranked;
  for (const PlanStats& s : plans)
    if (s.debrisRuns > 0) ranked.push_back(&s);
  if (ranked.empty()) return {};
  const bool site =
      std::any_of(ranked.begin(), ranked.end(), [](const PlanStats* s) { return s->site; });
  std::stable_sort(ranked.begin(), ranked.end(), [&](const PlanStats* a, const PlanStats* b) {
    if (site && a->pOutside != b->pOutside) return a->pOutside < b->pOutside;
    return a->medianReach95 < b->medianReach95;
  });
  const PlanStats& best = *ranked.front();
  char buf[512];
  std::string out;
  std::snprintf(buf, sizeof buf, "  best plan: %d (%s): ", best.plan, best.label.c_str());
  out += buf;
  if (site) {
    std::snprintf(buf, sizeof buf, "p_outside %.3f [%.3f, %.3f], ", best.pOutside, best.pOutsideLo,
                  best.pOutsideHi);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "median reach95 %.3g m (the least %s)\n", best.medianReach95,
                site ? "p_outside, then reach" : "reach");
  out += buf;
  if (ranked.size() < 2) return out;
  const PlanStats& next = *ranked[1];
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
    diff.push_back(reach95(*it->second) - reach95(*ra));
    onlyBest += ra->outside() && !it->second->outside();
    onlyNext += !ra->outside() && it->second->outside();
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
  // The share outside decides first; the reach is compared in every case.
  if (site && best.pOutside < next.pOutside) {
    const PairedTest share = mcNemarTest(onlyBest, onlyNext, m);
    std::snprintf(buf, sizeof buf,
                  "    p_outside %.3f against %.3f (outside in one plan only: %d and %d runs; "
                  "McNemar p = %.2g)",
                  best.pOutside, next.pOutside, onlyBest, onlyNext, share.p);
    out += buf;
    out += verdict(share);
  }
  const PairedTest reach = pairedTTest(diff);
  std::snprintf(buf, sizeof buf, "    reach95 %.3g m %s on average (paired t = %.3g, p = %.2g)",
                std::abs(reach.effect), reach.effect >= 0 ? "less" : "more", reach.statistic,
                reach.p);
  out += buf;
  out += verdict(reach);
  return out;
}

}  // namespace c2d
