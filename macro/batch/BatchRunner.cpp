#include "macro/batch/BatchRunner.h"

#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include <csignal>
#include <cstring>
#include <ctime>
#include <optional>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "macro/run/Interrupt.h"

namespace c2d {

namespace {

// The whole content of a file the child wrote.
std::string slurp(std::FILE* f) {
  std::string s;
  std::rewind(f);
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) s.append(buf, n);
  return s;
}

using Clock = std::chrono::steady_clock;

struct Child {
  std::size_t index = 0;
  pid_t pid = -1;
  std::FILE* output = nullptr;  // the child's stdout
  std::FILE* errors = nullptr;  // the child's stderr (its errors and warnings)
  std::FILE* result = nullptr;  // "exit runs steps iterations"
  Clock::time_point start;
  std::optional<Clock::time_point> termSent;  // the timeout's SIGTERM
  int forwarded = 0;                          // the batch's signal passed on
};

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

[[noreturn]] void runChild(const BatchJob& job, const DeckCalls& calls, const Child& c) {
  // A group of its own: a terminal's Ctrl-C reaches the batch alone, which passes
  // it on once. The child ends with the batch, even one killed outright.
  ::setpgid(0, 0);
#ifdef __linux__
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() == 1) ::_exit(kExitInternal);  // the batch is already gone
#endif
  installInterruptHandlers();
  ::dup2(fileno(c.output), STDOUT_FILENO);
  ::dup2(fileno(c.errors), STDERR_FILENO);
  DeckOptions o = job.options;
  o.progress = false;
  o.logName.clear();
  const DeckOutcome r = calls.run(job.deck, o, std::cout);
  if (r.exitCode != 0) std::cerr << r.message << "\n";
  std::cout.flush();
  std::cerr.flush();
  std::fprintf(c.result, "%d %d %d %d %d %d\n", r.exitCode, r.runs, r.total.steps,
               r.total.iterations, r.total.debrisRuns, r.total.outsideRuns);
  std::fflush(c.result);
  std::fflush(nullptr);
  ::_exit(r.exitCode);
}

void statusLine(bool show, std::size_t done, std::size_t total, std::size_t failed,
                const std::map<pid_t, Child>& running, const std::vector<std::string>& decks) {
  if (!show) return;
  std::ostringstream os;
  os << "[" << done << "/" << total << " done";
  if (failed) os << ", " << failed << " failed";
  os << "] running:";
  for (const auto& [pid, c] : running) os << ' ' << std::filesystem::path(decks[c.index]).filename().string();
  std::string line = os.str();
  if (line.size() > 79) {
    line.resize(76);
    line.append("...");
  }
  std::fprintf(stderr, "\r\033[K%s", line.c_str());
  std::fflush(stderr);
}

void clearLine(bool show) {
  if (!show) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
}

}  // namespace

std::string BatchResult::status() const {
  if (!started) return "not run";
  if (timedOut) return "timed out";
  if (interruptedBy) return "interrupted (" + signalName(interruptedBy) + ")";
  if (signal) return "crashed (signal " + std::to_string(signal) + ")";
  switch (exitCode) {
    case kExitOk: return "ok";
    case kExitDeckError: return "deck error";
    case kExitAnalysisFailed: return "analysis failed";
    case kExitInternal: return "internal error";
    default: return "exit " + std::to_string(exitCode);
  }
}

std::string batchStemClash(const std::vector<std::string>& decks) {
  std::map<std::string, std::string> seen;
  for (const std::string& d : decks) {
    const std::string stem = std::filesystem::path(d).stem().string();
    const auto [it, fresh] = seen.emplace(stem, d);
    if (!fresh)
      return "decks " + it->second + " and " + d + " would write the same outputs (" + stem +
             ".*): run them with different -o directories";
  }
  return {};
}

std::vector<BatchResult> runBatch(const std::vector<std::string>& decks, const BatchOptions& options,
                                  const DeckCalls& calls, std::ostream& out) {
  std::vector<BatchJob> jobs;
  for (const std::string& d : decks) jobs.push_back({d, options.deck});
  return runBatch(jobs, options, calls, out);
}

