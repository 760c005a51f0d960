#pragma once
// Result files that never look complete unless they are.
//
// AtomicFile: the text goes to a temporary file "<path>.<6 random
// characters>.part" beside <path>, created exclusively (O_CREAT|O_EXCL, never
// following a link: a link or file planted under any name is never written
// through, and two programs writing one path each have their own temporary);
// commit() closes it and renames it over <path> (rename is atomic on POSIX file
// systems and replaces a link rather than following it). Destroyed without
// commit(), it removes the temporary. So <path> either holds a previous run's
// file or the complete new one, never a truncated one; a run killed outright
// (no destructors) leaves at most a "<path>.*.part", whose name says it is partial.
// A run that fails or is interrupted keeps what it wrote under a name that says
// so: keep("failed") renames the .part to "<stem>.failed<ext>" (tagged()).
// There is no fsync: the guarantee covers an interrupted or failed run, not a
// crash of the operating system, which keeps an output step cheap.
//
// AtomicAppendFile: a document that grows during a run (the .pvd collection):
// header, records appended one at a time, footer. Every sync() rewrites
// "<path>.part" (as an AtomicFile: written aside, renamed onto it) with header + all records so far + footer, so that the .part is
// at every moment a well-formed document holding a prefix of the records (one
// can watch a run with it). Only close() writes <path>; keep(tag) writes the
// tagged name instead (a failed or interrupted run), and a destructor without
// either brings the .part up to date and leaves it. A sync costs a rewrite of the whole
// file; minSyncInterval bounds that cost for long histories (sync() then skips
// rewrites closer together than the interval; close() and keep() always write).
//
// Every write is checked (the stream after writing, flush, close, rename): a
// failure throws IoError naming the file and the system's reason, and leaves no
// file under the final name.
//
// SimulatedWriteFailure: while one lives, every AtomicFile whose final name is
// the given file name fails its writes with the given errno (a full disk for
// the tests, which can no longer plant a link to /dev/full).
#include <chrono>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

#include "core/Error.h"
#include "core/io/FdOutBuf.h"

namespace c2d {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path);  // creates the temporary (and the directory)
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  void commit();  // close, check every write succeeded, rename over path(); once only
  // Commit under tagged(path(), tag) instead (the partial result of a failed or
  // interrupted run); returns that path.
  std::filesystem::path keep(std::string_view tag);
  // Throws IoError when a write to the stream has failed so far (cheap; a file
  // that stays open for a whole run calls it at safe points). Flushes the stream
  // at most every flushInterval, so that the temporary can be watched.
  void check(std::chrono::milliseconds flushInterval = std::chrono::milliseconds(1000));
  bool committed() const { return committed_; }
  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& partPath() const { return part_; }

  // The whole content in one call: write + commit.
  static void write(const std::filesystem::path& path, std::string_view content);
  // "<dir>/<stem>.<tag><ext>": name_tplot.csv -> name_tplot.failed.csv.
  static std::filesystem::path tagged(const std::filesystem::path& path, std::string_view tag);

 private:
  void commitTo(const std::filesystem::path& target);

  std::filesystem::path path_, part_;
  std::unique_ptr<FdOutBuf> buf_;
  std::ostream out_;
  bool committed_ = false;
  std::chrono::steady_clock::time_point lastFlush_;
};

class SimulatedWriteFailure {
 public:
  SimulatedWriteFailure(std::string fileName, int err);
  ~SimulatedWriteFailure();
  SimulatedWriteFailure(const SimulatedWriteFailure&) = delete;
  SimulatedWriteFailure& operator=(const SimulatedWriteFailure&) = delete;

  static int errorFor(const std::filesystem::path& path);  // 0: none

 private:
  std::string name_;
};

class AtomicAppendFile {
 public:
  AtomicAppendFile(std::filesystem::path path, std::string header, std::string footer = {},
                   std::chrono::milliseconds minSyncInterval = std::chrono::milliseconds(0));
  ~AtomicAppendFile();  // brings the .part up to date (unless closed or kept); never throws
  AtomicAppendFile(const AtomicAppendFile&) = delete;
  AtomicAppendFile& operator=(const AtomicAppendFile&) = delete;

  void append(std::string_view record);  // kept in memory until the next sync
  void sync();                           // make "<path>.part" the complete document so far
  void close();  // write <path>, remove the .part; later appends are an error
  // The document so far under AtomicFile::tagged(path(), tag) (a failed or
  // interrupted run), the .part removed; closes the file. Returns that path.
  std::filesystem::path keep(std::string_view tag);
  bool closed() const { return closed_; }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path partPath() const;
  std::size_t pendingBytes() const { return body_.size() - syncedBody_; }

 private:
  void rewrite(const std::filesystem::path& target);
  void finalize(const std::filesystem::path& target);

  std::filesystem::path path_;
  std::string header_, footer_, body_;
  std::size_t syncedBody_ = 0;  // body bytes already in the .part
  bool written_ = false;        // the .part exists (header + footer at least)
  bool closed_ = false;
  std::chrono::milliseconds minInterval_;
  std::chrono::steady_clock::time_point lastWrite_;
};

}  // namespace c2d
