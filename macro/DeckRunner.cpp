#include "macro/DeckRunner.h"

#include <algorithm>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "core/io/AtomicFile.h"
#include "macro/CheckPass.h"
#include "macro/ExecutePass.h"
#include "macro/run/ProblemRun.h"
#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/run/Interrupt.h"
#include "macro/deck/Suggest.h"
#include "macro/studies/RunTiming.h"
#include "macro/run/StaleOutputs.h"
#include "macro/draws/Sweep.h"
#include "macro/batch/Shard.h"
#include "macro/studies/StudySize.h"
#include "macro/studies/EnsembleStudy.h"
#include "macro/studies/EnsembleTable.h"
#include "macro/output/NumberText.h"

namespace c2d {

namespace {

// The longest stem of a deck's own outputs (as fitFileStem cuts a run's).
constexpr std::size_t kMaxDeckStem = 160;

// A named plan's tag is its name; else its swept values.
std::string planTag(const RunInfo& r) { return r.planName.empty() ? sweepTag(r.sweep) : r.planName; }

// "_s07" for sample 7 of 20 (as many digits as the count).
std::string sampleTag(int sample, int samples) {
  std::string k = std::to_string(sample);
  const std::size_t width = std::to_string(samples).size();
  return "_s" + std::string(width > k.size() ? width - k.size() : 0, '0') + k;
}

std::string paramLabel(const std::vector<std::string>& names, const RunInfo& run) {
  std::string label;
  for (const std::string& n : names) {
    const auto it = run.params.find(n);
    if (it == run.params.end()) continue;
    if (!label.empty()) label += ", ";
    label += n + " = " + formatSweepValue(it->second);
  }
  return label;
}

// Stems: the deck's stem for a lone run; <stem>_<tag> for the runs of a sweep,
// <stem>_<k> for the others (k counts every run of the deck from 1); a sweep
// whose tags repeat (a sweep inside a top-level LOOP) gets <stem>_<k>_<tag>.
// Labels: the sweep values; for the other runs of a study the parameters whose
// values differ between runs ("n = 2"), else "run k".
std::vector<RunPlan> planRuns(const std::vector<RunInfo>& runs, const std::string& stem) {
  const std::size_t n = runs.size();
  std::vector<RunPlan> plans(n);
  std::map<std::string, int> uses;
  for (std::size_t k = 0; k < n; ++k) {
    const RunInfo& r = runs[k];
    const std::string sample = r.sample > 0 ? sampleTag(r.sample, r.samples) : std::string();
    plans[k].stem = fitFileStem(!r.sweep.empty()       ? stem + "_" + planTag(r) + sample
                                : r.sample > 0         ? stem + sample
                                : n > 1                ? stem + "_" + std::to_string(k + 1)
                                                       : stem);
    plans[k].plan = r.plan;
    plans[k].sample = r.sample;
    plans[k].drawn = r.drawn;
    plans[k].planName = r.planName;
    ++uses[plans[k].stem];
  }
  for (std::size_t k = 0; k < n; ++k)
    if ((!runs[k].sweep.empty() || runs[k].sample > 0) && uses[plans[k].stem] > 1)
      plans[k].stem = fitFileStem(stem + "_" + std::to_string(k + 1) +
                                  (runs[k].sweep.empty() ? "" : "_" + planTag(runs[k])) +
                                  (runs[k].sample > 0 ? sampleTag(runs[k].sample, runs[k].samples) : ""));

  std::set<std::string> names;
  for (const RunInfo& r : runs)
    for (const auto& [name, v] : r.params) names.insert(name);
  std::vector<std::string> differing;
  for (const std::string& name : names) {
    std::set<double> values;
    bool missing = false;
    for (const RunInfo& r : runs) {
      if (!r.sweep.empty() || r.sample > 0) continue;
      const auto it = r.params.find(name);
      if (it == r.params.end())
        missing = true;
      else
        values.insert(it->second);
    }
    if (values.size() > 1 || (missing && !values.empty())) differing.push_back(name);
  }
  for (std::size_t k = 0; k < n; ++k) {
    plans[k].label =
        !runs[k].sweep.empty() ? planLabel(runs[k].sweep, runs[k].planName)
        : runs[k].sample > 0   ? std::string()
                               : paramLabel(differing, runs[k]);
    if (runs[k].sample > 0)
      plans[k].label += (plans[k].label.empty() ? "sample " : ", sample ") + std::to_string(runs[k].sample);
    if (plans[k].label.empty() && n > 1) plans[k].label = "run " + std::to_string(k + 1);
  }
  return plans;
}

}  // namespace

namespace {

// The drawn names of the deck's ensemble in order of first appearance.
std::vector<std::string> drawnNames(const std::vector<RunInfo>& runs) {
  std::vector<std::string> names;
  for (const RunInfo& r : runs)
    for (const auto& [name, v] : r.drawn)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

// The protected zones of every run, in order of first appearance.
std::vector<std::string> studyZones(const std::vector<RunInfo>& runs) {
  std::vector<std::string> names;
  for (const RunInfo& r : runs)
    for (const std::string& z : r.zones)
      if (std::find(names.begin(), names.end(), z) == names.end()) names.push_back(z);
  return names;
}

// The swept names of the deck in order of first appearance (the plans table's columns).
std::vector<std::string> sweptNames(const std::vector<RunInfo>& runs) {
  std::vector<std::string> names;
  for (const RunInfo& r : runs)
    for (const auto& [name, v] : r.sweep)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

}  // namespace

namespace {

// A value given from outside the deck (--set) whose name no PARAmeter record
// of the deck assigns: it would change nothing, silently.
class UnusedParameter : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void checkOverridesUsed(const Parameters& params, const std::string& path) {
  const std::vector<std::string> unused = params.overridesUnused();
  if (unused.empty()) return;
  const std::string hint = didYouMean(unused[0], params.names());
  throw UnusedParameter(path + ": parameter '" + unused[0] +
                        "' is given (--set, params) but no PARAmeter record of the deck assigns it" +
                        (hint.empty() ? std::string() : ": " + hint));
}

// " given q=15 mu=0.3": the values given from outside (--set), so that parts
// of a study run with other values are not merged as one study.
std::string givenText(const std::map<std::string, double>& given) {
  std::string s;
  for (const auto& [name, v] : given) s += (s.empty() ? " given " : " ") + name + "=" + exactNumber(v);
  return s;
}

}  // namespace

std::string shardStem(const std::string& stem, const DeckOptions& options) {
  if (options.shards <= 1) return stem;
  return stem + "_part" + std::to_string(options.shard) + "of" + std::to_string(options.shards);
}

namespace {

// "out/a.failed.out, out/a_tplot.failed.csv"
std::string fileList(const std::vector<std::filesystem::path>& files) {
  std::string s;
  for (const auto& f : files) s += (s.empty() ? "" : ", ") + f.string();
  return s;
}

}  // namespace

DeckPlan planDeck(const std::string& path, const SolutionCommands& commands,
                  const std::map<std::string, double>& given) {
  const Deck deck = parseDeck(path);
  std::ostringstream discard;
  Parameters params;
  params.setOverrides(given);
  const DeckOptions options;
  CheckPass check(commands, options, discard);
  check.walk(deck.items, params);
  DeckPlan plan;
  plan.runs = check.runs();
  for (const RunInfo& r : check.infos()) plan.study = plan.study || !r.sweep.empty() || r.sample > 0;
  return plan;
}

namespace {

// The deck's log: written through a temporary that becomes <log> when the
// whole deck has run; a failed or interrupted deck keeps it as
// <stem>.failed.out or <stem>.interrupted.out, with the reason as its last
// lines. And the outputs a failed or interrupted run kept.
struct DeckLog {
  std::unique_ptr<AtomicFile> file;
  std::vector<std::filesystem::path> kept;

  void keep(std::string_view tag, const std::string& why) {
    if (!file) return;
    try {
      file->stream() << "\n  *** run " << tag << "\n" << why << "\n";
      kept.insert(kept.begin(), file->keep(tag));
    } catch (...) {
      // The log cannot be written (the reason is the message already).
    }
  }
  std::string keptText() const {
    return kept.empty() ? std::string() : "\n  computed results kept: " + fileList(kept);
  }
};

// A failed run whose deck has values that look like another unit names them.
std::string unitText(const Warnings& warnings) {
  const std::string at = warnings.unitLocations();
  if (at.empty()) return std::string();
  return "\n  advice: the deck's warnings name values that look like another unit (" + at +
         "): check them first";
}

// What the check pass planned: the runs' facts and their stems and labels.
struct CheckedDeck {
  std::vector<RunInfo> infos;
  std::vector<RunPlan> plans;
  bool ensemble = false;  // the runs are an ENSEmble's samples
};

// The check pass: everything bound with a scratch parameter table, its log discarded.
CheckedDeck checkDeck(const Deck& deck, const std::string& path, const std::string& stem,
                      const DeckOptions& options, const SolutionCommands& commands,
                      Warnings& warnings) {
  std::ostringstream discard;
  Parameters checkParams;
  checkParams.setOverrides(options.params);
  CheckPass check(commands, options, discard, &warnings);
  check.walk(deck.items, checkParams);
  checkOverridesUsed(checkParams, path);
  CheckedDeck checked;
  checked.infos = check.infos();
  checked.plans = planRuns(checked.infos, stem);
  const auto& infos = checked.infos;
  checked.ensemble =
      std::any_of(infos.begin(), infos.end(), [](const RunInfo& r) { return r.sample > 0; });
  if (checked.ensemble && std::any_of(infos.begin(), infos.end(), [](const RunInfo& r) { return r.sample == 0; })) {
    const Record& h = *check.ensembleHead();
    throw DeckError(h[0].loc, "a deck with an ENSEmble runs its study alone: another problem of this deck runs outside it",
                    h.excerpt(h[0].loc), "put the other problems in decks of their own");
  }
  return checked;
}

// The deck's log opened (its stem checked, an earlier failed or interrupted
// run's log removed), with its head: the deck, its warnings, the given values.
std::unique_ptr<AtomicFile> openLog(const std::filesystem::path& dir, const std::string& partStem,
                                    const std::string& path, const DeckOptions& options,
                                    const Warnings& warnings) {
  // The deck's outputs add at most ~60 characters to its stem (the runs'
  // stems are cut to 160 by fitFileStem): a longer stem would lose the
  // study's tables to "File name too long" after all the computing.
  if (partStem.size() > kMaxDeckStem)
    throw IoError("the deck's outputs would be named '" + partStem.substr(0, 40) + "...' (" +
                  std::to_string(partStem.size()) + " characters, at most " +
                  std::to_string(kMaxDeckStem) +
                  " before the suffixes of its files): give the deck a shorter name");
  removeStaleOutputs(dir, partStem);  // an earlier failed or interrupted run's log
  auto log = std::make_unique<AtomicFile>(dir /
                                          (options.logName.empty() ? partStem + ".out" : options.logName));
  log->stream() << "  collapse2d  " << path << "\n";
  for (const DeckWarning& w : warnings.list()) log->stream() << w.str() << "\n";
  for (const auto& [name, v] : options.params)
    log->stream() << "  given: " << name << " = " << exactNumber(v) << " (in place of the deck's value)\n";
  return log;
}

// Where the deck's own outputs go and what they are named after.
struct DeckFiles {
  std::string path;              // the deck
  std::string stem, partStem;    // the deck's stem; a shard's <stem>_part<i>of<n>
  std::filesystem::path dir;     // the output directory
};

// After the runs: the overlay (a shard of a study: its curves, for `collapse2d
// merge`), the plans or ensemble table (and, unsharded, the ensemble's study),
// a shard's manifest. Returns the ensemble study's summary for the console.
std::string writeStudyOutputs(const ExecutePass& runner, const DeckFiles& f,
                              const DeckOptions& options, int plannedRuns,
                              const std::vector<std::string>& swept, std::ostream& log) {
  std::string studySummary;
  // A shard of a study: its overlays are drawn by `collapse2d merge` from
  // the parts' curves (a part without a study's table draws its own).
  const bool studyPart = options.shards > 1 && (runner.planTable() || runner.ensembleTable());
  std::string curvesText, tableText;  // a part's, for its manifest's fingerprints
  if (studyPart && runner.overlay().numRuns() > 0)
    AtomicFile::write(f.dir / (f.partStem + "_curves.csv"), curvesText = runner.overlay().csv());
  else
    for (const auto& file : runner.overlay().write(f.dir, f.partStem))
      log << "\n  overlay of the runs: " << file.filename().string() << "\n";
  if (const auto& table = runner.planTable()) {
    const std::filesystem::path file = f.dir / (f.partStem + "_plans.csv");
    AtomicFile::write(file, tableText = table->csv());
    log << "\n  plans: " << file.filename().string() << " (" << table->rows().size()
        << " runs, " << table->failed() << " failed)\n";
  }
  if (const auto& table = runner.ensembleTable()) {
    const std::string text = tableText = table->csv();
    const std::filesystem::path file = f.dir / (f.partStem + "_ensemble.csv");
    AtomicFile::write(file, text);
    AtomicFile::write(f.dir / (f.partStem + "_timing.csv"), timingCsv(*table));
    log << "\n  ensemble: " << file.filename().string() << " (" << table->rows().size()
        << " runs, " << table->failed() << " failed; CPU times in " << f.partStem
        << "_timing.csv)\n";
    // A shard's table is a part: `collapse2d merge` makes the study of the whole.
    if (options.shards <= 1) {
      const EnsembleStudyReport report =
          writeEnsembleStudy(f.dir, f.stem, readEnsembleTable(text, swept.size()), runner.title());
      log << "\n" << report.text;
      studySummary = report.summary;
    }
  }
  if (options.shards > 1 && (runner.planTable() || runner.ensembleTable()))
    writeShardManifest(f.dir, f.partStem,
                       {f.path, deckFingerprint(f.path) + givenText(options.params), options.shard,
                        options.shards, plannedRuns, runner.ensembleTable() ? "ensemble" : "plans",
                        swept, runner.title(), runner.overlay().numRuns(),
                        contentFingerprint(tableText),
                        curvesText.empty() ? std::string() : contentFingerprint(curvesText)});
  return studySummary;
}

// The outcome of the runs: the totals, the runs this part executed, a study's
// failed runs; the log committed, the deck's summary on the console.
void finishRuns(DeckOutcome& outcome, const ExecutePass& runner, const DeckFiles& f,
                const DeckOptions& options, bool ensemble, const Warnings& warnings,
                AtomicFile& log, const std::string& studySummary, std::ostream& out) {
  outcome.total = runner.total();
  outcome.runs = runner.runs();
  outcome.failedRuns = runner.failed();
  int executed = outcome.runs;
  if (options.shards > 1) {
    executed = outcome.runs >= options.shard ? (outcome.runs - options.shard) / options.shards + 1 : 0;
    outcome.runs = executed;
  }
  if (outcome.failedRuns > 0) {
    log.stream() << "\n  run complete: " << outcome.failedRuns << " of " << executed
                 << " runs failed\n";
    outcome.exitCode = kExitAnalysisFailed;
    outcome.message = f.path + ": " + std::to_string(outcome.failedRuns) + " of " +
                      std::to_string(executed) + " runs of the study failed (see " + f.partStem +
                      (ensemble ? "_ensemble.csv" : "_plans.csv") + " and the log)" + unitText(warnings);
  } else {
    log.stream() << "\n  run complete\n";
  }
  log.commit();
  if (!options.quiet)
    out << f.path << ": " << (executed == 1 ? "" : std::to_string(executed) + " runs, ")
        << (outcome.failedRuns ? std::to_string(outcome.failedRuns) + " failed, " : "")
        << runSummaryText(outcome.total) << "\n"
        << studySummary;
}

// The outcome of a deck that failed with `error`: its exit code and message,
// its log kept under a tagged name. `printWarnings`: the deck's warnings
// printed (a deck error or an unused given value).
void failDeck(DeckOutcome& outcome, const std::exception_ptr& error, const std::string& path,
              DeckLog& log, const Warnings& warnings, const std::function<void()>& printWarnings) {
  try {
    std::rethrow_exception(error);
  } catch (const DeckError& e) {
    printWarnings();
    outcome.exitCode = kExitDeckError;
    outcome.message = e.what();
    outcome.errorAt = e.loc();
    log.keep("failed", e.what());
    outcome.message += log.keptText();
  } catch (const UnusedParameter& e) {
    printWarnings();
    outcome.exitCode = kExitUsage;
    outcome.message = e.what();
  } catch (const AnalysisError& e) {
    outcome.exitCode = kExitAnalysisFailed;
    log.keep("failed", e.what() + unitText(warnings));
    outcome.message = e.what() + unitText(warnings) + log.keptText();
  } catch (const Interrupted& e) {
    outcome.exitCode = interruptExitCode(e.signal());
    outcome.interrupted = e.signal();
    const std::string msg = path + ": " + e.what();
    log.keep("interrupted", msg);
    outcome.message = msg + log.keptText();
  } catch (const IoError& e) {
    outcome.exitCode = kExitInternal;
    const std::string msg = path + ": I/O error: " + e.what();
    log.keep("failed", msg);
    outcome.message = msg + log.keptText();
  } catch (const std::filesystem::filesystem_error& e) {
    outcome.exitCode = kExitInternal;
    std::string msg = path + ": I/O error: " + e.code().message();
    if (!e.path1().empty()) msg += ": '" + e.path1().string() + "'";
    log.keep("failed", msg);
    outcome.message = msg + log.keptText();
  } catch (const std::exception& e) {
    outcome.exitCode = kExitInternal;
    const std::string msg = std::string(path) + ": internal error: " + e.what();
    log.keep("failed", msg);
    outcome.message = msg + log.keptText();
  }
}

}  // namespace

DeckOutcome runDeck(const std::string& path, const DeckOptions& options,
                    const SolutionCommands& commands, std::ostream& out) {
  DeckOutcome outcome;
  Warnings warnings;
  bool printed = false;
  auto printWarnings = [&] {
    if (printed) return;
    printed = true;
    for (const DeckWarning& w : warnings.list()) std::cerr << w.str() << "\n";
    outcome.warnings = warnings.list();
  };
  DeckLog log;
  try {
    const Deck deck = parseDeck(path);
    DeckFiles f{path, std::filesystem::path(path).stem().string(), {}, {}};
    const CheckedDeck checked = checkDeck(deck, path, f.stem, options, commands, warnings);
    printWarnings();
    throwIfInterrupted("the start");

    f.dir = options.outDir.empty() ? std::filesystem::path(".") : options.outDir;
    std::filesystem::create_directories(f.dir);
    f.partStem = shardStem(f.stem, options);
    log.file = openLog(f.dir, f.partStem, path, options, warnings);
    DeckOptions runOptions = options;
    runOptions.safePoint = [&log] { log.file->check(); };
    Parameters params;
    params.setOverrides(options.params);
    ExecutePass runner(commands, runOptions, log.file->stream(), &out, checked.plans, f.stem);
    const auto& infos = checked.infos;
    const std::vector<std::string> swept = sweptNames(infos);
    const bool named =
        std::any_of(infos.begin(), infos.end(), [](const RunInfo& r) { return !r.planName.empty(); });
    if (checked.ensemble)
      runner.setEnsembleTable(EnsembleTable(swept, drawnNames(infos), studyZones(infos), named));
    else if (!swept.empty())
      runner.setPlanTable(PlanTable(swept, studyZones(infos), named));
    std::string studySummary;
    try {
      if (!checked.plans.empty()) runner.walk(deck.items, params);
      if (options.shards > 1) log.file->stream() << "\n" << kEndOfRuns << "\n";
      studySummary = writeStudyOutputs(runner, f, options, static_cast<int>(checked.plans.size()),
                                       swept, log.file->stream());
    } catch (...) {
      log.kept = runner.kept();
      throw;
    }
    finishRuns(outcome, runner, f, options, checked.ensemble, warnings, *log.file, studySummary,
               out);
  } catch (...) {
    failDeck(outcome, std::current_exception(), path, log, warnings, printWarnings);
  }
  return outcome;
}

DeckCalls deckCalls(const SolutionCommands& commands) {
  DeckCalls calls;
  calls.run = [&commands](const std::string& deck, const DeckOptions& options, std::ostream& out) {
    return runDeck(deck, options, commands, out);
  };
  calls.plan = [&commands](const std::string& deck, const std::map<std::string, double>& params) {
    return planDeck(deck, commands, params);
  };
  return calls;
}

}  // namespace c2d
