#include "macro/batch/Merge.h"

#include <algorithm>
#include <climits>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "core/InputFile.h"
#include "core/io/AtomicFile.h"
#include "macro/deck/Limits.h"
#include "macro/studies/Csv.h"
#include "macro/studies/CurveOverlay.h"
#include "macro/batch/DeckRun.h"
#include "macro/batch/Shard.h"
#include "macro/studies/EnsembleStudy.h"
#include "macro/studies/EnsembleTable.h"
#include "macro/studies/RunTiming.h"

namespace c2d {

namespace {

namespace fs = std::filesystem;

// A part refused: the message says why; file names it when it is not the
// file being read.
struct Refused : std::runtime_error {
  explicit Refused(const std::string& why, fs::path in = {})
      : std::runtime_error(why), file(std::move(in)) {}
  fs::path file;
};

// The most a part's file may hold: far above what 10000 runs write.
constexpr std::uintmax_t kMaxPartBytes = std::uintmax_t{1} << 30;

// A part's text: a regular file of at most kMaxPartBytes, or refused.
std::string readPart(const fs::path& p) {
  try {
    return readRegularFile(p, kMaxPartBytes);
  } catch (const UnfitInputFile& e) {
    throw Refused(e.what());
  }
}

// "2, 5, 7" (the first ten, then the count).
std::string missingParts(const std::set<int>& parts, int n) {
  std::string missing;
  int count = 0;
  for (int i = 1; i <= n; ++i) {
    if (parts.count(i)) continue;
    if (++count <= 10) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
  }
  if (count > 10) missing += ", ... (" + std::to_string(count) + " parts)";
  return missing;
}

// A part's file must be the one its manifest was written with.
void checkFingerprint(const std::string& text, const std::string& recorded) {
  const std::string actual = contentFingerprint(text);
  if (actual != recorded)
    throw Refused("its text is not the one its part wrote (fingerprint " + actual +
                  ", the manifest's " + recorded +
                  "): a file of another deck or run, or changed since");
}

// "2, 4, 6, ... (50 runs)".
std::string runList(const std::vector<int>& runs) {
  std::string s;
  for (std::size_t i = 0; i < runs.size() && i < 6; ++i)
    s += (i ? ", " : "") + std::to_string(runs[i]);
  if (runs.size() > 6) s += ", ...";
  if (runs.empty()) s = "none";
  return s + " (" + std::to_string(runs.size()) + " run" + (runs.size() == 1 ? "" : "s") + ")";
}

// The plans table's columns that hold text; the others hold numbers (or are
// empty: a failed run's debris, the site limits without a site).
bool textColumn(const std::string& name) {
  return name == "stem" || name == "status" || name == "reason" || name == "site" ||
         name == "at_rest";
}

// The rows of a part's plans table (run number, line), every cell checked.
std::vector<std::pair<int, std::string>> planRows(const std::string& text, std::string& header) {
  if (text.empty()) throw Refused("it is empty (no header)");
  if (text.back() != '\n')
    throw Refused("it ends in the middle of a row (no line end after its last line)");
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (!header.empty() && line != header) throw Refused("its columns differ from part 1's");
  header = line;
  const std::vector<std::string> head = splitCsv(line);
  const auto status = std::find(head.begin(), head.end(), "status") - head.begin();
  if (head.size() < 4 || head[0] != "run" || head[1] != "stem" ||
      status == static_cast<long>(head.size()))
    throw Refused("its header is not a plans table's (run,stem,...,status,...)");
  std::vector<std::pair<int, std::string>> rows;
  int lineNo = 1;
  while (nextTableLine(in, line, lineNo)) {
    const std::vector<std::string> c = splitCsv(line);
    const std::string at = "line " + std::to_string(lineNo) + ": ";
    if (c.size() != head.size())
      throw Refused(at + std::to_string(c.size()) + " cells where the header has " +
                    std::to_string(head.size()));
    const auto run = countCell(c[0], 1, DeckLimits::kMaxRuns);
    if (!run) throw Refused(at + "'" + c[0] + "' is not a run number");
    if (c[status] != "ok" && c[status] != "failed")
      throw Refused(at + "the status is '" + c[status] + "', not ok or failed");
    for (std::size_t k = 2; k < c.size(); ++k)
      if (!textColumn(head[k]) && !c[k].empty() && !numberCell(c[k]))
        throw Refused(at + "'" + c[k] + "' in column " + head[k] + " is not a number");
    rows.emplace_back(*run, line);
  }
  return rows;
}

// The runs shard i of n makes of a deck of `runs` runs.
std::vector<int> shardRuns(int i, int n, int runs) {
  std::vector<int> out;
  for (int k = i; k <= runs; k += n) out.push_back(k);
  return out;
}

struct StudyFiles {
  std::map<int, fs::path> manifests;
  std::map<int, std::map<std::string, fs::path>> tables;  // part -> kind -> file
  std::set<int> parts() const {
    std::set<int> p;
    for (const auto& [i, f] : manifests) p.insert(i);
    for (const auto& [i, f] : tables) p.insert(i);
    return p;
  }
};

// A row of the joined table: its run, the part it came from, its text, and
// for an ensemble its plan and sample.
struct JoinedRow {
  int run = 0, part = 0;
  std::string line;
  int plan = 0, sample = 0;
};

// What the parts read so far make of the study.
struct Joined {
  ShardManifest first;  // part 1's manifest
  std::string header;
  std::vector<JoinedRow> rows;
  CurveOverlay overlay;
  std::vector<std::pair<int, std::string>> timing;  // (run, line) of the parts' timing tables
  int timingParts = 0;
};

ShardManifest readManifest(const fs::path& file, int i, int n, const Joined& joined) {
  ShardManifest m;
  try {
    m = readShardManifest(readPart(file));
  } catch (const Refused&) {
    throw;
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const IoError*>(&e)) throw;
    throw Refused(e.what());
  }
  if (m.part != i || m.parts != n)
    throw Refused("it says part " + std::to_string(m.part) + " of " + std::to_string(m.parts) +
                  ": it was copied from another part");
  const ShardManifest& first = joined.first;
  if (i > 1 && (m.fingerprint != first.fingerprint || m.runs != first.runs ||
                m.table != first.table || m.swept != first.swept))
    throw Refused("it was written by another deck than part 1 (" + m.deck + ", fingerprint " +
                  m.fingerprint + ", " + std::to_string(m.runs) + " runs; part 1: " + first.deck +
                  ", fingerprint " + first.fingerprint + ", " + std::to_string(first.runs) +
                  " runs)");
  return m;
}

// The runs of a part's table, its rows added to joined.
std::vector<int> readTable(const std::string& text, int i, const ShardManifest& m, Joined& joined) {
  std::vector<int> runs;
  if (m.table == "plans") {
    for (auto& [run, line] : planRows(text, joined.header)) {
      runs.push_back(run);
      joined.rows.push_back({run, i, std::move(line)});
    }
    return runs;
  }
  EnsembleData d;
  try {
    d = readEnsembleTable(text, m.swept.size());
  } catch (const std::runtime_error& e) {
    throw Refused(e.what());
  }
  if (!joined.header.empty() && d.header != joined.header)
    throw Refused("its columns differ from part 1's");
  joined.header = d.header;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  for (const EnsembleRun& r : d.runs) {
    do std::getline(in, line);
    while (line.empty() || line == "\r");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    runs.push_back(r.run);
    joined.rows.push_back({r.run, i, line, r.plan, r.sample});
  }
  return runs;
}

// A part's timing table (RunTiming.h): the runs of its ensemble table, added to joined.
void readTimingPart(const fs::path& timing, const std::vector<int>& runs, Joined& joined,
                    fs::path& file) {
  file = timing;
  std::vector<std::pair<int, std::string>> rows;
  try {
    rows = readTimingRows(readPart(file));
  } catch (const Refused&) {
    throw;
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const IoError*>(&e)) throw;
    throw Refused(e.what());
  }
  std::vector<int> held;
  for (const auto& [run, line] : rows) held.push_back(run);
  if (held != runs)
    throw Refused("it holds runs " + runList(held) + ", where its ensemble table holds runs " +
                  runList(runs));
  joined.timing.insert(joined.timing.end(), rows.begin(), rows.end());
  ++joined.timingParts;
}

