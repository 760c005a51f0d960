#include "core/io/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <mutex>
#include <random>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace c2d {

namespace {

std::filesystem::path partPathOf(const std::filesystem::path& path) {
  std::filesystem::path part = path;
  part += ".part";
  return part;
}

std::mutex& failureMutex() {
  static std::mutex m;
  return m;
}
std::map<std::string, int>& failures() {
  static std::map<std::string, int> f;
  return f;
}

// "<path>.<6 random characters>.part", created exclusively: an existing file
// or link of that name is never opened, another name is drawn instead.
int createTemporary(const std::filesystem::path& path, std::filesystem::path& temp) {
  static const char kChars[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  thread_local std::mt19937_64 random{std::random_device{}() ^
                                      (static_cast<std::uint64_t>(::getpid()) << 32)};
  int err = EEXIST;
  for (int attempt = 0; attempt < 100 && err == EEXIST; ++attempt) {
    std::string suffix = ".";
    for (int k = 0; k < 6; ++k) suffix += kChars[random() % (sizeof kChars - 1)];
    temp = path;
    temp += suffix + ".part";
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd >= 0) return fd;
    err = errno;
  }
  errno = err;
  return -1;
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, int err) {
  std::string msg = "cannot " + what + " '" + path.string() + "'";
  if (err != 0) msg += ": " + std::string(std::strerror(err));
  throw IoError(msg);
}

}  // namespace

std::filesystem::path AtomicFile::tagged(const std::filesystem::path& path, std::string_view tag) {
  std::filesystem::path name = path.stem();
  name += ".";
  name += std::string(tag);
  name += path.extension();
  return path.parent_path() / name;
}

SimulatedWriteFailure::SimulatedWriteFailure(std::string fileName, int err)
    : name_(std::move(fileName)) {
  std::lock_guard lock(failureMutex());
  failures()[name_] = err;
}

SimulatedWriteFailure::~SimulatedWriteFailure() {
  std::lock_guard lock(failureMutex());
  failures().erase(name_);
}

int SimulatedWriteFailure::errorFor(const std::filesystem::path& path) {
  std::lock_guard lock(failureMutex());
  if (failures().empty()) return 0;
  const auto it = failures().find(path.filename().string());
  return it == failures().end() ? 0 : it->second;
}

AtomicFile::AtomicFile(std::filesystem::path path)
    : path_(std::move(path)), out_(nullptr), lastFlush_(std::chrono::steady_clock::now()) {
  if (path_.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(path_.parent_path(), ec);
    if (ec) fail(path_.parent_path(), "create the directory", ec.value());
  }
  const int fd = createTemporary(path_, part_);
  if (fd < 0) fail(path_, "create a temporary file to write", errno);
  buf_ = std::make_unique<FdOutBuf>(fd);
  if (const int err = SimulatedWriteFailure::errorFor(path_)) buf_->failWritesWith(err);
  out_.rdbuf(buf_.get());
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  buf_->close();
  std::error_code ec;  // a destructor must not throw; a leftover .part is harmless
  std::filesystem::remove(part_, ec);
}

void AtomicFile::check(std::chrono::milliseconds flushInterval) {
  if (committed_) return;
  if (out_) {
    const auto now = std::chrono::steady_clock::now();
    if (now - lastFlush_ < flushInterval) return;
    lastFlush_ = now;
    out_.flush();
    if (out_) return;
  }
  fail(path_, "write", buf_->error());
}

void AtomicFile::commit() { commitTo(path_); }

std::filesystem::path AtomicFile::keep(std::string_view tag) {
  const std::filesystem::path target = tagged(path_, tag);
  commitTo(target);
  return target;
}

void AtomicFile::commitTo(const std::filesystem::path& target) {
  if (committed_)
    throw std::logic_error("AtomicFile::commit called twice for '" + path_.string() + "'");
  out_.flush();
  const bool wrote = static_cast<bool>(out_) && buf_->close();
  if (!wrote) {
    std::error_code ec;
    std::filesystem::remove(part_, ec);
    committed_ = true;  // nothing left to commit; the destructor has nothing to remove
    fail(path_, "write", buf_->error());
  }
  std::error_code ec;
  std::filesystem::rename(part_, target, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(part_, ignored);
    committed_ = true;
    fail(target, "rename '" + part_.filename().string() + "' to", ec.value());
  }
  committed_ = true;
}

void AtomicFile::write(const std::filesystem::path& path, std::string_view content) {
  AtomicFile file(path);
  file.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  file.commit();
}

AtomicAppendFile::AtomicAppendFile(std::filesystem::path path, std::string header,
                                   std::string footer, std::chrono::milliseconds minSyncInterval)
    : path_(std::move(path)),
      header_(std::move(header)),
      footer_(std::move(footer)),
      minInterval_(minSyncInterval) {}

AtomicAppendFile::~AtomicAppendFile() {
  if (closed_ || (written_ && pendingBytes() == 0)) return;
  try {
    rewrite(partPath());
  } catch (...) {
    // Unwinding from another failure: the last synced document stays on disk.
  }
}

std::filesystem::path AtomicAppendFile::partPath() const { return partPathOf(path_); }

void AtomicAppendFile::append(std::string_view record) {
  if (closed_) throw std::logic_error("append to closed file '" + path_.string() + "'");
  body_.append(record);
}

void AtomicAppendFile::sync() {
  if (closed_) return;
  if (written_ && pendingBytes() == 0) return;
  if (written_ && minInterval_.count() > 0 &&
      std::chrono::steady_clock::now() - lastWrite_ < minInterval_)
    return;
  rewrite(partPath());
}

void AtomicAppendFile::close() {
  if (closed_) return;
  finalize(path_);
}

std::filesystem::path AtomicAppendFile::keep(std::string_view tag) {
  const std::filesystem::path target = AtomicFile::tagged(path_, tag);
  if (!closed_) finalize(target);
  return target;
}

void AtomicAppendFile::finalize(const std::filesystem::path& target) {
  closed_ = true;
  rewrite(target);
  std::error_code ec;
  std::filesystem::remove(partPath(), ec);
}

void AtomicAppendFile::rewrite(const std::filesystem::path& target) {
  AtomicFile file(target);
  std::ostream& out = file.stream();
  out.write(header_.data(), static_cast<std::streamsize>(header_.size()));
  out.write(body_.data(), static_cast<std::streamsize>(body_.size()));
  out.write(footer_.data(), static_cast<std::streamsize>(footer_.size()));
  file.commit();
  syncedBody_ = body_.size();
  written_ = true;
  lastWrite_ = std::chrono::steady_clock::now();
}

}  // namespace c2d
