#include "macro/batch/ParallelRuns.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "core/io/AtomicFile.h"
#include "macro/run/Interrupt.h"
#include "macro/batch/Merge.h"

namespace c2d {

namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

}  // namespace

std::string joinPartLogs(const std::vector<std::string>& partLogs, const std::string& study) {
  // A run's section starts at "  collapse2d  <title>" followed by "  run k of R,
  // outputs ...", and ends at the next one or at the end of the runs.
  const std::regex runLine(R"(  run ([0-9]+) of [0-9]+, outputs .*)");
  std::string header;
  std::map<int, std::string> sections;
  for (std::size_t p = 0; p < partLogs.size(); ++p) {
    const std::vector<std::string> l = lines(partLogs[p]);
    std::vector<std::pair<std::size_t, int>> starts;  // line, run
    std::size_t end = l.size();
    for (std::size_t i = 0; i < l.size(); ++i) {
      std::smatch m;
      if (l[i] == kEndOfRuns) {
        end = i;
        break;
      }
      if (i + 1 < l.size() && l[i].rfind("  collapse2d  ", 0) == 0 &&
          std::regex_match(l[i + 1], m, runLine))
        starts.emplace_back(i, std::stoi(m[1]));
    }
    auto text = [&](std::size_t from, std::size_t to) {
      while (to > from && l[to - 1].empty()) --to;
      std::string t;
      for (std::size_t i = from; i < to; ++i) t += l[i] + "\n";
      return t;
    };
    if (p == 0) header = text(0, starts.empty() ? end : starts.front().first);
    for (std::size_t k = 0; k < starts.size(); ++k) {
      std::string& section = sections[starts[k].second];
      section = "\n";
      section += text(starts[k].first, k + 1 < starts.size() ? starts[k + 1].first : end);
    }
  }
  std::string out = header;
  out += "  its runs in " + std::to_string(partLogs.size()) + " processes (collapse2d run -j " +
         std::to_string(partLogs.size()) + "), each run's section in run order\n";
  for (const auto& [run, t] : sections) out += t;
  out += "\n" + study + "\n  run complete\n";
  return out;
}

int runDeckInParallel(const std::string& deck, const BatchOptions& options,
                      const DeckCalls& calls, std::ostream& out, std::ostream& err) {
  DeckPlan plan;
  try {
    plan = calls.plan(deck, options.deck.params);
  } catch (const DeckError& e) {
    err << e.what() << "\n";
    return kExitDeckError;
  } catch (const std::exception&) {
    return -1;  // the deck's own run says what is wrong
  }
  if (!plan.study || plan.runs < 2 || options.jobs < 2) return -1;
  const int n = std::min(options.jobs, plan.runs);
  std::vector<BatchJob> jobs;
  for (int i = 1; i <= n; ++i) {
    BatchJob j{deck, options.deck};
    j.options.shard = i;
    j.options.shards = n;
    jobs.push_back(j);
  }
  const std::vector<BatchResult> results = runBatch(jobs, options, calls, out);
  if (const int sig = pendingInterrupt(); sig != 0) return interruptExitCode(sig);
  int status = 0;
  for (const BatchResult& r : results) {
    if (r.ok()) continue;
    if (r.started && r.signal == 0 && !r.timedOut && r.exitCode == kExitAnalysisFailed) {
      status = kExitAnalysisFailed;  // some runs failed; the study has their rows
      continue;
    }
    printBatchTable(out, results);
    return r.exitCode != 0 ? r.exitCode : kExitInternal;
  }
  const fs::path dir = options.deck.outDir.empty() ? fs::path(".") : options.deck.outDir;
  const std::string stem = fs::path(deck).stem().string();
  try {
    std::string study;
    std::ostringstream quiet;  // -q: the study's summary is in the log only
    if (!mergeStudyParts(dir, stem, n, options.deck.quiet ? quiet : out, err, &study)) return 1;
    std::vector<std::string> logs;
    for (int i = 1; i <= n; ++i) {
      std::ifstream in(dir /
                       (stem + "_part" + std::to_string(i) + "of" + std::to_string(n) + ".out"));
      std::ostringstream s;
      s << in.rdbuf();
      logs.push_back(s.str());
    }
    AtomicFile::write(dir / (stem + ".out"), joinPartLogs(logs, study));
    for (int i = 1; i <= n; ++i) {
      const std::string part = stem + "_part" + std::to_string(i) + "of" + std::to_string(n);
      for (const char* suffix :
           {".out", "_manifest.csv", "_plans.csv", "_ensemble.csv", "_curves.csv", "_timing.csv"})
        fs::remove(dir / (part + suffix));
    }
  } catch (const IoError& e) {
    err << "collapse2d run: I/O error: " << e.what() << "\n";
    return kExitInternal;
  } catch (const fs::filesystem_error& e) {
    err << "collapse2d run: I/O error: " << e.code().message() << "\n";
    return kExitInternal;
  }
  return status;
}

}  // namespace c2d
