#include "macro/studies/Sweep.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "macro/deck/Limits.h"
#include "macro/deck/Parameters.h"
#include "macro/deck/Record.h"
#include "macro/studies/EnsembleTable.h"

namespace c2d {

std::string formatSweepValue(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", value == 0 ? 0.0 : value);
  return buf;
}

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

std::vector<SweepItem> parseSweepItems(const Record& rec, std::size_t first) {
  std::vector<SweepItem> items;
  for (std::size_t i = first; i < rec.size(); ++i) {
    const Field& f = rec[i];
    if (f.text.empty())
      throw DeckError(f.loc, "empty value in a sweep", rec.excerpt(f.loc),
                      "separate the values by blanks (two commas make an empty field)");
    if (f.text.find(':') == std::string::npos) {
      items.push_back({Expression::parse(f), {}, {}});
      continue;
    }
    // lo:step:hi, each part an expression.
    std::vector<std::pair<std::string, int>> parts;  // text, column
    std::size_t start = 0;
    for (std::size_t c = 0; c <= f.text.size(); ++c)
      if (c == f.text.size() || f.text[c] == ':') {
        parts.emplace_back(f.text.substr(start, c - start), f.loc.col + static_cast<int>(start));
        start = c + 1;
      }
    if (parts.size() != 3)
      throw DeckError(f.loc, "a range of sweep values is lo:step:hi, got '" + f.text + "'",
                      rec.excerpt(f.loc), "e.g. 0:0.01:1 gives 0, 0.01, ..., 1");
    std::vector<Expression> e;
    for (const auto& [text, col] : parts) {
      SourceLoc at = f.loc;
      at.col = col;
      if (text.empty())
        throw DeckError(at, "a part of the range '" + f.text + "' is empty", rec.excerpt(at),
                        "a range is lo:step:hi");
      e.push_back(Expression::parse(text, at, rec.line));
    }
    items.push_back({e[0], e[1], e[2]});
  }
  return items;
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

void registerDeckBlocks(CommandRegistry& registry) {
  CommandSpec feap;
  feap.name = "FEAP";
  feap.doc =
      "Start of a problem: 'FEAP * * title', then the control record 'numnp numel nummat ndm "
      "ndf nen' (zeros: counted; frames have ndm 2, ndf 3, nen 2), or FEAP's keyword form: "
      "records of 'keyword value' pairs in any order, NODEs, ELEMents, MATErial, DIMEnsion, "
      "DOFS, ELNOdes (or NUMNp, NUMEl, NUMMat, NDM, NDF, NEN), e.g. 'NODES=10 ELEMENTS=9 "
      "MATERIAL=1', ended by a blank record (absent: counted, 2, 3, 2). Then the mesh "
      "commands up to END, and BATCh blocks.";
  feap.section = CommandSection::Mesh;
  feap.data = DataForm::Records;
  feap.dataSyntax = "numnp numel nummat ndm ndf nen | keyword value ...";
  registry.add(std::move(feap));

  CommandSpec s;
  s.name = "SWEEp";
  s.doc =
      "[ext] Parameter sweep, a top-level block before a problem: records 'name = v1 v2 ...' "
      "(values are expressions without blanks, or ranges lo:step:hi giving lo, lo + step, ... up "
      "to hi; a record without 'name =' continues the values of the one before; several names "
      "are zipped and need the same number of values), ended by a blank record. The next problem "
      "(with the PARAmeter blocks between the sweep and it, evaluated after the sweep values are "
      "set; they may use a swept name, not set it) runs once per value set (n times with an "
      "ENSEmble before or after the sweep); each run's outputs are tagged with its values, "
      "<stem>_ks=-393_tplot.csv, and every "
      "PLOT,CURVe of the runs is overlaid at the end of the deck in <stem>_<y>_vs_<x>.svg with "
      "one legend entry per run ('ks = -393'). FEAP's LOOP,,n ... NEXT around a problem with a "
      "PARAmeter block inside still works; its runs are <stem>_1, <stem>_2, ... "
      "A sweep is a study of plans (blast times, element numbers: any numeric field takes "
      "parameters): a run that fails is reported and the others run (exit status 2 if any "
      "failed), and the study ends with <stem>_plans.csv, one row per run: run number, stem, "
      "swept values, status (ok/failed) and reason, the debris figures. collapse2d run "
      "--shard i/n runs the i-th of n interleaved parts; collapse2d merge checks and joins the "
      "parts (tables and overlays); collapse2d run -j N runs the runs in N processes. "
      "A record 'PLAN = name1 name2 ...' names the plans (zipped like a variable; a name is a "
      "letter, then letters, digits or '_'; it sets no parameter): plan k's outputs are "
      "<stem>_<name k>_..., and its legend entries, picture titles and the tables (a column "
      "`name` after `stem` in <stem>_plans.csv and <stem>_ensemble.csv, after `plan` in an "
      "ensemble's plans and sensitivity tables) say its name instead of its values. With "
      "BLASt's ON field, plans that blast different column lines are one sweep: "
      "'PLAN = left right', 'on1 = 1 0', 'on2 = 0 1'.";
  s.section = CommandSection::Mesh;
  s.data = DataForm::Records;
  s.dataSyntax = "name = v1 v2 ... (a value, or a range lo:step:hi); v3 v4 ... (continued)";
  s.dataFields = {{"name", FieldKind::Text, {}, "parameter name"},
                  {"v1 v2 ...", FieldKind::Expression, {}, "its value in each run"}};
  registry.add(std::move(s));
}

}  // namespace c2d