namespace {

// A signal to the batch: passed on to every running deck once.
void forwardInterrupt(int sig, std::map<pid_t, Child>& running) {
  for (auto& [pid, c] : running)
    if (!c.forwarded) {
      ::kill(pid, sig);
      c.forwarded = sig;
    }
}

// A forked child running job, its output, errors and figures in temporary files.
Child startChild(const BatchJob& job, std::size_t index, const DeckCalls& calls,
                 std::ostream& out) {
  Child c;
  c.index = index;
  c.output = std::tmpfile();
  c.errors = std::tmpfile();
  c.result = std::tmpfile();
  if (!c.output || !c.errors || !c.result) throw std::runtime_error("cannot create a temporary file for a batch run");
  // Nothing buffered may be written twice, once by each process.
  out.flush();
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  c.start = std::chrono::steady_clock::now();
  c.pid = ::fork();
  if (c.pid < 0) throw std::runtime_error("fork failed for " + job.deck);
  if (c.pid == 0) runChild(job, calls, c);
  return c;
}

// Nothing ended: the timeouts (SIGTERM, SIGKILL after the grace), then a short
// sleep (a signal cuts it short).
void watchTimeouts(std::map<pid_t, Child>& running, const BatchOptions& options) {
  for (auto& [p, c] : running) {
    if (options.timeout > 0 && !c.termSent && secondsSince(c.start) > options.timeout) {
      ::kill(p, SIGTERM);
      c.termSent = Clock::now();
    } else if (c.termSent && secondsSince(*c.termSent) > kGraceSeconds) {
      ::kill(p, SIGKILL);
    }
  }
  const timespec pause{0, 20'000'000};
  ::nanosleep(&pause, nullptr);
}

// An ended child's result: its time, output, errors, figures and exit.
void collectChild(const Child& c, int status, BatchResult& r) {
  r.seconds = secondsSince(c.start);
  r.timedOut = c.termSent.has_value();
  r.interruptedBy = r.timedOut ? 0 : c.forwarded;
  r.output = slurp(c.output);
  r.errors = slurp(c.errors);
  std::istringstream figures(slurp(c.result));
  std::fclose(c.output);
  std::fclose(c.errors);
  std::fclose(c.result);
  if (WIFSIGNALED(status)) {
    r.signal = WTERMSIG(status);
    r.exitCode = kExitInternal;
  } else {
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : kExitInternal;
    int code = 0;
    // A child that exited without its figures (an abort in a library) crashed too.
    if (!(figures >> code >> r.runs >> r.steps >> r.iterations >> r.debrisRuns >> r.outsideRuns) &&
        r.exitCode == 0)
      r.exitCode = kExitInternal;
  }
  if (r.timedOut) r.exitCode = kExitTimedOut;
}

// A deck's output and errors where a run puts them, and a timeout's or crash's line.
void reportChild(const BatchResult& r, const BatchOptions& options, std::ostream& out) {
  out << r.output;
  out.flush();
  std::cerr << r.errors << std::flush;
  if (r.timedOut)
    out << r.deck << ": timed out after " << options.timeout << " s"
        << (r.signal ? " (killed: it did not stop at " + signalName(SIGTERM) + ")" : std::string()) << "\n";
  else if (r.signal)
    out << r.deck << ": crashed (" << signalName(r.signal) << ")\n";
  out.flush();
}

}  // namespace

