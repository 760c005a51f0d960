#include "macro/studies/Merge.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "core/output/AtomicFile.h"
#include "macro/studies/Csv.h"
#include "macro/studies/CurveOverlay.h"
#include "macro/DeckRunner.h"
#include "macro/studies/Shard.h"
#include "macro/studies/EnsembleStudy.h"
#include "macro/studies/EnsembleTable.h"

namespace c2d {

namespace {

namespace fs = std::filesystem;

// A part refused: the message names its file.
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw IoError("cannot read '" + p.string() + "'");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw IoError("cannot read '" + p.string() + "'");
  return s.str();
}

std::string missingParts(const std::set<int>& parts, int n) {
  std::string missing;
  for (int i = 1; i <= n; ++i)
    if (!parts.count(i)) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
  return missing;
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
  if (head.size() < 4 || head[0] != "run" || head[1] != "stem")
    throw Refused("its header is not a plans table's (run,stem,...)");
  std::vector<std::pair<int, std::string>> rows;
  int lineNo = 1;
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> c = splitCsv(line);
    const std::string at = "line " + std::to_string(lineNo) + ": ";
    if (c.size() != head.size())
      throw Refused(at + std::to_string(c.size()) + " cells where the header has " +
                    std::to_string(head.size()));
    const auto run = integerCell(c[0]);
    if (!run || *run < 1) throw Refused(at + "'" + c[0] + "' is not a run number");
    const auto status = std::find(head.begin(), head.end(), "status") - head.begin();
    if (c[status] != "ok" && c[status] != "failed")
      throw Refused(at + "the status is '" + c[status] + "', not ok or failed");
    for (std::size_t k = 2; k < c.size(); ++k)
      if (!textColumn(head[k]) && !c[k].empty() && !numberCell(c[k]))
        throw Refused(at + "'" + c[k] + "' in column " + head[k] + " is not a number");
    rows.emplace_back(static_cast<int>(*run), line);
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

// One deck's study; false when refused (message on err).
bool mergeStudy(const fs::path& dir, const std::string& stem, int n, const StudyFiles& files,
                std::ostream& out, std::ostream& err, std::string* log) {
  std::ostringstream logText;
  const std::string set = stem + "_part<i>of" + std::to_string(n);
  if (const std::string missing = missingParts(files.parts(), n); !missing.empty()) {
    err << "collapse2d merge: " << set << ": part"
        << (missing.find(',') == std::string::npos ? " " : "s ") << missing << " of " << n
        << " missing; not merged\n";
    return false;
  }
  ShardManifest first;
  std::string header;
  std::vector<std::pair<int, std::string>> rows;  // run, line
  CurveOverlay overlay;
  for (int i = 1; i <= n; ++i) {
    const std::string tag = "_part" + std::to_string(i) + "of" + std::to_string(n);
    fs::path file = dir / (stem + tag + "_manifest.csv");
    try {
      if (!files.manifests.count(i))
        throw Refused("missing: the part was not written by `collapse2d run --shard " +
                      std::to_string(i) + "/" + std::to_string(n) +
                      "` of this program, or its run did not end");
      ShardManifest m;
      try {
        m = readShardManifest(slurp(file));
      } catch (const std::runtime_error& e) {
        if (dynamic_cast<const IoError*>(&e)) throw;
        throw Refused(e.what());
      }
      if (m.part != i || m.parts != n)
        throw Refused("it says part " + std::to_string(m.part) + " of " + std::to_string(m.parts) +
                      ": it was copied from another part");
      if (i == 1) {
        first = m;
      } else if (m.fingerprint != first.fingerprint || m.runs != first.runs ||
                 m.table != first.table || m.swept != first.swept) {
        throw Refused("it was written by another deck than part 1 (" + m.deck + ", fingerprint " +
                      m.fingerprint + ", " + std::to_string(m.runs) +
                      " runs; part 1: " + first.deck + ", fingerprint " + first.fingerprint + ", " +
                      std::to_string(first.runs) + " runs)");
      }
      const auto kinds = files.tables.find(i);
      const auto table = kinds == files.tables.end() ? nullptr : [&]() -> const fs::path* {
        const auto t = kinds->second.find(m.table);
        return t == kinds->second.end() ? nullptr : &t->second;
      }();
      file = dir / (stem + tag + "_" + m.table + ".csv");
      if (!table) throw Refused("missing (the part's manifest names it)");
      const std::string text = slurp(file);
      std::vector<int> runs;
      if (m.table == "plans") {
        for (auto& row : planRows(text, header)) {
          runs.push_back(row.first);
          rows.push_back(std::move(row));
        }
      } else {
        EnsembleData d;
        try {
          d = readEnsembleTable(text, m.swept.size());
        } catch (const std::runtime_error& e) {
          throw Refused(e.what());
        }
        if (!header.empty() && d.header != header)
          throw Refused("its columns differ from part 1's");
        header = d.header;
        std::istringstream in(text);
        std::string line;
        std::getline(in, line);
        for (const EnsembleRun& r : d.runs) {
          do std::getline(in, line);
          while (line.empty() || line == "\r");
          if (!line.empty() && line.back() == '\r') line.pop_back();
          runs.push_back(r.run);
          rows.emplace_back(r.run, line);
        }
      }
      const std::vector<int> expected = shardRuns(i, n, m.runs);
      if (runs != expected)
        throw Refused("it holds runs " + runList(runs) + ", where part " + std::to_string(i) +
                      " of " + std::to_string(n) + " of this deck (" + std::to_string(m.runs) +
                      " runs) holds runs " + runList(expected));
      if (m.curves > 0) {
        file = dir / (stem + tag + "_curves.csv");
        try {
          overlay.addCsv(slurp(file));
        } catch (const IoError&) {
          throw Refused("missing (the part's manifest counts " + std::to_string(m.curves) +
                        " runs' curves)");
        } catch (const std::runtime_error& e) {
          throw Refused(e.what());
        }
      }
    } catch (const Refused& e) {
      err << "collapse2d merge: " << file.string() << ": " << e.what() << "; " << set
          << " is not merged\n";
      return false;
    }
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string text = header + "\n";
  for (const auto& [run, line] : rows) text += line + "\n";
  const fs::path joined = dir / (stem + "_" + first.table + ".csv");
  AtomicFile::write(joined, text);
  if (first.table == "plans") {
    int failed = 0;
    const auto head = splitCsv(header);
    const auto status = std::find(head.begin(), head.end(), "status") - head.begin();
    for (const auto& [run, line] : rows) failed += splitCsv(line)[status] == "failed";
    out << joined.filename().string() << ": " << rows.size() << " plans from " << n << " parts, "
        << failed << " failed\n";
    logText << "  plans: " << joined.filename().string() << " (" << rows.size() << " runs, "
            << failed << " failed)\n";
  } else {
    const EnsembleStudyReport report =
        writeEnsembleStudy(dir, stem, readEnsembleTable(text, first.swept.size()), first.title);
    out << joined.filename().string() << ": " << rows.size() << " runs from " << n << " parts\n"
        << report.summary;
    for (const auto& f : report.files) out << "  " << f.filename().string() << "\n";
    logText << "  ensemble: " << joined.filename().string() << " (" << rows.size() << " runs)\n\n"
            << report.text;
  }
  overlay.sortByRun();
  for (const auto& f : overlay.write(dir, stem)) {
    out << "  overlay of the runs: " << f.filename().string() << "\n";
    logText << "  overlay of the runs: " << f.filename().string() << "\n";
  }
  if (log) *log = logText.str();
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
      tables.push_back(readBatchCsv(slurp(file)));
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
      it->runs += r.runs;
      it->steps += r.steps;
      it->iterations += r.iterations;
      it->seconds += r.seconds;
      it->debrisRuns += r.debrisRuns;
      it->outsideRuns += r.outsideRuns;
    }
  AtomicFile::write(dir / "batch.csv", batchCsv(merged));
  out << "batch.csv: " << merged.size() << " deck" << (merged.size() == 1 ? "" : "s") << " from "
      << n << " parts\n";
  printBatchTable(out, merged);
  return true;
}

// The files of the studies in dir, by (stem, n).
std::map<std::pair<std::string, int>, StudyFiles> studyFiles(const fs::path& dir) {
  std::map<std::pair<std::string, int>, StudyFiles> studies;
  const std::regex part(R"((.+)_part([0-9]+)of([0-9]+)_(manifest|plans|ensemble|curves)\.csv)");
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (!std::regex_match(name, m, part)) continue;
    StudyFiles& s = studies[{m[1].str(), std::stoi(m[3])}];
    const int i = std::stoi(m[2]);
    if (m[4] == "manifest")
      s.manifests[i] = entry.path();
    else
      s.tables[i][m[4].str()] = entry.path();
  }
  return studies;
}

int mergeAll(const fs::path& dir, std::ostream& out, std::ostream& err) {
  if (!fs::is_directory(dir)) {
    err << "collapse2d merge: no directory '" << dir.string() << "'\n";
    return 1;
  }
  const auto studies = studyFiles(dir);
  std::map<int, std::map<int, fs::path>> batches;
  const std::regex batch(R"(batch_part([0-9]+)of([0-9]+)\.csv)");
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (std::regex_match(name, m, batch)) batches[std::stoi(m[2])][std::stoi(m[1])] = entry.path();
  }
  if (studies.empty() && batches.empty()) {
    err << "collapse2d merge: no parts (*_part<i>of<n>_*.csv, batch_part<i>of<n>.csv) in '"
        << dir.string() << "'\n";
    return 1;
  }
  int status = 0;
  for (const auto& [key, files] : studies)
    if (!mergeStudy(dir, key.first, key.second, files, out, err, nullptr)) status = 1;
  for (const auto& [n, parts] : batches)
    if (!mergeBatch(dir, n, parts, out, err)) status = 1;
  return status;
}

}  // namespace

bool mergeStudyParts(const fs::path& dir, const std::string& stem, int n, std::ostream& out,
                     std::ostream& err, std::string* log) {
  const auto studies = studyFiles(dir);
  const auto it = studies.find({stem, n});
  return mergeStudy(dir, stem, n, it == studies.end() ? StudyFiles{} : it->second, out, err, log);
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
  }
  return kExitInternal;
}

}  // namespace c2d