// Part i of n of the study: its manifest, table and curves, checked and added
// to joined. Throws Refused naming the file (file is set to it).
void readStudyPart(const fs::path& dir, const std::string& stem, int i, int n,
                   const StudyFiles& files, Joined& joined, fs::path& file) {
  const std::string tag = "_part" + std::to_string(i) + "of" + std::to_string(n);
  file = dir / (stem + tag + "_manifest.csv");
  if (!files.manifests.count(i))
    throw Refused("missing: the part was not written by `collapse2d run --shard " +
                  std::to_string(i) + "/" + std::to_string(n) +
                  "` of this program, or its run did not end");
  const ShardManifest m = readManifest(file, i, n, joined);
  if (i == 1) joined.first = m;
  const auto kinds = files.tables.find(i);
  const bool present = kinds != files.tables.end() && kinds->second.count(m.table);
  file = dir / (stem + tag + "_" + m.table + ".csv");
  if (!present) throw Refused("missing (the part's manifest names it)");
  const std::string text = readPart(file);
  const std::vector<int> runs = readTable(text, i, m, joined);
  const std::vector<int> expected = shardRuns(i, n, m.runs);
  if (runs != expected)
    throw Refused("it holds runs " + runList(runs) + ", where part " + std::to_string(i) + " of " +
                  std::to_string(n) + " of this deck (" + std::to_string(m.runs) +
                  " runs) holds runs " + runList(expected));
  checkFingerprint(text, m.tableHash);
  if (kinds != files.tables.end() && m.table == "ensemble" && kinds->second.count("timing"))
    readTimingPart(kinds->second.at("timing"), runs, joined, file);
  if (m.curves == 0) return;
  file = dir / (stem + tag + "_curves.csv");
  if (!fs::exists(fs::symlink_status(file)))
    throw Refused("missing (the part's manifest counts " + std::to_string(m.curves) +
                  " runs' curves)");
  const std::string curves = readPart(file);
  checkFingerprint(curves, m.curvesHash);
  try {
    joined.overlay.addCsv(curves);
  } catch (const std::runtime_error& e) {
    throw Refused(e.what());
  }
}

