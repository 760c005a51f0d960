#pragma once
// SIGINT and SIGTERM: a run stops at its next safe point (between two solution
// commands, so between two Newton iterations at most), keeps what it computed
// under names that say it was interrupted, and exits with 128 + the signal
// (130 for SIGINT, 143 for SIGTERM). A second signal ends the program at once
// (the default action), for a run that does not reach a safe point.
//
// The flag the handler sets is the one piece of global state of the program: a
// signal handler can reach nothing else.
#include <memory>
#include <stdexcept>
#include <string>

namespace c2d {

// Installs the handlers of SIGINT and SIGTERM (main, and each child of a batch).
void installInterruptHandlers();
// The same handlers for the time of one scope, the ones before restored when it
// ends (a host program with handlers of its own: the Python module), with any
// signal received before it forgotten. Not for two scopes at once.
class ScopedInterruptHandlers {
 public:
  ScopedInterruptHandlers();
  ~ScopedInterruptHandlers();
  ScopedInterruptHandlers(const ScopedInterruptHandlers&) = delete;
  ScopedInterruptHandlers& operator=(const ScopedInterruptHandlers&) = delete;

 private:
  struct Saved;
  std::unique_ptr<Saved> saved_;  // the sigaction records stay out of this header
};
// The signal received and not yet acted on, 0 when none.
int pendingInterrupt();
// Forget a received signal (tests).
void clearInterrupt();
// "SIGINT", "SIGTERM", or "signal N".
std::string signalName(int signal);
// The exit status of a run stopped by `signal`: 128 + signal.
inline int interruptExitCode(int signal) { return 128 + signal; }

// Thrown at a safe point after a signal; ends the run like a failure, with the
// outputs kept as "interrupted".
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& where);
  int signal() const { return signal_; }

 private:
  int signal_;
};

// A safe point: throws Interrupted when a signal has come; `where` says where
// the run stands ("step 42, t = 1.25").
inline void throwIfInterrupted(const std::string& where) {
  if (const int s = pendingInterrupt(); s != 0) throw Interrupted(s, where);
}
}  // namespace c2d
