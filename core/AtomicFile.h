#pragma once
// Result files that never look complete unless they are.
//
// AtomicFile: the text goes to "<path>.part"; commit() closes it and renames it
// over <path> (rename is atomic on POSIX file systems). Destroyed without
// commit(), it removes the .part file. So <path> either holds a previous run's
// file or the complete new one, never a truncated one; a run killed outright
// (no destructors) leaves at most a "<path>.part", whose name says it is partial.
// There is no fsync: the guarantee covers an interrupted or failed run, not a
// crash of the operating system, which keeps an output step cheap.
//
// AtomicAppendFile: a document that grows during a run (a CSV time history, the
// .pvd collection): header, records appended one at a time, footer. Every sync()
// rewrites "<path>.part" with header + all records so far + footer and renames it
// over <path>, so the file on disk is at every moment a complete, well-formed
// document holding a prefix of the records (all of them after close()). A run
// that ends by an exception still leaves the records of its committed steps: the
// destructor syncs. A sync costs a rewrite of the whole file; minSyncInterval
// bounds that cost for long histories (sync() then skips rewrites closer together
// than the interval; close() always writes).
//
// I/O failures throw std::runtime_error naming the file and the system's reason.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace c2d {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path);  // creates "<path>.part" (and its directory)
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  void commit();  // close, check every write succeeded, rename over path(); once only
  bool committed() const { return committed_; }
  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& partPath() const { return part_; }

  // The whole content in one call: write + commit.
  static void write(const std::filesystem::path& path, std::string_view content);

 private:
  std::filesystem::path path_, part_;
  std::ofstream out_;
  bool committed_ = false;
};

class AtomicAppendFile {
 public:
  AtomicAppendFile(std::filesystem::path path, std::string header, std::string footer = {},
                   std::chrono::milliseconds minSyncInterval = std::chrono::milliseconds(0));
  ~AtomicAppendFile();  // syncs unless closed; never throws
  AtomicAppendFile(const AtomicAppendFile&) = delete;
  AtomicAppendFile& operator=(const AtomicAppendFile&) = delete;

  void append(std::string_view record);  // kept in memory until the next sync
  void sync();                            // make <path> the complete document so far
  void close();                           // final sync; later appends are an error
  bool closed() const { return closed_; }
  const std::filesystem::path& path() const { return path_; }
  std::size_t pendingBytes() const { return body_.size() - syncedBody_; }

 private:
  void rewrite();

  std::filesystem::path path_;
  std::string header_, footer_, body_;
  std::size_t syncedBody_ = 0;  // body bytes already on disk
  bool written_ = false;        // the file exists (header + footer at least)
  bool closed_ = false;
  std::chrono::milliseconds minInterval_;
  std::chrono::steady_clock::time_point lastWrite_;
};

}  // namespace c2d
