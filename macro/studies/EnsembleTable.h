#pragma once
// [ext] The table of an ensemble's runs, <stem>_ensemble.csv, one row per run:
//   run,plan,sample,stem,[name,]<swept names...>,<drawn names...>,status,reason,
//   steps,iterations,cuts,energy_error,
//   <debris columns (macro/output/Debris.h)>,<zone columns, per protected zone>,cover
// (name: the plan's name, when the SWEEp names its plans: Sweep.h isPlanNames)
// `run` counts every run of the deck from 1 (shards join on it), `plan` the
// value sets of the sweep (1 without one), `sample` 1..n. The drawn values are
// the named parameters, dt_factor (JITTer) and blast_1, blast_2, ... (the BLASt
// records' times, DETOnators), each written to round-trip exactly. `cover` is
// where the debris lies: the x-intervals "x0:x1" it occupies, joined by ';'
// (the ensemble picture's map of where debris lies). steps, iterations, cuts
// and energy_error are the run's (macro/run/ProblemRun.h RunSummary, up to
// its failure for a failed run): the same in every process, so a sharded
// study merges to the same bytes. Its CPU time, which differs from process
// to process, is in <stem>_timing.csv (macro/studies/RunTiming.h).
//
// The statistics of the ensemble (PlanStatistics.h, Sensitivity.h,
// EnsemblePicture.h) are computed from the table as written and read back
// (readEnsembleTable), so that a run and the merge of its shards give the same
// tables to the last digit.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "macro/output/Debris.h"
#include "macro/draws/Sweep.h"

namespace c2d {

using DrawnValues = std::vector<std::pair<std::string, double>>;

// A run's numerical work and how well its energy account closed.
struct RunNumerics {
  int steps = 0, iterations = 0, cuts = 0;
  double energyError = 0;
};

struct EnsembleRow {
  int run = 0, plan = 0, sample = 0;
  std::string stem;
  SweepValues sweep;
  DrawnValues drawn;
  bool ok = true;
  std::string reason;
  std::optional<DebrisFigures> debris;
  std::string name;  // the plan's name (SWEEp's PLAN record), if any
  RunNumerics numerics;
  double cpuSeconds = 0;  // not in the table: <stem>_timing.csv
};

class EnsembleTable {
 public:
  // zones: the site's protected zones, whose columns follow the debris columns;
  // named: the plans have names (a `name` column).
  EnsembleTable(std::vector<std::string> swept, std::vector<std::string> drawn,
                std::vector<std::string> zones = {}, bool named = false)
      : swept_(std::move(swept)), drawn_(std::move(drawn)), zones_(std::move(zones)), named_(named) {}
  void add(EnsembleRow row) { rows_.push_back(std::move(row)); }
  const std::vector<EnsembleRow>& rows() const { return rows_; }
  const std::vector<std::string>& swept() const { return swept_; }
  const std::vector<std::string>& drawn() const { return drawn_; }
  int failed() const;

  std::string header() const;
  std::string csv() const;

 private:
  std::vector<std::string> swept_, drawn_, zones_;
  bool named_ = false;
  std::vector<EnsembleRow> rows_;
};

// One run of the table as read back.
struct EnsembleRun {
  int run = 0, plan = 0, sample = 0;
  std::string stem;
  std::string name;                  // the plan's name ("" when the plans have none)
  std::vector<double> swept, drawn;  // in the header's order
  bool ok = false;
  std::string reason;
  RunNumerics numerics;
  bool debris = false;                    // debris figures present
  std::map<std::string, double> figures;  // the numeric debris columns by name
  std::string site;                       // "inside", "outside", "none"
  bool atRest = true;
  std::string verdict = {};  // "felled", "in place", "other way", "" (no intended fall)
  std::vector<std::pair<double, double>> cover;

  double figure(const std::string& name) const;  // NaN when absent
  bool outside() const { return site == "outside"; }
  bool felled() const { return verdict == "felled"; }
};

struct EnsembleData {
  std::vector<std::string> swept, drawn;
  std::vector<std::string> zones;  // the protected zones' names (their columns)
  bool named = false;             // the table has the plans' names (column `name`)
  std::vector<EnsembleRun> runs;  // in table order
  std::string header;
};

// Reads the table's text (its first line the header; sweptCount: how many of
// the columns after `stem` are swept, the others up to `status` drawn). Throws
// std::runtime_error naming the line and column of a malformed row: a cell
// count other than the header's, text in a number column, a status other than
// ok/failed, a cut row.
EnsembleData readEnsembleTable(const std::string& text, std::size_t sweptCount);

}  // namespace c2d
