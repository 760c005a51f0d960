#include "macro/ExecutePass.h"

#include <ctime>
#include <iostream>

#include "macro/run/Interrupt.h"
#include "macro/output/NumberText.h"

namespace c2d {

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

}  // namespace

void ExecutePass::problem(const Problem& p, Parameters& params) {
  counted(p);
  // A count that depends on what ran (PARA inside a BATCh loop) may give more
  // runs than the check pass planned: they are numbered on.
  if (static_cast<std::size_t>(runs_) > plans_.size())
    plans_.push_back({stem_ + "_" + std::to_string(runs_), "run " + std::to_string(runs_), 0, 0, {}, {}});
  // A shard runs every n-th run only (runs k with k mod n == i - 1, k from 0).
  if (options_.shards > 1 && (runs_ - 1) % options_.shards != options_.shard - 1) return;
  const RunPlan plan = plans_.at(static_cast<std::size_t>(runs_ - 1));
  // The samples after an ensemble plan's first keep their tables (time
  // history, debris) and a short log: a study of hundreds of runs would
  // otherwise write gigabytes of pictures, animations and Newton lines.
  const bool brief = sample_ && sample_->sample > 1;
  const RunOptions ro = begin(p, plan, brief);
  std::ostream discard(nullptr);
  ProblemRun run(p, params, commands_, ro, brief ? discard : log_);
  // A run of a study (SWEEp, ENSEmble) that fails is reported and the study
  // goes on; elsewhere a failure ends the deck.
  const bool inStudy = (!sweep_.empty() && planTable_) || (sample_ && ensembleTable_);
  PlanRow row{runs_, ro.stem, sweep_, true, {}, {}, plan.planName};
  const std::clock_t cpuStart = std::clock();  // the process's CPU time: runs go one by one
  execute(run, row, inStudy);
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
  report(s, ro.stem);
  // An ensemble's plans are overlaid by their first sample.
  if (!brief)
    overlay_.add(runs_, sample_ ? planLabel(sweep_, plan.planName) : plan.label, p.title,
                 run.outputs().curves(run.history()));
}

RunOptions ExecutePass::begin(const Problem& p, const RunPlan& plan, bool brief) {
  RunOptions ro = runOptions();
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
  ro.pictures = !brief;
  if (brief) log_ << "  (the log of a sample after the first: its summary and debris)\n";
  log_ << "\n";
  ro.safePoint = options_.safePoint;
  return ro;
}

void ExecutePass::execute(ProblemRun& run, PlanRow& row, bool inStudy) {
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
      *console_ << "  " << row.stem << ": FAILED: " << row.reason << "\n" << std::flush;
  }
}

void ExecutePass::report(const RunSummary& s, const std::string& stem) {
  log_ << "\n  summary: " << runSummaryText(s) << "\n";
  const std::vector<std::string> warnings = runWarnings(s);
  for (const std::string& w : warnings) log_ << "  " << w << "\n";
  if (console_ && !options_.quiet && plans_.size() > 1)
    *console_ << "  " << stem << ": " << runSummaryText(s) << "\n" << std::flush;
  // Warnings go where the deck's warnings go (standard error), not with the summaries.
  if (console_)
    for (const std::string& w : warnings) std::cerr << stem << ": " << w << "\n" << std::flush;
}

}  // namespace c2d
