#include "macro/studies/EnsembleTable.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "macro/deck/Limits.h"
#include "macro/studies/Csv.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

std::string coverText(const std::vector<std::pair<double, double>>& cover) {
  std::string s;
  char buf[64];
  for (const auto& [a, b] : cover) {
    std::snprintf(buf, sizeof buf, "%s%.6g:%.6g", s.empty() ? "" : ";", a, b);
    s += buf;
  }
  return s;
}

// The run's numerics, between `reason` and the debris columns.
constexpr const char* kNumericsHeader = "steps,iterations,cuts,energy_error";
constexpr std::size_t kNumericsColumns = 4;

// A figure that is not finite (a run that failed on a NaN) is an empty cell.
std::string numericsCells(const RunNumerics& n) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%d,%d,%d,", n.steps, n.iterations, n.cuts);
  std::string s = buf;
  if (std::isfinite(n.energyError)) {
    std::snprintf(buf, sizeof buf, "%.3e", n.energyError);
    s += buf;
  }
  return s;
}

}  // namespace

int EnsembleTable::failed() const {
  return static_cast<int>(
      std::count_if(rows_.begin(), rows_.end(), [](const EnsembleRow& r) { return !r.ok; }));
}

std::string EnsembleTable::header() const {
  std::string h = named_ ? "run,plan,sample,stem,name" : "run,plan,sample,stem";
  for (const std::string& n : swept_) appendCell(h, csvCell(n));
  for (const std::string& n : drawn_) appendCell(h, csvCell(n));
  h += ",status,reason,";
  h += kNumericsHeader;
  h += ',';
  h += debrisCsvHeader(zones_);
  return h + ",cover";
}

std::string EnsembleTable::csv() const {
  const std::string debrisHeader = debrisCsvHeader(zones_);
  const std::string noDebris(
      static_cast<std::size_t>(std::count(debrisHeader.begin(), debrisHeader.end(), ',')), ',');
  std::string out = header() + "\n";
  for (const EnsembleRow& r : rows_) {
    out += std::to_string(r.run);
    appendCell(out, std::to_string(r.plan));
    appendCell(out, std::to_string(r.sample));
    appendCell(out, csvCell(r.stem));
    if (named_) appendCell(out, csvCell(r.name));
    for (const std::string& n : swept_) {
      out += ',';
      for (const auto& [name, v] : r.sweep)
        if (name == n) out += exactSweepValue(v);
    }
    for (const std::string& n : drawn_) {
      out += ',';
      for (const auto& [name, v] : r.drawn)
        if (name == n) out += exactNumber(v);
    }
    out += r.ok ? ",ok," : ",failed,";
    out += csvCell(r.reason.substr(0, r.reason.find('\n')));
    out += ',';
    out += numericsCells(r.numerics);
    out += ',';
    if (r.debris) {
      out += debrisCsvRow(*r.debris, zones_);
      appendCell(out, coverText(r.debris->cover));
    } else {
      out += noDebris;
      out += ',';
    }
    out += "\n";
  }
  return out;
}

namespace {

// The run's numerics from cells c[first..first+3]; bad(column, why) throws.
template <typename Bad>
RunNumerics readNumerics(const std::vector<std::string>& c, std::size_t first, const Bad& bad) {
  RunNumerics n;
  int* counts[] = {&n.steps, &n.iterations, &n.cuts};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto v = countCell(c[first + k], 0, INT_MAX);
    if (!v) bad(first + k, "'" + c[first + k] + "' is not a count");
    *counts[k] = *v;
  }
  const auto e = c[first + 3].empty() ? std::optional<double>(NAN) : numberCell(c[first + 3]);
  if (!e) bad(first + 3, "'" + c[first + 3] + "' is not a number");
  n.energyError = *e;
  return n;
}

}  // namespace

double EnsembleRun::figure(const std::string& name) const {
  const auto it = figures.find(name);
  return it == figures.end() ? NAN : it->second;
}

