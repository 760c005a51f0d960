#include "macro/DeckWalker.h"

#include "macro/deck/Limits.h"
#include "macro/deck/ParameterNote.h"

namespace c2d {

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

}  // namespace

std::string planLabel(const SweepValues& sweep, const std::string& name) {
  return name.empty() ? sweepLabel(sweep) : name;
}

RunOptions DeckWalker::runOptions() const {
  RunOptions ro;
  ro.outDir = options_.outDir.empty() ? std::filesystem::path(".") : options_.outDir;
  ro.progress = options_.progress && !options_.quiet;
  ro.solver = options_.solver;
  ro.sample = sample_;
  return ro;
}

void DeckWalker::counted(const Problem& p) {
  ++runs_;
  title_ = RunOutputs::displayTitle(p.title);
}

void DeckWalker::walk(const std::vector<TopItem>& items, Parameters& params) {
  for (const TopItem& item : items) {
    if (const auto* pb = std::get_if<ParamBlock>(&item)) {
      pb->apply(params);
    } else if (const auto* loop = std::get_if<TopLoop>(&item)) {
      walkLoop(*loop, params);
    } else if (const auto* sweep = std::get_if<TopSweep>(&item)) {
      walkSweep(*sweep, params);
    } else if (const auto* e = std::get_if<TopEnsemble>(&item)) {
      walkEnsemble(*e, params);
    } else {
      const Problem& p = std::get<Problem>(item);
      try {
        problem(p, params);
      } catch (const DeckError& e) {
        throw noteParameters(e, params);
      }
    }
  }
}

void DeckWalker::walkLoop(const TopLoop& loop, Parameters& params) {
  const int n = loop.count.evalInt(params, "loop count");
  if (n < 0 || n > DeckLimits::kMaxRuns) {
    const Record& h = loop.head;
    const SourceLoc at = loop.count.loc();
    throw DeckError(
        at,
        "top-level LOOP count " + std::to_string(n) +
            (n < 0 ? " is negative"
                   : " is beyond the largest this program takes (" +
                         std::to_string(DeckLimits::kMaxRuns) + " runs of its problems)"),
        h.excerpt(at));
  }
  const StudySize::Scope scope(size_, loop.head, n,
                               "the LOOP of line " + std::to_string(loop.head.loc.line) + ": " +
                                   std::to_string(n) + " passes");
  for (int i = 0; i < n; ++i) walk(loop.body, params);
}

void DeckWalker::walkSweep(const TopSweep& sweep, Parameters& params) {
  // The swept names may not be set again by the deck (Parameters::protect).
  for (const SweepVariable& v : sweep.variables) refuseOverride(params, v.name, v.record, "swept");
  const std::vector<SweepValues> sets = sweepRuns(sweep, params);
  const std::vector<std::string> names = sweepPlanNames(sweep);
  const std::string by = "swept by the SWEEp of line " + std::to_string(sweep.head.loc.line);
  const StudySize::Scope scope(size_, sweep.head, static_cast<long long>(sets.size()),
                               "the SWEEp of line " + std::to_string(sweep.head.loc.line) + ": " +
                                   std::to_string(sets.size()) + " value sets");
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const SweepValues& set = sets[k];
    sweep_ = set;
    planName_ = k < names.size() ? names[k] : std::string();
    for (const auto& [name, x] : sweep_) {
      params.set(name, x);
      params.protect(name, by);
    }
    walk(sweep.body, params);
  }
  for (const SweepVariable& v : sweep.variables) params.unprotect(v.name);
  sweep_.clear();
  planName_.clear();
}

void DeckWalker::walkEnsemble(const TopEnsemble& e, Parameters& params) {
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

}  // namespace c2d
