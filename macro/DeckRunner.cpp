#include "macro/DeckRunner.h"

#include <algorithm>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "core/output/AtomicFile.h"
#include "macro/studies/CurveOverlay.h"
#include "macro/deck/DeckParser.h"
#include "macro/run/Interrupt.h"
#include "macro/deck/Limits.h"
#include "macro/deck/ParameterNote.h"
#include "macro/deck/Suggest.h"
#include "macro/studies/PlanTable.h"
#include "macro/studies/RunTiming.h"
#include "macro/run/StaleOutputs.h"
#include "macro/studies/Sweep.h"
#include "macro/studies/Shard.h"
#include "macro/studies/StudySize.h"
#include "macro/studies/EnsembleStudy.h"
#include "macro/studies/EnsembleTable.h"

namespace c2d {

namespace {

// The longest stem of a deck's own outputs (as fitFileStem cuts a run's).
constexpr std::size_t kMaxDeckStem = 160;

// What the check pass learns about each run, to name it before anything runs.
struct RunInfo {
  SweepValues sweep;                     // empty outside a SWEEp
  std::string planName;                  // the SWEEp's PLAN name of its value set, if any
  std::map<std::string, double> params;  // the parameter table as the problem starts
  int plan = 0;                          // an ensemble's plan (1-based), 0 outside one
  int sample = 0, samples = 0;           // its sample 1..samples, 0 outside an ensemble
  DrawnValues drawn;                     // the sample's drawn values
  std::vector<std::string> zones;        // the site's protected zones (SITE)
};

// Output stem and legend label of each run, and what an ensemble's table says of it.
struct RunPlan {
  std::string stem, label;
  int plan = 0, sample = 0;
  DrawnValues drawn;
  std::string planName;  // the SWEEp's PLAN name, if any
};

// A named plan's tag and label is its name; else its swept values.
std::string planTag(const RunInfo& r) { return r.planName.empty() ? sweepTag(r.sweep) : r.planName; }
std::string planLabel(const SweepValues& sweep, const std::string& name) {
  return name.empty() ? sweepLabel(sweep) : name;
}

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

// A failure as the plans table gives it: its first line, the deck named
// without its directory ("deck.inp:41:5: error: ...").
std::string failureReason(const std::string& what) {
  std::string r = what.substr(0, what.find('\n'));
  const std::size_t e = r.find(": error: ");
  if (e != std::string::npos) {
    const std::size_t slash = r.rfind('/', e);
    if (slash != std::string::npos) r = r.substr(slash + 1);
  }
  return r;
}

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

// A name a study sets for each run cannot be given from outside the deck too:
// the study's tables and file names would show values the runs did not take.
void refuseOverride(const Parameters& params, const std::string& name, const Record& rec,
                    const std::string& how) {
  if (!params.overridden(name)) return;
  throw DeckError(rec[0].loc,
                  "'" + name + "' is " + how + " by this study for each run: it cannot also be given "
                  "from outside the deck (--set, params)",
                  rec.excerpt(rec[0].loc), "give the study's values here, or drop this name from the given ones");
}

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

// Walks the top-level items: PARAmeter blocks, problems, loops, sweeps. In the
// check pass every problem is bound only (and what names its run is noted); in
// the run pass bound and run.
class Walker {
 public:
  Walker(const SolutionCommands& commands, const DeckOptions& options, std::ostream& log,
         std::ostream* console, std::vector<RunPlan> plans, std::string stem = {},
         Warnings* warnings = nullptr)
      : commands_(commands),
        options_(options),
        log_(log),
        console_(console),
        execute_(!plans.empty()),
        plans_(std::move(plans)),
        stem_(std::move(stem)),
        warnings_(warnings) {}

