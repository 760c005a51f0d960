#include "macro/CheckPass.h"

#include "macro/deck/Limits.h"
#include "macro/run/Interrupt.h"

namespace c2d {

void CheckPass::problem(const Problem& p, Parameters& params) {
  // The planning: its size checked, a signal stops it.
  size_.checkProblem(p.head, runs_, DeckLimits::kMaxRuns);
  throwIfInterrupted("the planning of run " + std::to_string(runs_ + 1));
  counted(p);
  RunOptions ro = runOptions();
  RunInfo info{sweep_, planName_, {}, sample_ ? plan_ : 0, sample_ ? sample_->sample : 0, samples_, {}, {}};
  for (const std::string& n : params.names()) info.params[n] = params.get(n);
  ro.warnings = warnings_;
  ProblemRun run(p, params, commands_, ro, log_);
  run.bind(false);
  if (sample_) noteDraws(info, run);
  info.zones = zoneNames(run.model().site());
  infos_.push_back(std::move(info));
  // PARA commands in the BATCh blocks change the table for what follows (a
  // later top-level LOOP count), as they will when the problem runs.
  params = run.boundParams();
}

void CheckPass::noteDraws(RunInfo& info, const ProblemRun& run) const {
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

}  // namespace c2d
