#pragma once
// The three error channels: DeckError (bad input, with a source location),
// Status (numerical failure, returned so that step cutting can react), and
// assertions for broken invariants. AnalysisError ends a run that cannot go on;
// IoError one whose files cannot be written.
#include <stdexcept>
#include <string>

namespace c2d {

struct SourceLoc {
  std::string file;
  int line = 0;
  int col = 0;
  std::string str() const;  // "file:line:col"
};

class DeckError : public std::runtime_error {
 public:
  // message: what is wrong; text: the offending record (shown under the message);
  // hint: e.g. "did you mean 'COORdinates'?"
  DeckError(SourceLoc loc, const std::string& message, std::string text = {}, std::string hint = {});
  const SourceLoc& loc() const { return loc_; }
  const std::string& message() const { return message_; }
  const std::string& text() const { return text_; }
  const std::string& hint() const { return hint_; }

 private:
  SourceLoc loc_;
  std::string message_, text_, hint_;
};

// A failed analysis (non-convergence without step cutting, singular tangent, NaN):
// the message says which step and which command.
class AnalysisError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An output or input file that could not be written or read (missing or
// read-only directory, full disk, failed rename): the message names the path and
// gives the system's reason.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Outcome of a numerical operation that may fail without being a bug.
struct Status {
  bool ok = true;
  std::string why;
  static Status success() { return {}; }
  static Status failure(std::string w) { return {false, std::move(w)}; }
  explicit operator bool() const { return ok; }
};

}  // namespace c2d
