#include "macro/deck/Warnings.h"

namespace c2d {

std::string DeckWarning::str() const {
  std::string s = loc.str() + ": warning: " + message;
  if (!text.empty()) s += "\n    " + text;
  return s;
}

void Warnings::add(const SourceLoc& loc, const std::string& message, const std::string& text,
                   bool unit) {
  if (!seen_.insert(loc.str() + "\n" + message).second) return;
  list_.push_back({loc, message, text, unit});
}

std::string Warnings::unitLocations() const {
  std::string out;
  for (const DeckWarning& w : list_)
    if (w.unit) out += (out.empty() ? "" : ", ") + w.loc.str();
  return out;
}

}  // namespace c2d
