#include "macro/studies/Sensitivity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "macro/studies/Csv.h"
#include "macro/studies/MultipleTests.h"
#include "macro/studies/PlanStatistics.h"
#include "macro/studies/Statistics.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

// Per plan, per drawn value, per figure of kPlanFigures: rho.
struct PlanCorrelations {
  int plan = 0;
  std::string name;  // the plan's name, if any
  std::vector<double> swept;
  std::vector<std::vector<double>> rho;  // [input][figure]
  std::vector<std::vector<int>> pairs;   // [input][figure]: the runs with both values
  std::vector<std::vector<double>> p, holm;  // [input][figure]: p-value, Holm-adjusted in its family
  int runs = 0;
};

// The p-values of a plan and their Holm correction, one family per kind of
// input (the plan's inputs; the numerical scatter).
void testCorrelations(const EnsembleData& data, PlanCorrelations& c) {
  for (std::size_t i = 0; i < c.rho.size(); ++i) {
    c.p.emplace_back();
    for (std::size_t f = 0; f < c.rho[i].size(); ++f)
      c.p[i].push_back(rankCorrelationP(c.rho[i][f], c.pairs[i][f]));
  }
  c.holm.assign(c.rho.size(), std::vector<double>(kPlanFigures.size(), NAN));
  for (const bool numerical : {false, true}) {
    std::vector<double> family;
    for (std::size_t i = 0; i < c.rho.size(); ++i)
      if (isNumericalScatter(data.drawn[i]) == numerical)
        family.insert(family.end(), c.p[i].begin(), c.p[i].end());
    const std::vector<double> adjusted = holmAdjusted(family);
    std::size_t k = 0;
    for (std::size_t i = 0; i < c.rho.size(); ++i)
      if (isNumericalScatter(data.drawn[i]) == numerical)
        for (std::size_t f = 0; f < kPlanFigures.size(); ++f) c.holm[i][f] = adjusted[k++];
  }
}

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
      std::vector<int> pairs;
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
        pairs.push_back(static_cast<int>(x.size()));
      }
      c.rho.push_back(std::move(row));
      c.pairs.push_back(std::move(pairs));
    }
    testCorrelations(data, c);
    out.push_back(std::move(c));
  }
  return out;
}

std::string rhoCell(double v) { return std::isnan(v) ? std::string() : formatNumber("%.4f", v); }

std::string pCell(double v) { return std::isnan(v) ? std::string() : formatNumber("%.3g", v); }

bool standsOut(double holm) { return holm < kSensitivityLevel; }

}  // namespace

bool isNumericalScatter(const std::string& input) { return input == "dt_factor"; }

std::string sensitivityCsv(const EnsembleData& data) {
  std::string out = data.named ? "plan,name" : "plan";
  for (const std::string& n : data.swept) appendCell(out, csvCell(n));
  out += ",input,kind,figure,runs,rho,p,p_holm,mark\n";
  for (const PlanCorrelations& c : correlations(data))
    for (std::size_t i = 0; i < data.drawn.size(); ++i)
      for (std::size_t f = 0; f < kPlanFigures.size(); ++f) {
        out += std::to_string(c.plan);
        if (data.named) appendCell(out, csvCell(c.name));
        for (double v : c.swept) appendCell(out, exactSweepValue(v));
        appendCell(out, csvCell(data.drawn[i]));
        appendCell(out, isNumericalScatter(data.drawn[i]) ? "numerical scatter" : "input");
        appendCell(out, kPlanFigures[f]);
        appendCell(out, std::to_string(c.pairs[i][f]));
        appendCell(out, rhoCell(c.rho[i][f]));
        appendCell(out, pCell(c.p[i][f]));
        appendCell(out, pCell(c.holm[i][f]));
        appendCell(out, standsOut(c.holm[i][f]) ? "*" : "");
        out += '\n';
      }
  return out;
}

namespace {

// One input's line: each figure's rho with its p-value, * where it stands out.
std::string inputLine(const PlanCorrelations& c, std::size_t i, const std::string& input) {
  std::string line = "      " + input + ":";
  for (std::size_t f = 0; f < kPlanFigures.size(); ++f) {
    if (std::isnan(c.rho[i][f])) continue;
    line += " " + kPlanFigures[f] + " " + rhoCell(c.rho[i][f]) + " (p " + pCell(c.p[i][f]) + ")" +
            (standsOut(c.holm[i][f]) ? "*" : "");
  }
  return line + "\n";
}

// The inputs of one kind, the strongest correlation first.
std::string kindLines(const EnsembleData& data, const PlanCorrelations& c, bool numerical) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < data.drawn.size(); ++i)
    if (isNumericalScatter(data.drawn[i]) == numerical) order.push_back(i);
  auto strongest = [&](std::size_t i) {
    double m = 0;
    for (double v : c.rho[i])
      if (!std::isnan(v)) m = std::max(m, std::abs(v));
    return m;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return strongest(a) > strongest(b); });
  std::string out;
  for (std::size_t i : order) out += inputLine(c, i, data.drawn[i]);
  return out;
}

int familySize(const EnsembleData& data, const PlanCorrelations& c, bool numerical) {
  int m = 0;
  for (std::size_t i = 0; i < data.drawn.size(); ++i)
    if (isNumericalScatter(data.drawn[i]) == numerical)
      for (double p : c.p[i]) m += !std::isnan(p);
  return m;
}

}  // namespace

std::string sensitivityText(const EnsembleData& data) {
  if (data.drawn.empty()) return {};
  std::string out =
      "  sensitivity: Spearman's rank correlation of each drawn value with the debris figures, its\n"
      "  p-value (Student's t on n - 2), * where it stands out at 5 % after Holm's correction over\n"
      "  the plan's tests (the chance of any false * at most 5 %)\n";
  char buf[256];
  for (const PlanCorrelations& c : correlations(data)) {
    const std::string plan = "plan " + std::to_string(c.plan) + (c.name.empty() ? "" : " " + c.name);
    if (c.runs < 3) {
      std::snprintf(buf, sizeof buf, "    %s (%d run%s): too few for a correlation\n", plan.c_str(),
                    c.runs, c.runs == 1 ? "" : "s");
      out += buf;
      continue;
    }
    std::snprintf(buf, sizeof buf, "    %s (%d runs, %d tests of its inputs):\n", plan.c_str(), c.runs,
                  familySize(data, c, false));
    out += buf + kindLines(data, c, false);
    if (const std::string scatter = kindLines(data, c, true); !scatter.empty()) {
      std::snprintf(buf, sizeof buf,
                    "      numerical scatter (the time-step jitter, no input of the plan; %d tests"
                    " of their own; a * says the figures move with the step):\n",
                    familySize(data, c, true));
      out += buf;
      for (std::size_t p = 0; p < scatter.size();) {  // indented under its heading
        const std::size_t e = scatter.find('\n', p);
        out += "  " + scatter.substr(p, e + 1 - p);
        p = e + 1;
      }
    }
  }
  return out;
}

}  // namespace c2d
