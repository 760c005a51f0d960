#pragma once
// [ext] The table of a study of plans: a SWEEp over blast times, element
// numbers or any other parameter, one row per plan (run) in <stem>_plans.csv:
//   run,stem,[name,]<swept names...>,status,reason,<debris columns (macro/output/Debris.h)>
// (name: the plans' names, when the SWEEp names them: Sweep.h isPlanNames)
// status is "ok" or "failed" (reason: the first line of the failure), the
// debris columns are empty for a run without them. `run` counts every run of
// the deck from 1, so that the parts of a study split with --shard join again
// (macro/batch/Shard.h) by sorting on it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "macro/output/Debris.h"
#include "macro/studies/Csv.h"
#include "macro/draws/Sweep.h"

namespace c2d {

struct PlanRow {
  int run = 0;  // 1-based over every run of the deck
  std::string stem;
  SweepValues sweep;
  bool ok = true;
  std::string reason;  // why it failed
  std::optional<DebrisFigures> debris;
  std::string name;  // the plan's name (SWEEp's PLAN record), if any
};

class PlanTable {
 public:
  // names: every swept name of the deck (columns), in order of first appearance.
  // zones: the site's protected zones (macro/output/Debris.h zoneCsvHeader), if any;
  // named: the plans have names (a `name` column).
  explicit PlanTable(std::vector<std::string> names, std::vector<std::string> zones = {},
                     bool named = false)
      : names_(std::move(names)), zones_(std::move(zones)), named_(named) {}

  void add(PlanRow row) { rows_.push_back(std::move(row)); }
  const std::vector<PlanRow>& rows() const { return rows_; }
  int failed() const;

  std::string header() const;
  std::string csv() const;  // header and every row
  void write(const std::filesystem::path& path) const;

 private:
  std::vector<std::string> names_, zones_;
  bool named_ = false;
  std::vector<PlanRow> rows_;
};

}  // namespace c2d
