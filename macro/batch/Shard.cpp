#include "macro/batch/Shard.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

#include "core/io/AtomicFile.h"
#include "macro/studies/Csv.h"
#include "macro/deck/DeckReader.h"
#include "macro/deck/Limits.h"

namespace c2d {

const char* const kBatchHeader =
    "deck,status,exit,signal,runs,steps,iterations,wall_s,debris_runs,outside_runs";


namespace {

const char* const kManifestHeader = "key,value";

}  // namespace

std::string contentFingerprint(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string deckFingerprint(const std::string& path) {
  std::string records;  // every record's text, a line each
  for (const Record& r : DeckReader::readFile(path)) {
    records += r.lineText();
    records += '\n';
  }
  return contentFingerprint(records);
}

void writeShardManifest(const std::filesystem::path& dir, const std::string& partStem,
                        const ShardManifest& m) {
  std::string swept;
  for (const std::string& n : m.swept) swept += (swept.empty() ? "" : " ") + n;
  std::string out = std::string(kManifestHeader) + "\n";
  for (const auto& [k, v] :
       std::vector<std::pair<std::string, std::string>>{{"deck", m.deck},
                                                        {"fingerprint", m.fingerprint},
                                                        {"part", std::to_string(m.part)},
                                                        {"parts", std::to_string(m.parts)},
                                                        {"runs", std::to_string(m.runs)},
                                                        {"table", m.table},
                                                        {"swept", swept},
                                                        {"title", m.title},
                                                        {"curves", std::to_string(m.curves)},
                                                        {"table_hash", m.tableHash},
                                                        {"curves_hash", m.curvesHash}})
    out += k + "," + csvCell(v) + "\n";
  AtomicFile::write(dir / (partStem + "_manifest.csv"), out);
}

ShardManifest readShardManifest(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != kManifestHeader)
    throw std::runtime_error(text.empty() ? "the manifest is empty" : "not a part's manifest");
  std::map<std::string, std::string> kv;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto c = splitCsv(line);
    if (c.size() != 2) throw std::runtime_error("a manifest line without key and value: " + line);
    kv[c[0]] = c[1];
  }
  ShardManifest m;
  auto need = [&](const char* key) -> const std::string& {
    const auto it = kv.find(key);
    if (it == kv.end()) throw std::runtime_error(std::string("the manifest has no ") + key);
    return it->second;
  };
  auto whole = [&](const char* key, int lo, int hi) {
    const std::string& text = need(key);
    const auto v = countCell(text, lo, hi);
    if (!v)
      throw std::runtime_error(std::string("the manifest's ") + key + " '" + text +
                               "' is not a whole number from " + std::to_string(lo) + " to " +
                               std::to_string(hi));
    return *v;
  };
  m.deck = need("deck");
  m.fingerprint = need("fingerprint");
  m.part = whole("part", 1, kMaxShards);
  m.parts = whole("parts", 2, kMaxShards);
  m.runs = whole("runs", 1, DeckLimits::kMaxRuns);
  m.table = need("table");
  if (m.table != "plans" && m.table != "ensemble")
    throw std::runtime_error("the manifest's table is '" + m.table + "'");
  std::istringstream names(need("swept"));
  for (std::string n; names >> n;) m.swept.push_back(n);
  m.title = need("title");
  m.curves = whole("curves", 0, m.runs);
  m.tableHash = need("table_hash");
  m.curvesHash = need("curves_hash");
  return m;
}

std::string ShardSpec::tag() const {
  return "part" + std::to_string(index) + "of" + std::to_string(count);
}

bool parseShard(const std::string& text, ShardSpec& spec) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) return false;
  const auto n = countCell(text.substr(slash + 1), 1, kMaxShards);
  const auto i = n ? countCell(text.substr(0, slash), 1, *n) : std::nullopt;
  if (!i) return false;
  spec.index = *i;
  spec.count = *n;
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
    throw std::runtime_error(text.empty() ? std::string("it is empty")
                                          : "not a batch table (its first line is not '" +
                                                std::string(kBatchHeader) + "')");
  if (text.back() != '\n')
    throw std::runtime_error("it ends in the middle of a row (no line end after its last line)");
  int lineNo = 1;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty()) continue;
    const auto c = splitCsv(line);
    const std::string at = "line " + std::to_string(lineNo) + ": ";
    if (c.size() != 10)
      throw std::runtime_error(at + std::to_string(c.size()) + " cells where the header has 10");
    BatchResult r;
    r.deck = c[0];
    r.started = c[1] != "not run";
    r.timedOut = c[1] == "timed out";
    constexpr int kMaxCount = std::numeric_limits<int>::max();
    static const char* names[] = {"exit",       "signal",      "runs",        "steps",
                                  "iterations", "debris_runs", "outside_runs"};
    static const int highest[] = {255, 128, DeckLimits::kMaxRuns, kMaxCount, kMaxCount,
                                  DeckLimits::kMaxRuns, DeckLimits::kMaxRuns};
    int* ints[] = {&r.exitCode, &r.signal, &r.runs, &r.steps, &r.iterations, &r.debrisRuns, &r.outsideRuns};
    for (int k = 0; k < 7; ++k) {
      const std::string& cell = c[k < 5 ? 2 + k : 3 + k];
      const auto v = countCell(cell, 0, highest[k]);
      if (!v)
        throw std::runtime_error(at + "'" + cell + "' in column " + names[k] +
                                 " is not a whole number from 0 to " + std::to_string(highest[k]));
      *ints[k] = *v;
    }
    const auto wall = numberCell(c[7]);
    if (!wall || *wall < 0)
      throw std::runtime_error(at + "'" + c[7] + "' in column wall_s is not a number of seconds");
    r.seconds = *wall;
    results.push_back(r);
  }
  return results;
}

void writeBatchPart(const std::filesystem::path& dir, const ShardSpec& spec,
                    const std::vector<BatchResult>& results) {
  AtomicFile::write(dir / ("batch_" + spec.tag() + ".csv"), batchCsv(results));
}

}  // namespace c2d
