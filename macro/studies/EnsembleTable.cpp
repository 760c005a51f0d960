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

EnsembleData readEnsembleTable(const std::string& text, std::size_t sweptCount) {
  EnsembleData data;
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line.empty()) throw std::runtime_error("it is empty (no header)");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  data.header = line;
  const std::vector<std::string> head = splitCsv(line);
  const auto status = std::find(head.begin(), head.end(), "status");
  const std::vector<std::string> numericsNames = splitCsv(kNumericsHeader);
  if (head.size() < 6 || head[0] != "run" || head[1] != "plan" || head[2] != "sample" ||
      head[3] != "stem" || status == head.end() || status + 1 == head.end() ||
      *(status + 1) != "reason" || head.back() != "cover")
    throw std::runtime_error(
        "its header is not an ensemble table's (run,plan,sample,stem,...,status,reason,...,cover)");
  const auto firstNumerics = static_cast<std::size_t>(status - head.begin()) + 2;
  if (head.size() < firstNumerics + kNumericsColumns ||
      !std::equal(numericsNames.begin(), numericsNames.end(),
                  head.begin() + static_cast<long>(firstNumerics)))
    throw std::runtime_error(std::string("its columns after reason are not ") + kNumericsHeader);
  const std::size_t firstDebris = firstNumerics + kNumericsColumns;
  // The plans' names, when the sweep names them, come after the stem.
  data.named = head[4] == "name";
  const std::size_t first = data.named ? 5 : 4;
  const std::size_t values = static_cast<std::size_t>(status - head.begin()) - first;
  if (sweptCount > values)
    throw std::runtime_error("its header has fewer value columns than swept names");
  data.swept.assign(head.begin() + static_cast<long>(first),
                    head.begin() + static_cast<long>(first + sweptCount));
  data.drawn.assign(head.begin() + static_cast<long>(first + sweptCount), status);
  const std::string debrisHeader = debrisCsvHeader();
  std::vector<std::string> debrisNames = splitCsv(debrisHeader);
  if (head.size() < firstDebris + debrisNames.size() + 1 ||
      !std::equal(debrisNames.begin(), debrisNames.end(),
                  head.begin() + static_cast<long>(firstDebris)))
    throw std::runtime_error("its debris columns are not this program's (" + debrisHeader + ")");
  // The zones' columns, in groups of kZoneColumns, up to `cover`.
  const std::size_t fixedCount = debrisNames.size();
  const std::size_t zoneCells = head.size() - 1 - firstDebris - fixedCount;
  const std::string group = zoneCsvHeader({"<zone>"});
  if (zoneCells % kZoneColumns.size() != 0)
    throw std::runtime_error("its zone columns are not groups of " + group);
  for (std::size_t k = 0; k < zoneCells; k += kZoneColumns.size()) {
    const auto at = head.begin() + static_cast<long>(firstDebris + fixedCount + k);
    const std::string zone = at->substr(std::min(at->size(), kZoneColumns[0].size()));
    const std::vector<std::string> names = splitCsv(zoneCsvHeader({zone}));
    if (at->rfind(kZoneColumns[0], 0) != 0 || !std::equal(names.begin(), names.end(), at))
      throw std::runtime_error("its zone columns are not groups of " + group + " (at '" + *at +
                               "')");
    data.zones.push_back(zone);
    debrisNames.insert(debrisNames.end(), names.begin(), names.end());
  }
  if (text.back() != '\n')
    throw std::runtime_error("it ends in the middle of a row (no line end after its last line)");
  int lineNo = 1;
  while (nextTableLine(in, line, lineNo)) {
    const std::vector<std::string> c = splitCsv(line);
    auto bad = [&](std::size_t col, const std::string& why) {
      throw std::runtime_error("line " + std::to_string(lineNo) +
                               (col < head.size() ? ", column " + head[col] : "") + ": " + why);
    };
    if (c.size() != head.size())
      bad(head.size(),
          std::to_string(c.size()) + " cells where the header has " + std::to_string(head.size()));
    EnsembleRun r;
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
    if (data.named) r.name = c[4];
    // A value a run does not have (a plan with fewer BLASt records) is empty: NaN.
    for (std::size_t i = first; i < first + values; ++i) {
      const auto v = c[i].empty() ? std::optional<double>(NAN) : numberCell(c[i]);
      if (!v) bad(i, "'" + c[i] + "' is not a number");
      (i < first + sweptCount ? r.swept : r.drawn).push_back(*v);
    }
    const std::string& st = c[firstNumerics - 2];
    if (st != "ok" && st != "failed")
      bad(firstNumerics - 2, "the status is '" + st + "', not ok or failed");
    r.ok = st == "ok";
    r.reason = c[firstNumerics - 1];
    r.numerics = readNumerics(c, firstNumerics, bad);
    r.debris = !c[firstDebris].empty();
    if (r.debris) {
      const std::size_t firstZone = fixedCount;
      for (std::size_t k = 0; k < debrisNames.size(); ++k) {
        const std::string& name = debrisNames[k];
        const std::string& cell = c[firstDebris + k];
        if (name == "site") {
          if (cell != "inside" && cell != "outside" && cell != "none")
            bad(firstDebris + k, "the site status is '" + cell + "'");
          r.site = cell;
        } else if (name == "verdict") {
          if (!cell.empty() && cell != "felled" && cell != "in place" && cell != "other way")
            bad(firstDebris + k, "the verdict is '" + cell + "'");
          r.verdict = cell;
        } else if (name == "at_rest") {
          if (cell != "yes" && cell != "no")
            bad(firstDebris + k, "at_rest is '" + cell + "', not yes or no");
          r.atRest = cell == "yes";
        } else if (!cell.empty() || (name != "site_xmin" && name != "site_xmax" &&
                                     name != "risk_level" && name != "risk_confidence" &&
                                     k < firstZone)) {
          const auto v = numberCell(cell);
          if (!v) bad(firstDebris + k, "'" + cell + "' is not a number");
          r.figures[name] = *v;
        }
      }
      const std::string& cover = c.back();
      std::size_t p = 0;
      while (p < cover.size()) {
        std::size_t e = cover.find(';', p);
        if (e == std::string::npos) e = cover.size();
        const std::string span = cover.substr(p, e - p);
        const std::size_t colon = span.find(':');
        const auto a =
            colon == std::string::npos ? std::nullopt : numberCell(span.substr(0, colon));
        const auto b =
            colon == std::string::npos ? std::nullopt : numberCell(span.substr(colon + 1));
        if (!a || !b) bad(head.size() - 1, "'" + span + "' is not an interval x0:x1");
        r.cover.emplace_back(*a, *b);
        p = e + 1;
      }
    } else {
      for (std::size_t k = firstDebris; k < c.size(); ++k)
        if (!c[k].empty()) bad(k, "a row without debris figures has '" + c[k] + "' here");
    }
    data.runs.push_back(std::move(r));
  }
  return data;
}

}  // namespace c2d
