#include "core/io/FdOutBuf.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace c2d {

FdOutBuf::FdOutBuf(int fd, std::size_t bufferSize) : fd_(fd), buffer_(bufferSize) {
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

FdOutBuf::~FdOutBuf() {
  if (fd_ >= 0) ::close(fd_);
}

bool FdOutBuf::writeAll(const char* s, std::size_t n) {
  if (error_ != 0) return false;
  if (injected_ != 0 && n > 0) {
    error_ = injected_;
    return false;
  }
  while (n > 0) {
    const ssize_t w = ::write(fd_, s, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      error_ = w < 0 ? errno : EIO;
      return false;
    }
    s += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

bool FdOutBuf::flushBuffer() {
  const auto n = static_cast<std::size_t>(pptr() - pbase());
  const bool ok = writeAll(pbase(), n);
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return ok;
}

FdOutBuf::int_type FdOutBuf::overflow(int_type c) {
  if (!flushBuffer()) return traits_type::eof();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

int FdOutBuf::sync() { return flushBuffer() ? 0 : -1; }

std::streamsize FdOutBuf::xsputn(const char* s, std::streamsize n) {
  const auto room = static_cast<std::streamsize>(epptr() - pptr());
  if (n <= room) {
    std::memcpy(pptr(), s, static_cast<std::size_t>(n));
    pbump(static_cast<int>(n));
    return n;
  }
  // Larger than the room left: the buffer, then the text itself.
  if (!flushBuffer() || !writeAll(s, static_cast<std::size_t>(n))) return 0;
  return n;
}

bool FdOutBuf::close() {
  if (fd_ < 0) return error_ == 0;
  const bool flushed = flushBuffer();
  const int rc = ::close(fd_);
  fd_ = -1;
  if (rc != 0 && error_ == 0) error_ = errno;
  return flushed && rc == 0;
}

}  // namespace c2d