// An ensemble's runs in order number its plans and samples in order: a row
// whose plan or sample disagrees with its run is refused (in its part's file).
void checkEnsembleOrder(const std::vector<JoinedRow>& rows, const fs::path& dir,
                        const std::string& stem, int n) {
  int plan = 0, sample = 0;  // before run 1
  for (const JoinedRow& r : rows) {
    if ((r.plan == plan && r.sample == sample + 1) || (r.plan == plan + 1 && r.sample == 1)) {
      plan = r.plan;
      sample = r.sample;
      continue;
    }
    throw Refused("line of run " + std::to_string(r.run) + ": plan " + std::to_string(r.plan) +
                      ", sample " + std::to_string(r.sample) + " does not follow plan " +
                      std::to_string(plan) + ", sample " + std::to_string(sample) +
                      " of the run before (plans and samples are numbered in run order)",
                  dir / (stem + "_part" + std::to_string(r.part) + "of" + std::to_string(n) +
                         "_ensemble.csv"));
  }
}

// The parts' CPU times in run order as <stem>_timing.csv, when every part has them.
void writeJoinedTiming(const fs::path& dir, const std::string& stem, int n, Joined& joined,
                       std::ostream& out) {
  if (joined.timingParts == 0) return;
  if (joined.timingParts < n) {
    out << "  " << stem << "_timing.csv not written: " << joined.timingParts << " of " << n
        << " parts have their CPU times\n";
    return;
  }
  std::stable_sort(joined.timing.begin(), joined.timing.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string text = std::string(kTimingHeader) + "\n";
  for (const auto& [run, line] : joined.timing) text += line + "\n";
  const fs::path file = dir / (stem + "_timing.csv");
  AtomicFile::write(file, text);
  out << "  " << file.filename().string() << "\n";
}

// Writes the joined table and what follows from it; returns the log's text.
std::string writeJoined(const fs::path& dir, const std::string& stem, int n, Joined& joined,
                        std::ostream& out) {
  std::ostringstream logText;
  std::string text = joined.header + "\n";
  for (const JoinedRow& r : joined.rows) text += r.line + "\n";
  const fs::path file = dir / (stem + "_" + joined.first.table + ".csv");
  AtomicFile::write(file, text);
  if (joined.first.table == "plans") {
    int failed = 0;
    const auto head = splitCsv(joined.header);
    const auto status = std::find(head.begin(), head.end(), "status") - head.begin();
    for (const JoinedRow& r : joined.rows) failed += splitCsv(r.line)[status] == "failed";
    out << file.filename().string() << ": " << joined.rows.size() << " plans from " << n
        << " parts, " << failed << " failed\n";
    logText << "  plans: " << file.filename().string() << " (" << joined.rows.size() << " runs, "
            << failed << " failed)\n";
  } else {
    const EnsembleStudyReport report = writeEnsembleStudy(
        dir, stem, readEnsembleTable(text, joined.first.swept.size()), joined.first.title);
    out << file.filename().string() << ": " << joined.rows.size() << " runs from " << n
        << " parts\n"
        << report.summary;
    for (const auto& f : report.files) out << "  " << f.filename().string() << "\n";
    writeJoinedTiming(dir, stem, n, joined, out);
    logText << "  ensemble: " << file.filename().string() << " (" << joined.rows.size()
            << " runs)\n\n"
            << report.text;
  }
  joined.overlay.sortByRun();
  for (const auto& f : joined.overlay.write(dir, stem)) {
    out << "  overlay of the runs: " << f.filename().string() << "\n";
    logText << "  overlay of the runs: " << f.filename().string() << "\n";
  }
  return logText.str();
}

// One deck's study; false when refused (message on err).
bool mergeStudy(const fs::path& dir, const std::string& stem, int n, const StudyFiles& files,
                std::ostream& out, std::ostream& err, std::string* log) {
  const std::string set = stem + "_part<i>of" + std::to_string(n);
  if (const std::string missing = missingParts(files.parts(), n); !missing.empty()) {
    err << "collapse2d merge: " << set << ": part"
        << (missing.find(',') == std::string::npos ? " " : "s ") << missing << " of " << n
        << " missing; not merged\n";
    return false;
  }
  Joined joined;
  fs::path file;
  try {
    for (int i = 1; i <= n; ++i) readStudyPart(dir, stem, i, n, files, joined, file);
    std::stable_sort(joined.rows.begin(), joined.rows.end(),
                     [](const JoinedRow& a, const JoinedRow& b) { return a.run < b.run; });
    if (joined.first.table == "ensemble") checkEnsembleOrder(joined.rows, dir, stem, n);
  } catch (const Refused& e) {
    err << "collapse2d merge: " << (e.file.empty() ? file : e.file).string() << ": " << e.what()
        << "; " << set << " is not merged\n";
    return false;
  }
  const std::string text = writeJoined(dir, stem, n, joined, out);
  if (log) *log = text;
  return true;
}

bool mergeBatch(const fs::path& dir, int n, const std::map<int, fs::path>& parts, std::ostream& out,
                std::ostream& err) {
  std::set<int> present;
  for (const auto& [i, f] : parts) present.insert(i);
  if (const std::string missing = missingParts(present, n); !missing.empty()) {
    err << "collapse2d merge: batch.csv: part"
        << (missing.find(',') == std::string::npos ? " " : "s ") << missing << " of " << n
        << " missing; not merged\n";
    return false;
  }
  std::vector<std::vector<BatchResult>> tables;
  for (const auto& [i, file] : parts) {
    try {
      tables.push_back(readBatchCsv(readPart(file)));
    } catch (const IoError&) {
      throw;
    } catch (const std::runtime_error& e) {
      err << "collapse2d merge: " << file.string() << ": " << e.what()
          << "; batch.csv is not merged\n";
      return false;
    }
  }
  // A deck in several parts had its runs split: then every part holds it alone.
  std::map<std::string, std::vector<int>> where;
  for (std::size_t i = 0; i < tables.size(); ++i)
    for (const BatchResult& r : tables[i]) where[r.deck].push_back(static_cast<int>(i) + 1);
  for (const auto& [deck, in] : where) {
    const bool split =
        in.size() == static_cast<std::size_t>(n) &&
        std::all_of(tables.begin(), tables.end(), [](const auto& t) { return t.size() == 1; });
    if (in.size() > 1 && !split) {
      err << "collapse2d merge: " << parts.at(in[1]).string() << ": deck " << deck << " is in part "
          << in[0] << " too (a part copied over another?); batch.csv is not merged\n";
      return false;
    }
  }
  std::vector<BatchResult> merged;
  for (const auto& rows : tables)
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
      // Each count of a part is at most INT_MAX (readBatchCsv): the sum stops there.
      for (auto [sum, add] : {std::pair{&it->runs, r.runs}, {&it->steps, r.steps},
                              {&it->iterations, r.iterations}, {&it->debrisRuns, r.debrisRuns},
                              {&it->outsideRuns, r.outsideRuns}})
        *sum = *sum > INT_MAX - add ? INT_MAX : *sum + add;
      it->seconds += r.seconds;
    }
  AtomicFile::write(dir / "batch.csv", batchCsv(merged));
  out << "batch.csv: " << merged.size() << " deck" << (merged.size() == 1 ? "" : "s") << " from "
      << n << " parts\n";
  printBatchTable(out, merged);
  return true;
}

