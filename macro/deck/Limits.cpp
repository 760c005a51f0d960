#include "macro/deck/Limits.h"

#include <unistd.h>

#include <algorithm>

#include "core/Error.h"

namespace c2d {

int DeckLimits::maxNodes() {
  constexpr long long kCap = 10'000'000;
  constexpr long long kBytesPerEntity = 4096;
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return static_cast<int>(kCap);
  const long long memory = static_cast<long long>(pages) * pageSize;
  return static_cast<int>(std::clamp(memory / kBytesPerEntity, 1000LL, kCap));
}

void checkNumber(const Record& r, std::size_t i, long long value, long long limit,
                 const std::string& what, const std::string& why) {
  if (value >= 1 && value <= limit) return;
  const std::string msg = value < 1
                              ? what + " must be positive, got " + std::to_string(value)
                              : what + " " + std::to_string(value) +
                                    " is beyond the largest this program takes (" +
                                    std::to_string(limit) + (why.empty() ? "" : ", " + why) + ")";
  throw DeckError(r.fieldLoc(i), msg, r.excerpt(r.fieldLoc(i)));
}

}  // namespace c2d
