#include "macro/studies/RunTiming.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "macro/deck/Limits.h"
#include "macro/studies/Csv.h"

namespace c2d {

std::string timingCsv(const EnsembleTable& table) {
  std::string out = std::string(kTimingHeader) + "\n";
  char buf[96];
  for (const EnsembleRow& r : table.rows()) {
    std::snprintf(buf, sizeof buf, "%d,%d,%d,%.3f\n", r.run, r.plan, r.sample, r.cpuSeconds);
    out += buf;
  }
  return out;
}

std::vector<std::pair<int, std::string>> readTimingRows(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line != kTimingHeader)
    throw std::runtime_error(std::string("its header is not ") + kTimingHeader);
  if (text.back() != '\n')
    throw std::runtime_error("it ends in the middle of a row (no line end after its last line)");
  std::vector<std::pair<int, std::string>> rows;
  int lineNo = 1;
  while (nextTableLine(in, line, lineNo)) {
    const std::vector<std::string> c = splitCsv(line);
    const std::string at = "line " + std::to_string(lineNo) + ": ";
    if (c.size() != 4)
      throw std::runtime_error(at + std::to_string(c.size()) + " cells where the header has 4");
    constexpr int most = DeckLimits::kMaxRuns;
    const auto run = countCell(c[0], 1, most);
    if (!run || !countCell(c[1], 1, most) || !countCell(c[2], 1, most))
      throw std::runtime_error(at + "run, plan and sample must be counts");
    const auto cpu = numberCell(c[3]);
    if (!cpu || *cpu < 0) throw std::runtime_error(at + "'" + c[3] + "' is not a CPU time");
    rows.emplace_back(*run, line);
  }
  return rows;
}

}  // namespace c2d