namespace {

// Where an ensemble table's columns are, read from its header.
struct TableColumns {
  std::vector<std::string> head;
  std::size_t first = 0;          // the first swept value (after stem, or name)
  std::size_t values = 0;         // swept and drawn values
  std::size_t sweptCount = 0;
  std::size_t firstNumerics = 0;  // after status and reason
  std::size_t firstDebris = 0;
  std::size_t fixedCount = 0;     // the debris columns before the zones'
  std::vector<std::string> debrisNames;  // the fixed ones, then the zones'
};

// A bad cell: "line n, column name: why".
struct BadCell {
  const std::vector<std::string>& head;
  const int& lineNo;
  [[noreturn]] void operator()(std::size_t col, const std::string& why) const {
    throw std::runtime_error("line " + std::to_string(lineNo) +
                             (col < head.size() ? ", column " + head[col] : "") + ": " + why);
  }
};

// The fixed columns: run,plan,sample,stem[,name], the values, status,reason,
// the numerics; the swept and drawn names into data.
void readFixedColumns(std::size_t sweptCount, TableColumns& t, EnsembleData& data) {
  const std::vector<std::string>& head = t.head;
  const auto status = std::find(head.begin(), head.end(), "status");
  const std::vector<std::string> numericsNames = splitCsv(kNumericsHeader);
  if (head.size() < 6 || head[0] != "run" || head[1] != "plan" || head[2] != "sample" ||
      head[3] != "stem" || status == head.end() || status + 1 == head.end() ||
      *(status + 1) != "reason" || head.back() != "cover")
    throw std::runtime_error(
        "its header is not an ensemble table's (run,plan,sample,stem,...,status,reason,...,cover)");
  t.firstNumerics = static_cast<std::size_t>(status - head.begin()) + 2;
  if (head.size() < t.firstNumerics + kNumericsColumns ||
      !std::equal(numericsNames.begin(), numericsNames.end(),
                  head.begin() + static_cast<long>(t.firstNumerics)))
    throw std::runtime_error(std::string("its columns after reason are not ") + kNumericsHeader);
  t.firstDebris = t.firstNumerics + kNumericsColumns;
  // The plans' names, when the sweep names them, come after the stem.
  data.named = head[4] == "name";
  t.first = data.named ? 5 : 4;
  t.values = static_cast<std::size_t>(status - head.begin()) - t.first;
  t.sweptCount = sweptCount;
  if (sweptCount > t.values)
    throw std::runtime_error("its header has fewer value columns than swept names");
  data.swept.assign(head.begin() + static_cast<long>(t.first),
                    head.begin() + static_cast<long>(t.first + sweptCount));
  data.drawn.assign(head.begin() + static_cast<long>(t.first + sweptCount), status);
}

// The debris columns: this program's fixed ones, then the zones' in groups of
// kZoneColumns, up to `cover`; the zones into data.
void readDebrisColumns(TableColumns& t, EnsembleData& data) {
  const std::vector<std::string>& head = t.head;
  const std::string debrisHeader = debrisCsvHeader();
  t.debrisNames = splitCsv(debrisHeader);
  if (head.size() < t.firstDebris + t.debrisNames.size() + 1 ||
      !std::equal(t.debrisNames.begin(), t.debrisNames.end(),
                  head.begin() + static_cast<long>(t.firstDebris)))
    throw std::runtime_error("its debris columns are not this program's (" + debrisHeader + ")");
  t.fixedCount = t.debrisNames.size();
  const std::size_t zoneCells = head.size() - 1 - t.firstDebris - t.fixedCount;
  const std::string group = zoneCsvHeader({"<zone>"});
  if (zoneCells % kZoneColumns.size() != 0)
    throw std::runtime_error("its zone columns are not groups of " + group);
  for (std::size_t k = 0; k < zoneCells; k += kZoneColumns.size()) {
    const auto at = head.begin() + static_cast<long>(t.firstDebris + t.fixedCount + k);
    const std::string zone = at->substr(std::min(at->size(), kZoneColumns[0].size()));
    const std::vector<std::string> names = splitCsv(zoneCsvHeader({zone}));
    if (at->rfind(kZoneColumns[0], 0) != 0 || !std::equal(names.begin(), names.end(), at))
      throw std::runtime_error("its zone columns are not groups of " + group + " (at '" + *at +
                               "')");
    data.zones.push_back(zone);
    t.debrisNames.insert(t.debrisNames.end(), names.begin(), names.end());
  }
}

// A row's run, plan, sample, stem and name, its values (an empty one, a value
// the run does not have such as a plan with fewer BLASt records: NaN), status,
// reason and numerics.
void readRunCells(const std::vector<std::string>& c, const TableColumns& t, bool named,
                  const BadCell& bad, EnsembleRun& r) {
  constexpr int most = DeckLimits::kMaxRuns;
  const auto run = countCell(c[0], 1, most), plan = countCell(c[1], 1, most),
             sample = countCell(c[2], 1, most);
  if (!run) bad(0, "'" + c[0] + "' is not a run number");
  if (!plan) bad(1, "'" + c[1] + "' is not a plan number");
  if (!sample) bad(2, "'" + c[2] + "' is not a sample number");
  r.run = *run;
  r.plan = *plan;
  r.sample = *sample;
  r.stem = c[3];
  if (named) r.name = c[4];
  for (std::size_t i = t.first; i < t.first + t.values; ++i) {
    const auto v = c[i].empty() ? std::optional<double>(NAN) : numberCell(c[i]);
    if (!v) bad(i, "'" + c[i] + "' is not a number");
    (i < t.first + t.sweptCount ? r.swept : r.drawn).push_back(*v);
  }
  const std::string& st = c[t.firstNumerics - 2];
  if (st != "ok" && st != "failed")
    bad(t.firstNumerics - 2, "the status is '" + st + "', not ok or failed");
  r.ok = st == "ok";
  r.reason = c[t.firstNumerics - 1];
  r.numerics = readNumerics(c, t.firstNumerics, bad);
}

// The debris cells of a row with debris: site, verdict, at_rest and the
// figures (the optional ones and the zones' may be empty).
void readDebrisCells(const std::vector<std::string>& c, const TableColumns& t,
                     const BadCell& bad, EnsembleRun& r) {
  const std::size_t firstZone = t.fixedCount;
  for (std::size_t k = 0; k < t.debrisNames.size(); ++k) {
    const std::string& name = t.debrisNames[k];
    const std::string& cell = c[t.firstDebris + k];
    if (name == "site") {
      if (cell != "inside" && cell != "outside" && cell != "none")
        bad(t.firstDebris + k, "the site status is '" + cell + "'");
      r.site = cell;
    } else if (name == "verdict") {
      if (!cell.empty() && cell != "felled" && cell != "in place" && cell != "other way")
        bad(t.firstDebris + k, "the verdict is '" + cell + "'");
      r.verdict = cell;
    } else if (name == "at_rest") {
      if (cell != "yes" && cell != "no")
        bad(t.firstDebris + k, "at_rest is '" + cell + "', not yes or no");
      r.atRest = cell == "yes";
    } else if (!cell.empty() || (name != "site_xmin" && name != "site_xmax" &&
                                 name != "risk_level" && name != "risk_confidence" &&
                                 k < firstZone)) {
      const auto v = numberCell(cell);
      if (!v) bad(t.firstDebris + k, "'" + cell + "' is not a number");
      r.figures[name] = *v;
    }
  }
}

// The cover cell: intervals x0:x1 separated by ';'.
void readCoverCell(const std::string& cover, std::size_t column, const BadCell& bad,
                   EnsembleRun& r) {
  std::size_t p = 0;
  while (p < cover.size()) {
    std::size_t e = cover.find(';', p);
    if (e == std::string::npos) e = cover.size();
    const std::string span = cover.substr(p, e - p);
    const std::size_t colon = span.find(':');
    const auto a = colon == std::string::npos ? std::nullopt : numberCell(span.substr(0, colon));
    const auto b = colon == std::string::npos ? std::nullopt : numberCell(span.substr(colon + 1));
    if (!a || !b) bad(column, "'" + span + "' is not an interval x0:x1");
    r.cover.emplace_back(*a, *b);
    p = e + 1;
  }
}

// One data row; a row without debris has all its debris cells empty.
EnsembleRun readRunRow(const std::string& line, const TableColumns& t, bool named,
                       const BadCell& bad) {
  const std::vector<std::string> c = splitCsv(line);
  const std::vector<std::string>& head = t.head;
  if (c.size() != head.size())
    bad(head.size(),
        std::to_string(c.size()) + " cells where the header has " + std::to_string(head.size()));
  EnsembleRun r;
  readRunCells(c, t, named, bad, r);
  r.debris = !c[t.firstDebris].empty();
  if (r.debris) {
    readDebrisCells(c, t, bad, r);
    readCoverCell(c.back(), head.size() - 1, bad, r);
  } else {
    for (std::size_t k = t.firstDebris; k < c.size(); ++k)
      if (!c[k].empty()) bad(k, "a row without debris figures has '" + c[k] + "' here");
  }
  return r;
}

}  // namespace

EnsembleData readEnsembleTable(const std::string& text, std::size_t sweptCount) {
  EnsembleData data;
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line.empty()) throw std::runtime_error("it is empty (no header)");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  data.header = line;
  TableColumns t;
  t.head = splitCsv(line);
  readFixedColumns(sweptCount, t, data);
  readDebrisColumns(t, data);
  if (text.back() != '\n')
    throw std::runtime_error("it ends in the middle of a row (no line end after its last line)");
  int lineNo = 1;
  const BadCell bad{t.head, lineNo};
  while (nextTableLine(in, line, lineNo)) data.runs.push_back(readRunRow(line, t, data.named, bad));
  return data;
}

}  // namespace c2d
