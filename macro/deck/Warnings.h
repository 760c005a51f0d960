#pragma once
// Deck warnings: input that is accepted but surely not meant (a node no
// element uses, gravity on materials without density). Collected while a deck
// is bound, before anything is computed, each once however often its problem is
// bound (top-level loops, sweeps); printed as "file:line:col: warning: ..." on
// stderr and at the head of the log.
#include <set>
#include <string>
#include <vector>

#include "core/Error.h"

namespace c2d {

struct DeckWarning {
  SourceLoc loc;
  std::string message;
  std::string text;   // the offending record, as for a DeckError
  bool unit = false;  // a value that looks like another unit (a failed run names it)
  std::string str() const;
};

class Warnings {
 public:
  void add(const SourceLoc& loc, const std::string& message, const std::string& text = {},
           bool unit = false);
  // The locations of the unit warnings, "file:line:col, ..." (empty: none).
  std::string unitLocations() const;
  const std::vector<DeckWarning>& list() const { return list_; }
  bool empty() const { return list_.empty(); }

 private:
  std::vector<DeckWarning> list_;
  std::set<std::string> seen_;  // location + message
};

}  // namespace c2d
