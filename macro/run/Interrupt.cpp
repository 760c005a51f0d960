#include "macro/run/Interrupt.h"

#include <csignal>
#include <cstring>
#include <memory>

namespace c2d {

namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void onInterrupt(int signal) { received = signal; }

}  // namespace

void installInterruptHandlers() {
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = onInterrupt;
  sigemptyset(&sa.sa_mask);
  // No SA_RESTART: a blocking wait returns (EINTR) so that a batch forwards the
  // signal at once. SA_RESETHAND: the second signal takes the default action.
  sa.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

struct ScopedInterruptHandlers::Saved {
  struct sigaction interrupt, terminate;
};

ScopedInterruptHandlers::ScopedInterruptHandlers() : saved_(std::make_unique<Saved>()) {
  sigaction(SIGINT, nullptr, &saved_->interrupt);
  sigaction(SIGTERM, nullptr, &saved_->terminate);
  received = 0;
  installInterruptHandlers();
}

ScopedInterruptHandlers::~ScopedInterruptHandlers() {
  sigaction(SIGINT, &saved_->interrupt, nullptr);
  sigaction(SIGTERM, &saved_->terminate, nullptr);
}

int pendingInterrupt() { return received; }

void clearInterrupt() { received = 0; }

std::string signalName(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGKILL:
      return "SIGKILL";
    case SIGSEGV:
      return "SIGSEGV";
    case SIGABRT:
      return "SIGABRT";
    default:
      return "signal " + std::to_string(signal);
  }
}

Interrupted::Interrupted(int signal, const std::string& where)
    : std::runtime_error("interrupted by " + signalName(signal) +
                         (where.empty() ? "" : " at " + where)),
      signal_(signal) {}

}  // namespace c2d