  void walk(const std::vector<TopItem>& items, Parameters& params) {
    for (const TopItem& item : items) {
      if (const auto* pb = std::get_if<ParamBlock>(&item)) {
        pb->apply(params);
      } else if (const auto* loop = std::get_if<TopLoop>(&item)) {
        const int n = loop->count.evalInt(params, "loop count");
        if (n < 0 || n > DeckLimits::kMaxRuns) {
          const Record& h = loop->head;
          const SourceLoc at = loop->count.loc();
          throw DeckError(
              at,
              "top-level LOOP count " + std::to_string(n) +
                  (n < 0 ? " is negative"
                         : " is beyond the largest this program takes (" +
                               std::to_string(DeckLimits::kMaxRuns) + " runs of its problems)"),
              h.excerpt(at));
        }
        const StudySize::Scope scope(size_, loop->head, n,
                                     "the LOOP of line " + std::to_string(loop->head.loc.line) +
                                         ": " + std::to_string(n) + " passes");
        for (int i = 0; i < n; ++i) walk(loop->body, params);
      } else if (const auto* sweep = std::get_if<TopSweep>(&item)) {
        // The swept names may not be set again by the deck (Parameters::protect).
        for (const SweepVariable& v : sweep->variables) refuseOverride(params, v.name, v.record, "swept");
        const std::vector<SweepValues> sets = sweepRuns(*sweep, params);
        const std::vector<std::string> names = sweepPlanNames(*sweep);
        const std::string by = "swept by the SWEEp of line " + std::to_string(sweep->head.loc.line);
        const StudySize::Scope scope(size_, sweep->head, static_cast<long long>(sets.size()),
                                     "the SWEEp of line " + std::to_string(sweep->head.loc.line) +
                                         ": " + std::to_string(sets.size()) + " value sets");
        for (std::size_t k = 0; k < sets.size(); ++k) {
          const SweepValues& set = sets[k];
          sweep_ = set;
          planName_ = k < names.size() ? names[k] : std::string();
          for (const auto& [name, x] : sweep_) {
            params.set(name, x);
            params.protect(name, by);
          }
          walk(sweep->body, params);
        }
        for (const SweepVariable& v : sweep->variables) params.unprotect(v.name);
        sweep_.clear();
        planName_.clear();
      } else if (const auto* e = std::get_if<TopEnsemble>(&item)) {
        walkEnsemble(*e, params);
      } else {
        try {
          runProblem(std::get<Problem>(item), params);
        } catch (const DeckError& e) {
          throw noteParameters(e, params);
        }
      }
    }
  }

  const std::vector<RunInfo>& infos() const { return infos_; }
  int runs() const { return runs_; }
  const RunSummary& total() const { return total_; }
  const CurveOverlay& overlay() const { return overlay_; }
  // The study's table: set before walking when the deck has a SWEEp.
  void setPlanTable(PlanTable table) { planTable_ = std::move(table); }
  const std::optional<PlanTable>& planTable() const { return planTable_; }
  // The outputs a failed or interrupted run kept (tagged names).
  const std::vector<std::filesystem::path>& kept() const { return kept_; }
  // The ensemble's table: set before walking when the deck has an ENSEmble.
  void setEnsembleTable(EnsembleTable table) { ensembleTable_ = std::move(table); }
  const std::optional<EnsembleTable>& ensembleTable() const { return ensembleTable_; }
  // The first ENSEmble record walked, if any.
  const Record* ensembleHead() const { return ensembleHead_; }
  // The title of the last problem walked.
  const std::string& title() const { return title_; }

 private:
  // Every sample of the ensemble runs the body (PARAmeter blocks, the problem)
  // from the same parameter table, with its drawn values set (and protected).
  void walkEnsemble(const TopEnsemble& e, Parameters& params) {
    if (!ensembleHead_) ensembleHead_ = &e.head;
    for (const DrawRecord& d : e.draws) refuseOverride(params, d.name, d.record, "drawn");
    detonators_ = e.detonators ? &*e.detonators : nullptr;
    const EnsembleSpec spec = evaluateEnsemble(e, params);
    pairing_.check(e, spec, plan_ + 1);
    const Parameters base = params;
    const std::string by = "drawn by the ENSEmble of line " + std::to_string(e.head.loc.line);
    const StudySize::Scope scope(size_, e.head, spec.samples,
                                 "the ENSEmble of line " + std::to_string(e.head.loc.line) + ": " +
                                     std::to_string(spec.samples) + " samples");
    ++plan_;
    for (int k = 1; k <= spec.samples; ++k) {
      params = base;
      const SampleDraws draws = drawSample(spec, k);
      for (const auto& [name, v] : draws.values) {
        params.set(name, v);
        params.protect(name, by);
      }
      sample_ = &draws;
      samples_ = spec.samples;
      try {
        walk(e.body, params);
      } catch (const StudySizeError&) {
        throw;  // of the study, not of this sample's draws
      } catch (const DeckError& err) {
        // A value that only some draws make bad: say which sample drew what.
        std::string drawn;
        for (const auto& [name, v] : draws.values)
          drawn += (drawn.empty() ? "" : ", ") + name + " = " + formatSweepValue(v);
        throw DeckError(err.loc(),
                        err.message() + " (in sample " + std::to_string(k) + " of the ENSEmble of line " +
                            std::to_string(e.head.loc.line) + (drawn.empty() ? "" : ", which drew " + drawn) +
                            ")",
                        err.text(), err.hint());
      }
      sample_ = nullptr;
    }
    params = base;
  }