std::vector<BatchResult> runBatch(const std::vector<BatchJob>& batchJobs, const BatchOptions& options,
                                  const DeckCalls& calls, std::ostream& out) {
  std::vector<std::string> decks;
  for (const BatchJob& j : batchJobs) decks.push_back(j.deck);
  std::vector<BatchResult> results(decks.size());
  const std::size_t jobs = options.jobs < 1 ? 1 : static_cast<std::size_t>(options.jobs);
  std::map<pid_t, Child> running;
  std::size_t next = 0, done = 0, failed = 0;
  for (std::size_t i = 0; i < decks.size(); ++i) results[i].deck = decks[i];
  while (next < decks.size() || !running.empty()) {
    // A signal to the batch: no new deck starts.
    const int sig = pendingInterrupt();
    if (sig != 0) forwardInterrupt(sig, running);
    while (sig == 0 && next < decks.size() && running.size() < jobs) {
      results[next].started = true;
      const Child c = startChild(batchJobs[next], next, calls, out);
      running.emplace(c.pid, c);
      ++next;
    }
    if (running.empty()) break;  // interrupted before the remaining decks
    statusLine(options.progress, done, decks.size(), failed, running, decks);
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("waitpid failed in a batch run: ") + std::strerror(errno));
    }
    if (pid == 0) {
      watchTimeouts(running, options);
      continue;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;  // not one of ours
    const Child c = it->second;
    running.erase(it);
    BatchResult& r = results[c.index];
    collectChild(c, status, r);
    ++done;
    if (!r.ok()) ++failed;
    clearLine(options.progress);
    reportChild(r, options, out);
  }
  clearLine(options.progress);
  return results;
}

void printBatchTable(std::ostream& os, const std::vector<BatchResult>& results) {
  std::size_t w = 4;
  for (const BatchResult& r : results) w = std::max(w, r.deck.size());
  char buf[512];
  std::snprintf(buf, sizeof buf, "%-*s  %-22s %5s %7s %11s %10s  %s\n", static_cast<int>(w), "deck",
                "status", "runs", "steps", "iterations", "wall (s)", "debris");
  os << "\n" << buf;
  int failed = 0;
  for (const BatchResult& r : results) {
    if (!r.ok()) ++failed;
    // Debris against the site: "inside", "OUTSIDE" (k of n runs), "-" without ground contact.
    const std::string debris = r.debrisRuns == 0 ? "-"
                               : r.outsideRuns == 0
                                   ? "inside"
                                   : "OUTSIDE" + (r.debrisRuns > 1 ? " (" + std::to_string(r.outsideRuns) +
                                                                         " of " + std::to_string(r.debrisRuns) + ")"
                                                                   : std::string());
    if (r.ok())
      std::snprintf(buf, sizeof buf, "%-*s  %-22s %5d %7d %11d %10.2f  %s\n", static_cast<int>(w),
                    r.deck.c_str(), r.status().c_str(), r.runs, r.steps, r.iterations, r.seconds,
                    debris.c_str());
    else if (r.started)
      std::snprintf(buf, sizeof buf, "%-*s  %-22s %5s %7s %11s %10.2f  %s\n", static_cast<int>(w),
                    r.deck.c_str(), r.status().c_str(), "-", "-", "-", r.seconds, debris.c_str());
    else
      std::snprintf(buf, sizeof buf, "%-*s  %-22s %5s %7s %11s %10s  %s\n", static_cast<int>(w),
                    r.deck.c_str(), r.status().c_str(), "-", "-", "-", "-", "-");
    os << buf;
  }
  int timedOut = 0, interrupted = 0, notRun = 0;
  for (const BatchResult& r : results) {
    timedOut += r.timedOut;
    interrupted += r.interruptedBy != 0;
    notRun += !r.started;
  }
  os << results.size() << " deck" << (results.size() == 1 ? "" : "s") << ": "
     << results.size() - static_cast<std::size_t>(failed) << " ok, " << failed << " failed";
  if (timedOut) os << " (" << timedOut << " timed out)";
  if (interrupted || notRun) os << "; interrupted: " << interrupted << " stopped, " << notRun << " not run";
  os << "\n";
}

int batchExitCode(const std::vector<BatchResult>& results) {
  for (const BatchResult& r : results)
    if (r.started && !r.ok()) return r.exitCode != 0 ? r.exitCode : kExitInternal;
  for (const BatchResult& r : results)
    if (!r.started) return kExitInternal;  // the caller reports the signal that stopped the batch
  return 0;
}

}  // namespace c2d
