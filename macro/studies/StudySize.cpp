#include "macro/studies/StudySize.h"

#include "core/Error.h"

namespace c2d {

StudySize::Scope::Scope(StudySize& size, const Record& head, long long passes, std::string what)
    : size_(size) {
  size_.levels_.push_back({&head, passes, std::move(what)});
}

StudySize::Scope::~Scope() { size_.levels_.pop_back(); }

void StudySize::checkProblem(const Record& head, long long runsBefore, long long maxRuns) const {
  long long runs = 1;
  bool capped = false;
  std::string product, items;
  for (const Level& l : levels_) {
    // Each factor is at most maxRuns: stop multiplying once beyond it.
    if (runs <= maxRuns)
      runs *= l.passes;
    else
      capped = true;
    if (l.passes == 1) continue;
    product += (product.empty() ? "" : " x ") + std::to_string(l.passes);
    items += (items.empty() ? "" : "; ") + l.what;
  }
  if (runsBefore + runs <= maxRuns) return;
  const Record& at = levels_.empty() ? head : *levels_.front().head;
  std::string msg = "the study has ";
  if (runs > maxRuns)
    msg += product + (capped ? "" : " = " + std::to_string(runs)) + " runs (" + items + ")";
  else
    msg += std::to_string(runsBefore) + " runs before this problem and " + std::to_string(runs) +
           " of it" + (items.empty() ? "" : " (" + items + ")");
  msg += ", more than the " + std::to_string(maxRuns) + " runs a deck may have";
  throw StudySizeError(at[0].loc, msg, at.excerpt(at[0].loc),
                  "split the study over decks, or fewer values or samples");
}

}  // namespace c2d