  void runProblem(const Problem& p, Parameters& params) {
    if (!execute_) {  // the planning: its size checked, a signal stops it
      size_.checkProblem(p.head, runs_, DeckLimits::kMaxRuns);
      throwIfInterrupted("the planning of run " + std::to_string(runs_ + 1));
    }
    ++runs_;
    title_ = RunOutputs::displayTitle(p.title);
    RunOptions ro;
    ro.outDir = options_.outDir.empty() ? std::filesystem::path(".") : options_.outDir;
    ro.progress = options_.progress && !options_.quiet;
    ro.solver = options_.solver;
    ro.sample = sample_;
    if (!execute_) {
      RunInfo info{sweep_, planName_, {}, sample_ ? plan_ : 0, sample_ ? sample_->sample : 0, samples_, {}, {}};
      for (const std::string& n : params.names()) info.params[n] = params.get(n);
      ro.warnings = warnings_;
      ProblemRun run(p, params, commands_, ro, log_);
      run.bind(false);
      if (sample_) {
        info.drawn = sample_->values;
        if (sample_->jitter) info.drawn.emplace_back("dt_factor", sample_->stepFactor);
        const std::vector<double>& blasts = run.drawnBlastTimes();
        if (sample_->detonators && blasts.empty() && warnings_ && detonators_)
          warnings_->add((*detonators_)[0].loc,
                         "DETOnators, and the problem has no BLASt record: there is no blast "
                         "time to scatter",
                         detonators_->excerpt((*detonators_)[0].loc));
        for (std::size_t i = 0; i < blasts.size(); ++i)
          info.drawn.emplace_back("blast_" + std::to_string(i + 1), blasts[i]);
      }
      info.zones = zoneNames(run.model().site());
      infos_.push_back(std::move(info));
      // PARA commands in the BATCh blocks change the table for what follows (a
      // later top-level LOOP count), as they will when the problem runs.
      params = run.boundParams();
      return;
    }
    // A count that depends on what ran (PARA inside a BATCh loop) may give more
    // runs than the check pass planned: they are numbered on.
    if (static_cast<std::size_t>(runs_) > plans_.size())
      plans_.push_back({stem_ + "_" + std::to_string(runs_), "run " + std::to_string(runs_), 0, 0, {}, {}});
    // A shard runs every n-th run only (runs k with k mod n == i - 1, k from 0).
    if (options_.shards > 1 && (runs_ - 1) % options_.shards != options_.shard - 1) return;
    const RunPlan plan = plans_.at(static_cast<std::size_t>(runs_ - 1));
    ro.stem = plan.stem;
    ro.label = plan.label;
    log_ << "\n  collapse2d  " << p.title << "\n";
    log_ << "  run " << runs_ << " of " << plans_.size() << ", outputs " << ro.stem
         << (plan.label.empty() ? "" : " (" + plan.label + ")") << "\n";
    if (!plan.drawn.empty()) {
      log_ << "  drawn:";
      for (std::size_t i = 0; i < plan.drawn.size(); ++i)
        log_ << (i ? ", " : " ") << plan.drawn[i].first << " = " << exactNumber(plan.drawn[i].second);
      log_ << "\n";
    }
    // The samples after an ensemble plan's first keep their tables (time
    // history, debris) and a short log: a study of hundreds of runs would
    // otherwise write gigabytes of pictures, animations and Newton lines.
    const bool brief = sample_ && sample_->sample > 1;
    ro.pictures = !brief;
    if (brief) log_ << "  (the log of a sample after the first: its summary and debris)\n";
    log_ << "\n";
    ro.safePoint = options_.safePoint;
    std::ostream discard(nullptr);
    ProblemRun run(p, params, commands_, ro, brief ? discard : log_);
    // A run of a study (SWEEp, ENSEmble) that fails is reported and the study
    // goes on; elsewhere a failure ends the deck.
    const bool inStudy = (!sweep_.empty() && planTable_) || (sample_ && ensembleTable_);
    PlanRow row{runs_, ro.stem, sweep_, true, {}, {}, plan.planName};
    const std::clock_t cpuStart = std::clock();  // the process's CPU time: runs go one by one
    try {
      run.bind(true);
      try {
        run.run();
      } catch (const Interrupted&) {
        kept_ = run.keepOutputs("interrupted");
        throw;
      } catch (...) {
        kept_ = run.keepOutputs("failed");
        throw;
      }
    } catch (const std::runtime_error& e) {
      const bool expected = dynamic_cast<const AnalysisError*>(&e) || dynamic_cast<const DeckError*>(&e);
      if (!inStudy || !expected) throw;
      row.ok = false;
      row.reason = failureReason(e.what());
      ++failed_;
      log_ << "\n  *** run failed\n" << e.what() << "\n";
      if (console_ && !options_.quiet)
        *console_ << "  " << ro.stem << ": FAILED: " << row.reason << "\n" << std::flush;
    }
    row.debris = run.debris();
    const RunSummary s = run.summary();
    if (planTable_ && !sample_) planTable_->add(row);
    if (ensembleTable_ && sample_) {
      const double cpu = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
      ensembleTable_->add({runs_, plan.plan, plan.sample, ro.stem, sweep_, plan.drawn, row.ok,
                           row.reason, row.debris, plan.planName,
                           RunNumerics{s.steps, s.iterations, s.cuts, s.energyError}, cpu});
    }
    total_ += s;
    if (!row.ok) return;
    if (brief && row.debris) log_ << debrisLogLines(*row.debris);
    log_ << "\n  summary: " << runSummaryText(s) << "\n";
    const std::vector<std::string> warnings = runWarnings(s);
    for (const std::string& w : warnings) log_ << "  " << w << "\n";
    if (console_ && !options_.quiet && plans_.size() > 1)
      *console_ << "  " << ro.stem << ": " << runSummaryText(s) << "\n" << std::flush;
    // Warnings go where the deck's warnings go (standard error), not with the summaries.
    if (console_)
      for (const std::string& w : warnings) std::cerr << ro.stem << ": " << w << "\n" << std::flush;
    // An ensemble's plans are overlaid by their first sample.
    if (!brief)
      overlay_.add(runs_, sample_ ? planLabel(sweep_, plan.planName) : plan.label, p.title,
                   run.outputs().curves(run.history()));
  }

