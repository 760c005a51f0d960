#include "core/AtomicFile.h"

#include <cerrno>
#include <cstring>
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

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, int err) {
  std::string msg = "cannot " + what + " '" + path.string() + "'";
  if (err != 0) msg += ": " + std::string(std::strerror(err));
  throw std::runtime_error(msg);
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path path)
    : path_(std::move(path)), part_(partPathOf(path_)) {
  if (path_.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(path_.parent_path(), ec);
    if (ec) fail(path_.parent_path(), "create directory", ec.value());
  }
  errno = 0;
  out_.open(part_, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!out_) fail(part_, "open for writing", errno);
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::error_code ec;  // a destructor must not throw; a leftover .part is harmless
  std::filesystem::remove(part_, ec);
}

void AtomicFile::commit() {
  if (committed_) throw std::logic_error("AtomicFile::commit called twice for '" + path_.string() + "'");
  errno = 0;
  out_.flush();
  const bool wrote = static_cast<bool>(out_);
  const int err = errno;
  out_.close();
  if (!wrote || out_.fail()) {
    std::error_code ec;
    std::filesystem::remove(part_, ec);
    fail(part_, "write", err);
  }
  std::error_code ec;
  std::filesystem::rename(part_, path_, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(part_, ignored);
    fail(path_, "rename '" + part_.filename().string() + "' to", ec.value());
  }
  committed_ = true;
}

void AtomicFile::write(const std::filesystem::path& path, std::string_view content) {
  AtomicFile file(path);
  file.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  file.commit();
}

AtomicAppendFile::AtomicAppendFile(std::filesystem::path path, std::string header, std::string footer,
                                   std::chrono::milliseconds minSyncInterval)
    : path_(std::move(path)),
      header_(std::move(header)),
      footer_(std::move(footer)),
      minInterval_(minSyncInterval) {}

AtomicAppendFile::~AtomicAppendFile() {
  if (closed_ || (written_ && pendingBytes() == 0)) return;
  try {
    rewrite();
  } catch (...) {
    // Unwinding from another failure: the last synced document stays on disk.
  }
}

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
  rewrite();
}

void AtomicAppendFile::close() {
  if (closed_) return;
  rewrite();
  closed_ = true;
}

void AtomicAppendFile::rewrite() {
  AtomicFile file(path_);
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
