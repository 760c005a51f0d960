// libFuzzer target for `collapse2d merge`: the input is a folder of parts,
// written as a sequence of files, each one a line "=== NAME" followed by its
// text up to the next such line; "=== NAME -> TARGET" makes NAME a symbolic
// link instead (to another file of the folder or to /dev/zero). NAME is a file
// name (no '/', at most 200 characters, at most 24 files). The folder is
// written afresh in a temporary directory and merged (mergeParts). The
// expected answers are the statuses of merge: 0 merged, 1 a part refused (by
// name), 3 an I/O error; an "internal error", any exception, a crash or a
// sanitizer report is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "macro/batch/Merge.h"

namespace {

namespace fs = std::filesystem;

const fs::path& scratch() {
  static const fs::path dir = [] {
    const fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    const fs::path d = base / ("c2d-merge-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

bool validName(const std::string& name) {
  return !name.empty() && name.size() <= 200 && name.find('/') == std::string::npos &&
         name.find('\0') == std::string::npos && name != "." && name != "..";
}

// Writes the files the input describes into dir.
void writeFolder(const std::string& text, const fs::path& dir) {
  std::size_t p = text.rfind("=== ", 0) == 0 ? 0 : text.find("\n=== ");
  int files = 0;
  while (p != std::string::npos && files < 24) {
    if (text[p] == '\n') ++p;
    const std::size_t eol = text.find('\n', p);
    std::string head = text.substr(p + 4, eol == std::string::npos ? std::string::npos : eol - p - 4);
    const std::size_t next = eol == std::string::npos ? std::string::npos : text.find("\n=== ", eol);
    const std::string body = eol == std::string::npos
                                 ? std::string()
                                 : text.substr(eol + 1, next == std::string::npos ? std::string::npos
                                                                                   : next - eol);
    p = next;
    const std::size_t arrow = head.find(" -> ");
    std::error_code ec;
    if (arrow != std::string::npos) {
      const std::string name = head.substr(0, arrow), target = head.substr(arrow + 4);
      if (!validName(name) || (target != "/dev/zero" && !validName(target))) continue;
      fs::create_symlink(target, dir / name, ec);
    } else if (validName(head)) {
      std::ofstream(dir / head, std::ios::binary) << body;
    }
    ++files;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const fs::path dir = scratch() / "parts";
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  writeFolder(text, dir);
  std::ostringstream out, err;
  const int status = c2d::mergeParts(dir, out, err);
  // An internal error is a line of the program's own, starting with its
  // prefix; a part's text quoted inside a message may say anything (a cell
  // reading "collapse2d merge: internal error: " included), but no quoted
  // text starts a line (the files' names and cells hold no newline).
  const std::string log = "\n" + err.str();
  if ((status != 0 && status != 1 && status != 3) ||
      log.find("\ncollapse2d merge: internal error: ") != std::string::npos) {
    std::fprintf(stderr, "merge: status %d\n%s", status, err.str().c_str());
    std::abort();
  }
  return 0;
}
