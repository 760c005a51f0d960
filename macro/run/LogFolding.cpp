#include "macro/run/LogFolding.h"

namespace c2d {

bool LogFolding::admit(const std::string& reason, const std::string& item) {
  Reason& r = reasons_[reason];
  r.items.insert(item);
  return ++r.lines <= shown_;
}

std::string LogFolding::summary() const {
  std::string out;
  for (const auto& [reason, r] : reasons_) {
    if (r.lines <= shown_) continue;
    out += "  " + reason + ": " + std::to_string(r.lines) + " lines (" +
           std::to_string(r.items.size()) + (r.items.size() == 1 ? " case" : " cases") +
           "), the first " + std::to_string(shown_) + " written above, the other " +
           std::to_string(r.lines - shown_) + " left out\n";
  }
  return out;
}

}  // namespace c2d
