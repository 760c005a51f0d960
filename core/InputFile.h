#pragma once
// Reading a file that another program (or a person) may have put in place of
// the one expected: a study's parts, a restart file. Only a regular file is
// read (a link to one is followed); a device (/dev/zero), a FIFO or a
// directory is refused before a byte is read (the open does not block), and so
// is a file larger than the caller's limit, so that nothing unbounded is read
// into memory.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace c2d {

// A file refused for what it is: the message says why (without the path).
class UnfitInputFile : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The whole text of the regular file at path, at most maxBytes of it. Throws
// UnfitInputFile (not a regular file; larger than maxBytes) or IoError (cannot
// be opened or read: the path and the system's reason).
std::string readRegularFile(const std::filesystem::path& path, std::uintmax_t maxBytes);

}  // namespace c2d
