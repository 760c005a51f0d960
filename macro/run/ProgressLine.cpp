#include "macro/run/ProgressLine.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>

#include "solvers/Analysis.h"

namespace c2d {

void ProgressLine::erase() {
  if (!on_) return;
  if (shown_) std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  shown_ = false;
}

void ProgressLine::show(Analysis& analysis, int hinges, int cuts) {
  if (!on_) return;
  const auto now = std::chrono::steady_clock::now();
  if (shown_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  const State& s = analysis.state();
  const auto& h = analysis.stepHistory();
  char line[256];
  std::snprintf(line, sizeof line, "%s: step %d  t = %.4g  load %.4g  Newton it %d  hinges %d%s",
                stem_.c_str(), s.step, s.t, analysis.loadFactor(),
                h.empty() ? 0 : h.back().iteration, hinges,
                cuts ? ("  cuts " + std::to_string(cuts)).c_str() : "");
  // A line longer than the terminal would wrap, and '\r' would not return to its start.
  std::size_t width = 80;
  winsize ws{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) width = ws.ws_col;
  std::string text = line;
  if (text.size() >= width) text.resize(width - 1);
  std::fprintf(stderr, "\r\033[K%s", text.c_str());
  std::fflush(stderr);
  shown_ = true;
}

}  // namespace c2d
