#pragma once
// The size of a study before it is planned: a problem inside LOOPs, SWEEps and
// an ENSEmble runs as many times as the product of their passes. Each count
// passes its own limit, so the product is checked too, when the walk first
// reaches the problem, before any run is bound: a deck of 10000 samples times
// a 10000-value sweep is a deck error naming the items and the limit, not
// hours of planning.
#include <string>
#include <vector>

#include "core/Error.h"
#include "macro/deck/Record.h"

namespace c2d {

// A study too large: a deck error of the study as a whole (not of a sample).
class StudySizeError : public DeckError {
 public:
  using DeckError::DeckError;
};

class StudySize {
 public:
  // While a Scope lives, the problems walked run `passes` times more (what:
  // "the SWEEp of line 3: 40 value sets").
  class Scope {
   public:
    Scope(StudySize& size, const Record& head, long long passes, std::string what);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    StudySize& size_;
  };

  // The problem at `head` is reached with runsBefore runs before it: throws
  // DeckError (at the outermost item's head) when its runs would take the
  // deck beyond maxRuns.
  void checkProblem(const Record& head, long long runsBefore, long long maxRuns) const;

 private:
  struct Level {
    const Record* head;
    long long passes;
    std::string what;
  };
  std::vector<Level> levels_;
};

}  // namespace c2d
