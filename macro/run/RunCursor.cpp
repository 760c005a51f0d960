#include "macro/run/RunCursor.h"

#include <array>
#include <string_view>

namespace c2d {

namespace {

// Commands that only read the run: what they write never changes its steps.
bool output(const Macro& m) {
  static constexpr std::array<std::string_view, 10> keys = {"plot", "pvie", "tplo", "disp", "velo",
                                                            "acce", "reac", "stre", "para", "rest"};
  for (std::string_view k : keys)
    if (m.key == k) return true;
  return m.is("form") && !m.option.empty();  // FORM,LONG / FORM,SHORt: the tables' digits
}

}  // namespace

void RunCursor::reset(const std::vector<std::vector<Macro>>& batches) {
  batches_ = &batches;
  frames_.clear();
}

RunCursor::Scope::Scope(RunCursor& cursor, const std::vector<Macro>& list, bool loopBody, int pass,
                        int passes)
    : cursor_(cursor) {
  cursor_.frames_.push_back({&list, 0, loopBody, pass, passes});
}

RunCursor::Scope::~Scope() { cursor_.frames_.pop_back(); }

std::optional<RunCursor::Next> RunCursor::scan(const std::vector<Macro>& list, std::size_t from,
                                               const Parameters& params) const {
  for (std::size_t i = from; i < list.size(); ++i) {
    const Macro& m = list[i];
    if (m.is("loop")) {
      const int n = m.has(0) ? m.numbers[0].evalInt(params, "loop count") : 1;
      if (n <= 0) continue;
      // A body of outputs only: so are its other passes.
      if (const std::optional<Next> next = scan(m.body, 0, params)) return next;
      continue;
    }
    if (m.is("time") || m.is("save")) return Next::Step;
    if (m.is("stop")) return Next::End;
    if (!output(m)) return Next::Change;
  }
  return std::nullopt;
}

RunCursor::Next RunCursor::afterLoop(const Parameters& params) const {
  if (frames_.empty()) return Next::End;
  // The frame whose running command is the loop (or, outside any loop, the command).
  std::size_t d = frames_.size() - 1;
  if (frames_[d].loopBody && d > 0) --d;
  for (;; --d) {
    const Frame& f = frames_[d];
    if (const std::optional<Next> next = scan(*f.list, f.index + 1, params)) return *next;
    // The list ends: the loop's next pass, else what follows the loop.
    if (f.loopBody && f.pass + 1 < f.passes)
      if (const std::optional<Next> next = scan(*f.list, 0, params)) return *next;
    if (d == 0) break;
  }
  // The BATCh block ends: the blocks after it.
  if (batches_) {
    bool after = false;
    for (const std::vector<Macro>& b : *batches_) {
      if (after)
        if (const std::optional<Next> next = scan(b, 0, params)) return *next;
      after = after || &b == frames_.front().list;
    }
  }
  return Next::End;
}

}  // namespace c2d
