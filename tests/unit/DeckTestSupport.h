#pragma once
// Support for the deck front-end tests: a temporary directory that removes
// itself, a file's whole text, a text's lines and whether it holds a string,
// and a check that a call fails with a DeckError at a given place.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/Error.h"

namespace c2d::testing {

class DeckTempDir {
 public:
  DeckTempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "c2d-deck-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~DeckTempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  DeckTempDir(const DeckTempDir&) = delete;
  DeckTempDir& operator=(const DeckTempDir&) = delete;

  // Writes text to name (relative to the directory, parents created); returns the full path.
  std::string write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// The whole text of a file ("" when it cannot be read).
inline std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Whether the text holds what.
inline bool contains(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

// The lines of a text, without their ends.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Runs f, expects a DeckError at file:line:col whose what() contains text.
inline void expectDeckError(const std::function<void()>& f, const std::string& file, int line,
                            int col, const std::string& text) {
  try {
    f();
    ADD_FAILURE() << "no DeckError (expected '" << text << "' at " << file << ":" << line << ":"
                  << col << ")";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.loc().file, file) << e.what();
    EXPECT_EQ(e.loc().line, line) << e.what();
    EXPECT_EQ(e.loc().col, col) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos)
        << "message lacks '" << text << "':\n"
        << e.what();
    const std::string head =
        file + ":" + std::to_string(line) + ":" + std::to_string(col) + ": error: ";
    EXPECT_EQ(std::string(e.what()).rfind(head, 0), 0u) << e.what();
  }
}

}  // namespace c2d::testing
