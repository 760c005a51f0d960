#include "core/InputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/Error.h"

namespace c2d {

namespace {

[[noreturn]] void cannotRead(const std::filesystem::path& path, int err) {
  throw IoError("cannot read '" + path.string() + "': " + std::strerror(err));
}

struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string readRegularFile(const std::filesystem::path& path, std::uintmax_t maxBytes) {
  // O_NONBLOCK: opening a FIFO returns at once (it is then refused by fstat).
  const Descriptor d{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (d.fd < 0) cannotRead(path, errno);
  struct stat st {};
  if (::fstat(d.fd, &st) != 0) cannotRead(path, errno);
  if (!S_ISREG(st.st_mode))
    throw UnfitInputFile(S_ISDIR(st.st_mode) ? "it is a directory, not a file"
                                              : "it is not a regular file (a device, a FIFO or a "
                                                "socket), so it is not read");
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > maxBytes)
    throw UnfitInputFile("it holds " + std::to_string(size) + " bytes, more than the " +
                         std::to_string(maxBytes) + " such a file can hold");
  std::string text;
  text.resize(static_cast<std::size_t>(size));
  std::size_t done = 0;
  for (;;) {
    if (done == text.size()) {
      // The file may have grown since fstat: read on, up to the limit.
      if (text.size() > maxBytes) break;
      text.resize(std::min<std::uintmax_t>(maxBytes + 1, text.size() + 65536));
    }
    const ssize_t n = ::read(d.fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) cannotRead(path, errno);
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  if (done > maxBytes)
    throw UnfitInputFile("it holds more than the " + std::to_string(maxBytes) +
                         " bytes such a file can hold");
  return text;
}

}  // namespace c2d
