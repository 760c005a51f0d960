#include "macro/studies/PlanTable.h"

#include <algorithm>

#include "core/io/AtomicFile.h"

namespace c2d {

int PlanTable::failed() const {
  return static_cast<int>(
      std::count_if(rows_.begin(), rows_.end(), [](const PlanRow& r) { return !r.ok; }));
}

std::string PlanTable::header() const {
  std::string h = named_ ? "run,stem,name" : "run,stem";
  for (const std::string& n : names_) {
    h += ',';
    h += csvCell(n);
  }
  h += ",status,reason,";
  return h + debrisCsvHeader(zones_);
}

std::string PlanTable::csv() const {
  // Empty debris cells: as many as the debris header has columns.
  const std::string header = debrisCsvHeader(zones_);
  const std::string noDebris(
      static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')), ',');
  std::string out = this->header() + "\n";
  for (const PlanRow& r : rows_) {
    out += std::to_string(r.run);
    out += ',';
    out += csvCell(r.stem);
    if (named_) appendCell(out, csvCell(r.name));
    for (const std::string& n : names_) {
      out += ",";
      for (const auto& [name, value] : r.sweep)
        if (name == n) {
          out += exactSweepValue(value);
          break;
        }
    }
    std::string reason = r.reason.substr(0, r.reason.find('\n'));
    out += r.ok ? ",ok," : ",failed,";
    out += csvCell(reason);
    out += ',';
    out += r.debris ? debrisCsvRow(*r.debris, zones_) : noDebris;
    out += "\n";
  }
  return out;
}

void PlanTable::write(const std::filesystem::path& path) const { AtomicFile::write(path, csv()); }

}  // namespace c2d
