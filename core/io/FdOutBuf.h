#pragma once
// An output stream buffer over a POSIX file descriptor that it owns: the
// descriptor of a file created exclusively (core/io/AtomicFile.h), which a
// std::ofstream cannot adopt. A failed write(2) is kept (error()) and fails
// the stream; close() closes the descriptor and reports its failure too.
#include <streambuf>
#include <vector>

namespace c2d {

class FdOutBuf : public std::streambuf {
 public:
  explicit FdOutBuf(int fd, std::size_t bufferSize = 64 * 1024);
  ~FdOutBuf() override;  // closes the descriptor (unwritten bytes are lost)
  FdOutBuf(const FdOutBuf&) = delete;
  FdOutBuf& operator=(const FdOutBuf&) = delete;

  // The errno of the first failed write or close, 0 while every one succeeded.
  int error() const { return error_; }
  // Writes what is buffered and closes the descriptor; false on failure.
  bool close();
  // Every later write fails with err (a full disk: ENOSPC), for tests.
  void failWritesWith(int err) { injected_ = err; }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;
  std::streamsize xsputn(const char* s, std::streamsize n) override;

 private:
  bool flushBuffer();
  bool writeAll(const char* s, std::size_t n);

  int fd_;
  int error_ = 0, injected_ = 0;
  std::vector<char> buffer_;
};

}  // namespace c2d
