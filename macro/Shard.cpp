#include "macro/Shard.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "core/AtomicFile.h"
#include "macro/PlanTable.h"

namespace c2d {

namespace {

// Cells of one CSV line (quoted cells may hold commas and doubled quotes).
std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else if (c != '\r') {
      cells.back() += c;
    }
  }
  return cells;
}

std::vector<std::string> readLines(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);)
    if (!l.empty() && l != "\r") lines.push_back(l);
  return lines;
}

const char* kBatchHeader =
    "deck,status,exit,signal,runs,steps,iterations,wall_s,debris_runs,outside_runs";

// A complete set of parts 1..n, or the message naming the missing ones.
std::string missingParts(const std::map<int, std::filesystem::path>& parts, int n) {
  std::string missing;
  for (int i = 1; i <= n; ++i)
    if (!parts.count(i)) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
  return missing;
}

}  // namespace

std::string ShardSpec::tag() const {
  return "part" + std::to_string(index) + "of" + std::to_string(count);
}

bool parseShard(const std::string& text, ShardSpec& spec) {
  int i = 0, n = 0;
  char slash = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &i, &slash, &n, &extra) != 3 || slash != '/')
    return false;
  if (n < 1 || i < 1 || i > n) return false;
  spec.index = i;
  spec.count = n;
  return true;
}

std::vector<std::string> shardDecks(const std::vector<std::string>& decks, const ShardSpec& spec,
                                    DeckOptions& deck) {
  if (!spec.active()) return decks;
  if (decks.size() == 1) {
    deck.shard = spec.index;
    deck.shards = spec.count;
    return decks;
  }
  std::vector<std::string> mine;
  for (std::size_t k = 0; k < decks.size(); ++k)
    if (static_cast<int>(k % static_cast<std::size_t>(spec.count)) == spec.index - 1)
      mine.push_back(decks[k]);
  return mine;
}

std::string batchCsv(const std::vector<BatchResult>& results) {
  std::string out = std::string(kBatchHeader) + "\n";
  char buf[256];
  for (const BatchResult& r : results) {
    std::snprintf(buf, sizeof buf, ",%d,%d,%d,%d,%d,%.3f,%d,%d\n", r.exitCode, r.signal, r.runs,
                  r.steps, r.iterations, r.seconds, r.debrisRuns, r.outsideRuns);
    out += csvCell(r.deck);
    out += ',';
    out += csvCell(r.status());
    out += buf;
  }
  return out;
}

std::vector<BatchResult> readBatchCsv(const std::string& text) {
  std::vector<BatchResult> results;
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != kBatchHeader)
    throw std::runtime_error("not a batch table (its first line is not '" +
                             std::string(kBatchHeader) + "')");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto c = splitCsv(line);
    if (c.size() != 10) throw std::runtime_error("a batch table row without 10 cells: " + line);
    BatchResult r;
    r.deck = c[0];
    r.started = c[1] != "not run";
    r.timedOut = c[1] == "timed out";
    r.exitCode = std::stoi(c[2]);
    r.signal = std::stoi(c[3]);
    r.runs = std::stoi(c[4]);
    r.steps = std::stoi(c[5]);
    r.iterations = std::stoi(c[6]);
    r.seconds = std::stod(c[7]);
    r.debrisRuns = std::stoi(c[8]);
    r.outsideRuns = std::stoi(c[9]);
    results.push_back(r);
  }
  return results;
}

void writeBatchPart(const std::filesystem::path& dir, const ShardSpec& spec,
                    const std::vector<BatchResult>& results) {
  AtomicFile::write(dir / ("batch_" + spec.tag() + ".csv"), batchCsv(results));
}

