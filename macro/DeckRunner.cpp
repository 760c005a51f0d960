#include "macro/DeckRunner.h"

#include <fstream>
#include <sstream>

#include "macro/DeckParser.h"

namespace c2d {

namespace {

// Walks the top-level items: PARAmeter blocks, problems, loops. In the check
// pass every problem is bound only; in the run pass bound and run.
class Walker {
 public:
  Walker(const SolutionCommands& commands, const DeckOptions& options, std::string stem,
         std::ostream& log, bool execute, int totalRuns)
      : commands_(commands), options_(options), stem_(std::move(stem)), log_(log),
        execute_(execute), totalRuns_(totalRuns) {}

  void walk(const std::vector<TopItem>& items, Parameters& params) {
    for (const TopItem& item : items) {
      if (const auto* pb = std::get_if<ParamBlock>(&item)) {
        pb->apply(params);
      } else if (const auto* loop = std::get_if<TopLoop>(&item)) {
        const int n = loop->count.evalInt(params, "loop count");
        for (int i = 0; i < n; ++i) walk(loop->body, params);
      } else {
        runProblem(std::get<Problem>(item), params);
      }
    }
  }

  int runs() const { return runs_; }
  const RunSummary& total() const { return total_; }

 private:
  void runProblem(const Problem& p, Parameters& params) {
    ++runs_;
    RunOptions ro;
    ro.outDir = options_.outDir.empty() ? std::filesystem::path(".") : options_.outDir;
    ro.stem = totalRuns_ > 1 ? stem_ + "_" + std::to_string(runs_) : stem_;
    ro.progress = options_.progress && !options_.quiet;
    ro.solver = options_.solver;
    if (execute_) {
      log_ << "\n  collapse2d  " << p.title << "\n";
      log_ << "  run " << runs_ << " of " << totalRuns_ << ", outputs " << ro.stem << "\n\n";
    }
    ProblemRun run(p, params, commands_, ro, log_);
    run.bind(execute_);
    if (!execute_) return;
    run.run();
    const RunSummary s = run.summary();
    total_.steps += s.steps;
    total_.iterations += s.iterations;
    total_.cuts += s.cuts;
    total_.hinges += s.hinges;
    total_.energyError = std::max(total_.energyError, s.energyError);
    total_.seconds += s.seconds;
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "\n  summary: %d steps, %d iterations, %d cuts, %d hinges, energy error %.3e\n",
                  s.steps, s.iterations, s.cuts, s.hinges, s.energyError);
    log_ << buf;
  }

  const SolutionCommands& commands_;
  const DeckOptions& options_;
  std::string stem_;
  std::ostream& log_;
  bool execute_;
  int totalRuns_;
  int runs_ = 0;
  RunSummary total_;
};

}  // namespace

DeckOutcome runDeck(const std::string& path, const DeckOptions& options,
                    const SolutionCommands& commands, std::ostream& out) {
  DeckOutcome outcome;
  const std::string stem = std::filesystem::path(path).stem().string();
  try {
    const Deck deck = parseDeck(path);
    // Check pass: bind everything with a scratch parameter table, log discarded.
    std::ostringstream discard;
    Parameters checkParams;
    Walker check(commands, options, stem, discard, false, 0);
    check.walk(deck.items, checkParams);

    const std::filesystem::path dir = options.outDir.empty() ? std::filesystem::path(".") : options.outDir;
    std::filesystem::create_directories(dir);
    const std::filesystem::path logPath = dir / (options.logName.empty() ? stem + ".out" : options.logName);
    std::ofstream log(logPath);
    if (!log) throw std::runtime_error("cannot write the log " + logPath.string());
    log << "  collapse2d  " << path << "\n";
    Parameters params;
    Walker runner(commands, options, stem, log, true, check.runs());
    try {
      runner.walk(deck.items, params);
    } catch (const std::exception& e) {
      log << "\n  *** run failed\n" << e.what() << "\n";
      throw;
    }
    log << "\n  run complete\n";
    outcome.total = runner.total();
    outcome.runs = runner.runs();
    if (!options.quiet) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "%s: %d run%s, %d steps, %d iterations, %d cuts, %d hinges, energy error %.2e, "
                    "%.2f s\n",
                    path.c_str(), outcome.runs, outcome.runs == 1 ? "" : "s", outcome.total.steps,
                    outcome.total.iterations, outcome.total.cuts, outcome.total.hinges,
                    outcome.total.energyError, outcome.total.seconds);
      out << buf;
    }
  } catch (const DeckError& e) {
    outcome.exitCode = kExitDeckError;
    outcome.message = e.what();
  } catch (const AnalysisError& e) {
    outcome.exitCode = kExitAnalysisFailed;
    outcome.message = e.what();
  } catch (const std::exception& e) {
    outcome.exitCode = kExitInternal;
    outcome.message = std::string(path) + ": internal error: " + e.what();
  }
  return outcome;
}

}  // namespace c2d
