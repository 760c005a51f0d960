#include "core/Error.h"

namespace c2d {

std::string SourceLoc::str() const {
  return file + ":" + std::to_string(line) + ":" + std::to_string(col);
}

namespace {
std::string format(const SourceLoc& loc, const std::string& message, const std::string& text,
                   const std::string& hint) {
  std::string s = loc.str() + ": error: " + message;
  if (!text.empty()) s += "\n    " + text;
  if (!hint.empty()) s += "\n    " + hint;
  return s;
}
}  // namespace

DeckError::DeckError(SourceLoc loc, const std::string& message, std::string text, std::string hint)
    : std::runtime_error(format(loc, message, text, hint)),
      loc_(std::move(loc)),
      message_(message),
      text_(std::move(text)),
      hint_(std::move(hint)) {}

}  // namespace c2d
