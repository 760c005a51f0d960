#pragma once
// The progress line of a run on a terminal (--progress): one line on standard
// error, rewritten in place at most every 0.1 s and erased when the run ends,
// so that the run's summary takes its place.
#include <chrono>
#include <string>

namespace c2d {

class Analysis;

class ProgressLine {
 public:
  // `on`: shown at all; `stem`: the run's name at the line's start.
  ProgressLine(bool on, std::string stem) : on_(on), stem_(std::move(stem)) {}
  // The run starts: the first commit shows the line.
  void start() { last_ = std::chrono::steady_clock::now(); }
  // At a commit: the step, time, load factor, Newton iterations, hinges and cuts.
  void show(Analysis& analysis, int hinges, int cuts);
  // The run ended (or failed: nothing left for the message to run into).
  void erase();

 private:
  bool on_;
  std::string stem_;
  std::chrono::steady_clock::time_point last_;
  bool shown_ = false;
};

}  // namespace c2d