int mergeParts(const std::filesystem::path& dir, std::ostream& out, std::ostream& err) {
  if (!std::filesystem::is_directory(dir)) {
    err << "collapse2d merge: no directory '" << dir.string() << "'\n";
    return 1;
  }
  // (name of the joined file, n) -> part index -> file
  std::map<std::pair<std::string, int>, std::map<int, std::filesystem::path>> sets;
  const std::regex plans(R"((.+)_part([0-9]+)of([0-9]+)_plans\.csv)");
  const std::regex batch(R"(batch_part([0-9]+)of([0-9]+)\.csv)");
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (std::regex_match(name, m, plans))
      sets[{m[1].str() + "_plans.csv", std::stoi(m[3])}][std::stoi(m[2])] = entry.path();
    else if (std::regex_match(name, m, batch))
      sets[{"batch.csv", std::stoi(m[2])}][std::stoi(m[1])] = entry.path();
  }
  if (sets.empty()) {
    err << "collapse2d merge: no parts (*_part<i>of<n>_plans.csv, batch_part<i>of<n>.csv) in '"
        << dir.string() << "'\n";
    return 1;
  }
  int status = 0;
  for (const auto& [key, parts] : sets) {
    const auto& [joined, n] = key;
    if (const std::string missing = missingParts(parts, n); !missing.empty()) {
      err << "collapse2d merge: " << joined << ": part"
          << (missing.find(',') == std::string::npos ? " " : "s ") << missing << " of " << n
          << " missing\n";
      status = 1;
      continue;
    }
    if (joined == "batch.csv") {
      // One row per deck, in order of first appearance; a deck split over the
      // parts (its runs sharded) sums its counts and keeps the first failure.
      std::vector<BatchResult> merged;
      for (const auto& [i, file] : parts) {
        std::ifstream in(file);
        std::stringstream ss;
        ss << in.rdbuf();
        std::vector<BatchResult> rows;
        try {
          rows = readBatchCsv(ss.str());
        } catch (const std::exception& e) {
          err << "collapse2d merge: " << file.string() << ": " << e.what() << "\n";
          status = 1;
          continue;
        }
        for (const BatchResult& r : rows) {
          auto it = std::find_if(merged.begin(), merged.end(),
                                 [&](const BatchResult& m) { return m.deck == r.deck; });
          if (it == merged.end()) {
            merged.push_back(r);
            continue;
          }
          if (it->ok() && !r.ok()) {
            it->exitCode = r.exitCode;
            it->signal = r.signal;
          }
          it->runs += r.runs;
          it->steps += r.steps;
          it->iterations += r.iterations;
          it->seconds += r.seconds;
          it->debrisRuns += r.debrisRuns;
          it->outsideRuns += r.outsideRuns;
        }
      }
      AtomicFile::write(dir / joined, batchCsv(merged));
      out << joined << ": " << merged.size() << " deck" << (merged.size() == 1 ? "" : "s")
          << " from " << n << " parts\n";
      printBatchTable(out, merged);
      continue;
    }
    // Plans: the same header in every part, rows ordered by run number.
    std::string header;
    std::vector<std::pair<int, std::string>> rows;
    bool consistent = true;
    for (const auto& [i, file] : parts) {
      const auto lines = readLines(file);
      if (lines.empty()) continue;
      if (header.empty()) header = lines[0];
      if (lines[0] != header) {
        err << "collapse2d merge: " << file.string()
            << ": its columns differ from the other parts'\n";
        consistent = false;
        break;
      }
      for (std::size_t k = 1; k < lines.size(); ++k)
        rows.emplace_back(std::atoi(lines[k].c_str()), lines[k]);
    }
    if (!consistent || header.empty()) {
      if (header.empty()) err << "collapse2d merge: " << joined << ": the parts are empty\n";
      status = 1;
      continue;
    }
    std::stable_sort(rows.begin(), rows.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::string text = header + "\n";
    int failed = 0;
    for (const auto& [run, line] : rows) {
      text += line + "\n";
      const auto cells = splitCsv(line);
      if (std::find(cells.begin(), cells.end(), "failed") != cells.end()) ++failed;
    }
    AtomicFile::write(dir / joined, text);
    out << joined << ": " << rows.size() << " plans from " << n << " parts, " << failed
        << " failed\n";
  }
  return status;
}

}  // namespace c2d
