#include "macro/run/StaleOutputs.h"

#include <regex>
#include <system_error>
#include <vector>

namespace c2d {

int removeStaleOutputs(const std::filesystem::path& dir, const std::string& stem) {
  // What follows the stem in the names above (the stem itself is compared as text).
  static const std::regex kStale(
      R"((_tplot(_[0-9]+)?)?\.(failed|interrupted)\.(out|csv|pvd)|_[0-9]{4,}\.vtu|_deformed_[0-9]{4,}\.svg)");
  std::error_code ec;
  std::vector<std::filesystem::path> stale;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() > stem.size() && name.compare(0, stem.size(), stem) == 0 &&
        std::regex_match(name.begin() + static_cast<std::ptrdiff_t>(stem.size()), name.end(),
                         kStale) &&
        it->is_regular_file(ec))
      stale.push_back(it->path());
  }
  int removed = 0;
  for (const auto& p : stale) removed += std::filesystem::remove(p, ec) ? 1 : 0;
  return removed;
}

}  // namespace c2d