// The parts found in a folder: the studies' files by (stem, n), the batch
// tables by n and i, and the files whose names hold counts out of range.
struct Found {
  std::map<std::pair<std::string, int>, StudyFiles> studies;
  std::map<int, std::map<int, fs::path>> batches;
  std::vector<std::pair<fs::path, std::string>> badNames;  // file, why
};

// Part i of n as a file's name gives them: 1 <= i <= n, 2 <= n <= kMaxShards.
bool partCounts(const std::string& i, const std::string& n, const fs::path& file, Found& found,
                std::pair<int, int>& counts) {
  const auto parts = countCell(n, 2, kMaxShards);
  const auto part = parts ? countCell(i, 1, *parts) : std::nullopt;
  if (part) {
    counts = {*part, *parts};
    return true;
  }
  found.badNames.emplace_back(
      file, "its name says part " + i + " of " + n + ", where parts are 1 to n of n from 2 to " +
                std::to_string(kMaxShards) + " (not written by `collapse2d run --shard`)");
  return false;
}

Found findParts(const fs::path& dir) {
  Found found;
  const std::regex part(
      R"((.+)_part([0-9]+)of([0-9]+)_(manifest|plans|ensemble|curves|timing)\.csv)");
  const std::regex batch(R"(batch_part([0-9]+)of([0-9]+)\.csv)");
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    std::pair<int, int> c;
    if (std::regex_match(name, m, part)) {
      if (!partCounts(m[2], m[3], entry.path(), found, c)) continue;
      StudyFiles& s = found.studies[{m[1].str(), c.second}];
      if (m[4] == "manifest")
        s.manifests[c.first] = entry.path();
      else
        s.tables[c.first][m[4].str()] = entry.path();
    } else if (std::regex_match(name, m, batch) && partCounts(m[1], m[2], entry.path(), found, c)) {
      found.batches[c.second][c.first] = entry.path();
    }
  }
  return found;
}

