#include "macro/studies/Sensitivity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "macro/studies/Csv.h"
#include "macro/studies/PlanStatistics.h"
#include "macro/studies/Statistics.h"

namespace c2d {

namespace {

// Per plan, per drawn value, per figure of kPlanFigures: rho.
struct PlanCorrelations {
  int plan = 0;
  std::string name;  // the plan's name, if any
  std::vector<double> swept;
  std::vector<std::vector<double>> rho;  // [input][figure]
  int runs = 0;
};

std::vector<PlanCorrelations> correlations(const EnsembleData& data) {
  std::map<int, std::vector<const EnsembleRun*>> byPlan;
  for (const EnsembleRun& r : data.runs)
    if (r.ok && r.debris) byPlan[r.plan].push_back(&r);
  std::vector<PlanCorrelations> out;
  for (const auto& [plan, runs] : byPlan) {
    PlanCorrelations c;
    c.plan = plan;
    c.name = runs.front()->name;
    c.swept = runs.front()->swept;
    c.runs = static_cast<int>(runs.size());
    for (std::size_t i = 0; i < data.drawn.size(); ++i) {
      std::vector<double> row;
      for (const std::string& f : kPlanFigures) {
        // The runs that have both values (a drawn value may be absent: NaN).
        std::vector<double> x, y;
        for (const EnsembleRun* r : runs) {
          const double xi = i < r->drawn.size() ? r->drawn[i] : NAN, yi = r->figure(f);
          if (std::isnan(xi) || std::isnan(yi)) continue;
          x.push_back(xi);
          y.push_back(yi);
        }
        row.push_back(rankCorrelation(x, y));
      }
      c.rho.push_back(std::move(row));
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::string rhoCell(double v) {
  if (std::isnan(v)) return {};
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

}  // namespace

std::string sensitivityCsv(const EnsembleData& data) {
  std::string out = data.named ? "plan,name" : "plan";
  for (const std::string& n : data.swept) appendCell(out, csvCell(n));
  out += ",input";
  for (const std::string& f : kPlanFigures) appendCell(out, f);
  out += '\n';
  for (const PlanCorrelations& c : correlations(data))
    for (std::size_t i = 0; i < data.drawn.size(); ++i) {
      out += std::to_string(c.plan);
      if (data.named) appendCell(out, csvCell(c.name));
      for (double v : c.swept) appendCell(out, exactSweepValue(v));
      appendCell(out, csvCell(data.drawn[i]));
      for (double v : c.rho[i]) appendCell(out, rhoCell(v));
      out += '\n';
    }
  return out;
}

std::string sensitivityText(const EnsembleData& data) {
  if (data.drawn.empty()) return {};
  std::string out =
      "  sensitivity: Spearman's rank correlation of each drawn value with the debris figures\n";
  char buf[256];
  for (const PlanCorrelations& c : correlations(data)) {
    if (c.runs < 3) {
      std::snprintf(buf, sizeof buf, "    plan %d (%d run%s): too few for a correlation\n", c.plan,
                    c.runs, c.runs == 1 ? "" : "s");
      out += buf;
      continue;
    }
    // 2/sqrt(n) is below 1 from 5 runs on: fewer cannot tell a correlation from noise.
    if (c.runs < 5)
      std::snprintf(buf, sizeof buf,
                    "    plan %d%s%s (%d runs; too few for any |rho| to stand out of the noise):\n",
                    c.plan, c.name.empty() ? "" : " ", c.name.c_str(), c.runs);
    else
      std::snprintf(buf, sizeof buf,
                    "    plan %d%s%s (%d runs; |rho| above %.2f stands out of the noise):\n", c.plan,
                    c.name.empty() ? "" : " ", c.name.c_str(), c.runs,
                    2 / std::sqrt(static_cast<double>(c.runs)));
    out += buf;
    std::vector<std::size_t> order(data.drawn.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    auto strongest = [&](std::size_t i) {
      double m = 0;
      for (double v : c.rho[i])
        if (!std::isnan(v)) m = std::max(m, std::abs(v));
      return m;
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return strongest(a) > strongest(b); });
    for (std::size_t i : order) {
      std::string line = "      " + data.drawn[i] + ":";
      for (std::size_t f = 0; f < kPlanFigures.size(); ++f) {
        const double v = c.rho[i][f];
        std::snprintf(buf, sizeof buf, " %s %s", kPlanFigures[f].c_str(),
                      std::isnan(v) ? "-" : rhoCell(v).c_str());
        line += buf;
      }
      out += line + "\n";
    }
  }
  return out;
}

}  // namespace c2d
