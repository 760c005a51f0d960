#include "macro/draws/Sweep.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "macro/deck/Limits.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Record.h"
#include "macro/output/NumberText.h"

namespace c2d {

std::string formatSweepValue(double value) { return formatNumber("%g", value == 0 ? 0.0 : value); }

std::string exactSweepValue(double value) { return exactNumber(value == 0 ? 0.0 : value); }

std::string sweepTag(const SweepValues& values) {
  std::string tag;
  for (const auto& [name, v] : values) {
    if (!tag.empty()) tag += '_';
    tag += name + "=" + formatSweepValue(v);
  }
  // Names are parameter names and values come from %g: only "inf"/"nan" could
  // surprise a shell, and they stay plain letters.
  for (char& c : tag)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' ||
          c == '=' || c == '_'))
      c = '_';
  return tag;
}

std::string fitFileStem(const std::string& stem, std::size_t max) {
  if (stem.size() <= max || max < 10) return stem;
  std::uint32_t h = 2166136261u;  // FNV-1a
  for (unsigned char c : stem) h = (h ^ c) * 16777619u;
  char hex[12];
  std::snprintf(hex, sizeof hex, "_%08x", static_cast<unsigned>(h));
  return stem.substr(0, max - 9) + hex;
}

std::string sweepLabel(const SweepValues& values) {
  std::string label;
  for (const auto& [name, v] : values) {
    if (!label.empty()) label += ", ";
    label += name + " = " + formatSweepValue(v);
  }
  return label;
}


std::vector<double> sweepValues(const SweepVariable& v, const Parameters& params) {
  std::vector<double> out;
  for (const SweepItem& item : v.items) {
    const double lo = item.value.eval(params);
    if (!item.range()) {
      out.push_back(lo);
      continue;
    }
    const double step = item.step->eval(params), hi = item.last->eval(params);
    const SourceLoc& at = item.step->loc();
    const std::string text = item.value.text() + ":" + item.step->text() + ":" + item.last->text();
    if (!(step != 0) || !std::isfinite(step) || !std::isfinite(lo) || !std::isfinite(hi))
      throw DeckError(at, "the range " + text + " needs a finite step other than 0",
                      v.record.excerpt(at));
    const double r = (hi - lo) / step;
    if (r < -1e-9)
      throw DeckError(at,
                      "the range " + text + " steps away from its end (" + formatSweepValue(lo) +
                          " by " + formatSweepValue(step) + " towards " + formatSweepValue(hi) + ")",
                      v.record.excerpt(at));
    if (r + 1 > DeckLimits::kMaxRuns)
      throw DeckError(at,
                      "the range " + text + " has more values than this program runs (" +
                          std::to_string(DeckLimits::kMaxRuns) + ")",
                      v.record.excerpt(at));
    const long n = static_cast<long>(std::floor(r + 1e-9)) + 1;
    for (long k = 0; k < n; ++k) {
      const double x = lo + static_cast<double>(k) * step;
      out.push_back(std::abs(x - hi) <= 1e-9 * std::abs(step) ? hi : x);
    }
  }
  if (out.size() > static_cast<std::size_t>(DeckLimits::kMaxRuns))
    throw DeckError(v.record[0].loc,
                    "'" + v.name + "' has " + std::to_string(out.size()) +
                        " values, more than this program runs (" +
                        std::to_string(DeckLimits::kMaxRuns) + ")",
                    v.record.excerpt(v.record[0].loc));
  return out;
}

bool isPlanNames(const SweepVariable& v) { return toLower(v.name) == "plan"; }

std::vector<std::string> sweepPlanNames(const TopSweep& sweep) {
  std::vector<std::string> names;
  for (const SweepVariable& v : sweep.variables) {
    if (!isPlanNames(v)) continue;
    for (const SweepItem& item : v.items) {
      const std::string name = item.value.text();
      const SourceLoc& at = item.value.loc();
      if (item.range() || !Parameters::validName(name))
        throw DeckError(at, "'" + name + "' is no plan name: a letter, then letters, digits or '_'",
                        v.record.excerpt(at), "PLAN = felling_left felling_right implosion");
      for (const std::string& other : names)
        if (toLower(other) == toLower(name))
          throw DeckError(at, "plan name '" + name + "' is given twice", v.record.excerpt(at),
                          "each plan of the sweep has a name of its own (file names, legends, tables)");
      names.push_back(name);
    }
  }
  if (!names.empty() && std::all_of(sweep.variables.begin(), sweep.variables.end(),
                                    [](const SweepVariable& v) { return isPlanNames(v); }))
    throw DeckError(sweep.head[0].loc, "a SWEEp of plan names alone: its plans would be the same",
                    sweep.head.excerpt(sweep.head[0].loc),
                    "sweep what makes the plans differ next to PLAN (on1 = 1 0, delay = 0.2 0.5)");
  return names;
}

std::vector<SweepValues> sweepRuns(const TopSweep& sweep, const Parameters& params) {
  std::vector<std::vector<double>> values;
  for (const SweepVariable& v : sweep.variables) {
    // The plan names count as values (zipped), set no parameter.
    values.push_back(isPlanNames(v) ? std::vector<double>(v.items.size(), 0.0) : sweepValues(v, params));
    if (values.back().size() != values.front().size()) {
      const SweepVariable& w = sweep.variables.front();
      throw DeckError(v.record[0].loc,
                      "'" + v.name + "' has " + std::to_string(values.back().size()) +
                          " values and '" + w.name + "' (line " + std::to_string(w.record.loc.line) +
                          ") " + std::to_string(values.front().size()) +
                          ": the variables of a sweep are zipped, one value of each per run",
                      v.record.excerpt(v.record[0].loc));
    }
  }
  std::vector<SweepValues> runs(values.empty() ? 0 : values.front().size());
  for (std::size_t i = 0; i < runs.size(); ++i)
    for (std::size_t k = 0; k < values.size(); ++k)
      if (!isPlanNames(sweep.variables[k])) runs[i].emplace_back(sweep.variables[k].name, values[k][i]);
  return runs;
}


}  // namespace c2d