// Sets of parts that would write one file (a stem's parts in 2 and in 3, from
// before and after an edit): none of them is merged.
bool clashingSets(const Found& found, const std::string& stem, int n, std::ostream& err) {
  std::string others;
  for (const auto& [key, files] : found.studies)
    if (key.first == stem && key.second != n)
      others += (others.empty() ? "" : ", ") + std::to_string(key.second);
  if (others.empty()) return false;
  err << "collapse2d merge: " << stem << "_part<i>of" << n << ": the folder holds parts of " << stem
      << " in " << others << " too (an earlier split?): they would write the same "
      << stem << " tables; remove the stale set; not merged\n";
  return true;
}

int mergeAll(const fs::path& dir, std::ostream& out, std::ostream& err) {
  if (!fs::is_directory(dir)) {
    err << "collapse2d merge: no directory '" << dir.string() << "'\n";
    return 1;
  }
  const Found found = findParts(dir);
  for (const auto& [file, why] : found.badNames)
    err << "collapse2d merge: " << file.string() << ": " << why << "; not merged\n";
  if (found.studies.empty() && found.batches.empty()) {
    if (found.badNames.empty())
      err << "collapse2d merge: no parts (*_part<i>of<n>_*.csv, batch_part<i>of<n>.csv) in '"
          << dir.string() << "'\n";
    return 1;
  }
  int status = found.badNames.empty() ? 0 : 1;
  for (const auto& [key, files] : found.studies)
    if (clashingSets(found, key.first, key.second, err) ||
        !mergeStudy(dir, key.first, key.second, files, out, err, nullptr))
      status = 1;
  if (found.batches.size() > 1) {
    err << "collapse2d merge: batch_part<i>of<n>.csv: the folder holds batch parts of "
        << found.batches.size() << " splits (n = " << found.batches.begin()->first << ", "
        << std::next(found.batches.begin())->first
        << (found.batches.size() > 2 ? ", ..." : "")
        << "): they would write the same batch.csv; remove the stale ones; not merged\n";
    return 1;
  }
  for (const auto& [n, parts] : found.batches)
    if (!mergeBatch(dir, n, parts, out, err)) status = 1;
  return status;
}

}  // namespace

bool mergeStudyParts(const fs::path& dir, const std::string& stem, int n, std::ostream& out,
                     std::ostream& err, std::string* log) {
  const Found found = findParts(dir);
  const auto it = found.studies.find({stem, n});
  return mergeStudy(dir, stem, n, it == found.studies.end() ? StudyFiles{} : it->second, out, err,
                    log);
}

int mergeParts(const fs::path& dir, std::ostream& out, std::ostream& err) {
  try {
    return mergeAll(dir, out, err);
  } catch (const IoError& e) {
    err << "collapse2d merge: I/O error: " << e.what() << "\n";
  } catch (const fs::filesystem_error& e) {
    err << "collapse2d merge: I/O error: " << e.code().message();
    if (!e.path1().empty()) err << ": '" << e.path1().string() << "'";
    err << "\n";
  } catch (const std::exception& e) {
    // Never an abort: whatever a part holds ends with a message and a status.
    err << "collapse2d merge: internal error: " << e.what() << "\n";
  }
  return kExitInternal;
}

}  // namespace c2d