  const SolutionCommands& commands_;
  const DeckOptions& options_;
  std::ostream& log_;
  std::ostream* console_;
  bool execute_;
  std::vector<RunPlan> plans_;
  std::string stem_;
  Warnings* warnings_;
  std::vector<RunInfo> infos_;
  SweepValues sweep_;
  std::string planName_;  // the PLAN name of the sweep's value set walked
  const SampleDraws* sample_ = nullptr;  // the ensemble's sample being walked
  int samples_ = 0, plan_ = 0;           // its sample count; the ensemble plans walked
  EnsemblePairing pairing_;              // the same n and seed in every plan
  std::optional<EnsembleTable> ensembleTable_;
  const Record* ensembleHead_ = nullptr;
  const Record* detonators_ = nullptr;  // the DETOnators record of the ensemble walked
  std::string title_;
  int runs_ = 0;
  RunSummary total_;
  CurveOverlay overlay_;
  std::optional<PlanTable> planTable_;
  int failed_ = 0;
  StudySize size_;  // the passes of the LOOPs, SWEEps and ENSEmble being walked

 public:
  int failed() const { return failed_; }
  std::vector<std::filesystem::path> kept_;
};

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
  Walker check(commands, options, discard, nullptr, {});
  check.walk(deck.items, params);
  DeckPlan plan;
  plan.runs = check.runs();
  for (const RunInfo& r : check.infos()) plan.study = plan.study || !r.sweep.empty() || r.sample > 0;
  return plan;
}

DeckOutcome runDeck(const std::string& path, const DeckOptions& options,
                    const SolutionCommands& commands, std::ostream& out) {
  DeckOutcome outcome;
  const std::string stem = std::filesystem::path(path).stem().string();
  Warnings warnings;
  bool printed = false;
  auto printWarnings = [&] {
    if (printed) return;
    printed = true;
    for (const DeckWarning& w : warnings.list()) std::cerr << w.str() << "\n";
    outcome.warnings = warnings.list();
  };
  // The log is written through a temporary and becomes <log> when the whole deck
  // has run; a failed or interrupted deck keeps it as <stem>.failed.out or
  // <stem>.interrupted.out, with the reason as its last lines.
  std::unique_ptr<AtomicFile> log;
  std::vector<std::filesystem::path> kept;
  auto keepLog = [&](std::string_view tag, const std::string& why) {
    if (!log) return;
    try {
      log->stream() << "\n  *** run " << tag << "\n" << why << "\n";
      kept.insert(kept.begin(), log->keep(tag));
    } catch (...) {
      // The log cannot be written (the reason is the message already).
    }
  };
  auto keptText = [&] {
    return kept.empty() ? std::string() : "\n  computed results kept: " + fileList(kept);
  };
  // A failed run whose deck has values that look like another unit names them.
  auto unitText = [&] {
    const std::string at = warnings.unitLocations();
    if (at.empty()) return std::string();
    return "\n  advice: the deck's warnings name values that look like another unit (" + at +
           "): check them first";
  };
  try {
    const Deck deck = parseDeck(path);
    // Check pass: bind everything with a scratch parameter table, log discarded.
    std::ostringstream discard;
    Parameters checkParams;
    checkParams.setOverrides(options.params);
    Walker check(commands, options, discard, nullptr, {}, stem, &warnings);
    check.walk(deck.items, checkParams);
    checkOverridesUsed(checkParams, path);
    const std::vector<RunPlan> plans = planRuns(check.infos(), stem);
    const auto& infos = check.infos();
    const bool ensemble =
        std::any_of(infos.begin(), infos.end(), [](const RunInfo& r) { return r.sample > 0; });
    if (ensemble && std::any_of(infos.begin(), infos.end(), [](const RunInfo& r) { return r.sample == 0; })) {
      const Record& h = *check.ensembleHead();
      throw DeckError(h[0].loc, "a deck with an ENSEmble runs its study alone: another problem of this deck runs outside it",
                      h.excerpt(h[0].loc), "put the other problems in decks of their own");
    }
    printWarnings();
    throwIfInterrupted("the start");

    const std::filesystem::path dir =
        options.outDir.empty() ? std::filesystem::path(".") : options.outDir;
    std::filesystem::create_directories(dir);
    const std::string partStem = shardStem(stem, options);
    // The deck's outputs add at most ~60 characters to its stem (the runs'
    // stems are cut to 160 by fitFileStem): a longer stem would lose the
    // study's tables to "File name too long" after all the computing.
    if (partStem.size() > kMaxDeckStem)
      throw IoError("the deck's outputs would be named '" + partStem.substr(0, 40) + "...' (" +
                    std::to_string(partStem.size()) + " characters, at most " +
                    std::to_string(kMaxDeckStem) +
                    " before the suffixes of its files): give the deck a shorter name");
    removeStaleOutputs(dir, partStem);  // an earlier failed or interrupted run's log
    log = std::make_unique<AtomicFile>(dir /
                                       (options.logName.empty() ? partStem + ".out" : options.logName));
    log->stream() << "  collapse2d  " << path << "\n";
    for (const DeckWarning& w : warnings.list()) log->stream() << w.str() << "\n";
    for (const auto& [name, v] : options.params)
      log->stream() << "  given: " << name << " = " << exactNumber(v) << " (in place of the deck's value)\n";
    DeckOptions runOptions = options;
    runOptions.safePoint = [&log] { log->check(); };
    Parameters params;
    params.setOverrides(options.params);
    Walker runner(commands, runOptions, log->stream(), &out, plans, stem);
    const std::vector<std::string> swept = sweptNames(check.infos());
    const bool named =
        std::any_of(infos.begin(), infos.end(), [](const RunInfo& r) { return !r.planName.empty(); });
    if (ensemble)
      runner.setEnsembleTable(EnsembleTable(swept, drawnNames(check.infos()), studyZones(infos), named));
    else if (!swept.empty())
      runner.setPlanTable(PlanTable(swept, studyZones(infos), named));
    std::string studySummary;
    try {
      if (!plans.empty()) runner.walk(deck.items, params);
      if (options.shards > 1) log->stream() << "\n" << kEndOfRuns << "\n";
      // A shard of a study: its overlays are drawn by `collapse2d merge` from
      // the parts' curves (a part without a study's table draws its own).
      const bool studyPart = options.shards > 1 && (runner.planTable() || runner.ensembleTable());
      std::string curvesText, tableText;  // a part's, for its manifest's fingerprints
      if (studyPart && runner.overlay().numRuns() > 0)
        AtomicFile::write(dir / (partStem + "_curves.csv"), curvesText = runner.overlay().csv());
      else
        for (const auto& f : runner.overlay().write(dir, partStem))
          log->stream() << "\n  overlay of the runs: " << f.filename().string() << "\n";
      if (const auto& table = runner.planTable()) {
        const std::filesystem::path file = dir / (partStem + "_plans.csv");
        AtomicFile::write(file, tableText = table->csv());
        log->stream() << "\n  plans: " << file.filename().string() << " (" << table->rows().size()
                      << " runs, " << table->failed() << " failed)\n";
      }
      if (const auto& table = runner.ensembleTable()) {
        const std::string text = tableText = table->csv();
        const std::filesystem::path file = dir / (partStem + "_ensemble.csv");
        AtomicFile::write(file, text);
        AtomicFile::write(dir / (partStem + "_timing.csv"), timingCsv(*table));
        log->stream() << "\n  ensemble: " << file.filename().string() << " ("
                      << table->rows().size() << " runs, " << table->failed()
                      << " failed; CPU times in " << partStem << "_timing.csv)\n";
        // A shard's table is a part: `collapse2d merge` makes the study of the whole.
        if (options.shards <= 1) {
          const EnsembleStudyReport report =
              writeEnsembleStudy(dir, stem, readEnsembleTable(text, swept.size()), runner.title());
          log->stream() << "\n" << report.text;
          studySummary = report.summary;
        }
      }
      if (options.shards > 1 && (runner.planTable() || runner.ensembleTable()))
        writeShardManifest(dir, partStem,
                           {path, deckFingerprint(path) + givenText(options.params), options.shard,
                            options.shards, static_cast<int>(plans.size()), runner.ensembleTable() ? "ensemble" : "plans",
                            swept, runner.title(), runner.overlay().numRuns(),
                            contentFingerprint(tableText),
                            curvesText.empty() ? std::string() : contentFingerprint(curvesText)});
    } catch (...) {
      kept = runner.kept();
      throw;
    }
    outcome.total = runner.total();
    outcome.runs = runner.runs();
    outcome.failedRuns = runner.failed();
    int executed = outcome.runs;
    if (options.shards > 1) {
      executed = outcome.runs >= options.shard ? (outcome.runs - options.shard) / options.shards + 1 : 0;
      outcome.runs = executed;
    }
    if (outcome.failedRuns > 0) {
      log->stream() << "\n  run complete: " << outcome.failedRuns << " of " << executed
                    << " runs failed\n";
      outcome.exitCode = kExitAnalysisFailed;
      outcome.message = path + ": " + std::to_string(outcome.failedRuns) + " of " +
                        std::to_string(executed) + " runs of the study failed (see " + partStem +
                        (ensemble ? "_ensemble.csv" : "_plans.csv") + " and the log)" + unitText();
    } else {
      log->stream() << "\n  run complete\n";
    }
    log->commit();
    if (!options.quiet)
      out << path << ": " << (executed == 1 ? "" : std::to_string(executed) + " runs, ")
          << (outcome.failedRuns ? std::to_string(outcome.failedRuns) + " failed, " : "")
          << runSummaryText(outcome.total) << "\n"
          << studySummary;
  } catch (const DeckError& e) {
    printWarnings();
    outcome.exitCode = kExitDeckError;
    outcome.message = e.what();
    outcome.errorAt = e.loc();
    keepLog("failed", e.what());
    outcome.message += keptText();
  } catch (const UnusedParameter& e) {
    printWarnings();
    outcome.exitCode = kExitUsage;
    outcome.message = e.what();
  } catch (const AnalysisError& e) {
    outcome.exitCode = kExitAnalysisFailed;
    keepLog("failed", e.what() + unitText());
    outcome.message = e.what() + unitText() + keptText();
  } catch (const Interrupted& e) {
    outcome.exitCode = interruptExitCode(e.signal());
    outcome.interrupted = e.signal();
    const std::string msg = path + ": " + e.what();
    keepLog("interrupted", msg);
    outcome.message = msg + keptText();
  } catch (const IoError& e) {
    outcome.exitCode = kExitInternal;
    const std::string msg = path + ": I/O error: " + e.what();
    keepLog("failed", msg);
    outcome.message = msg + keptText();
  } catch (const std::filesystem::filesystem_error& e) {
    outcome.exitCode = kExitInternal;
    std::string msg = path + ": I/O error: " + e.code().message();
    if (!e.path1().empty()) msg += ": '" + e.path1().string() + "'";
    keepLog("failed", msg);
    outcome.message = msg + keptText();
  } catch (const std::exception& e) {
    outcome.exitCode = kExitInternal;
    const std::string msg = std::string(path) + ": internal error: " + e.what();
    keepLog("failed", msg);
    outcome.message = msg + keptText();
  }
  return outcome;
}

}  // namespace c2d
