#pragma once
// Support for the tests of the result writers: a strict little XML reader (it
// rejects unbalanced or misnamed end tags, bad attributes and stray '<' or '&'),
// and an element whose section forces and hinge state a test sets directly
// (the temporary directory and a file's text: DeckTestSupport.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/Element.h"
#include "core/Hinge.h"
#include "tests/unit/DeckTestSupport.h"
#include "tests/unit/StubElementSupport.h"

namespace c2d::testing {

// The temporary an AtomicFile writes <path> through ("<path>.XXXXXX.part"),
// or an empty path when there is none.
inline std::filesystem::path partFileOf(const std::filesystem::path& path) {
  const std::string prefix = path.filename().string() + ".";
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(path.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() == prefix.size() + 11 && name.starts_with(prefix) && name.ends_with(".part"))
      return e.path();
  }
  return {};
}

struct XmlNode {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::string text;  // character data directly inside, entities decoded
  std::vector<XmlNode> children;

  std::string attr(const std::string& key) const {
    auto it = attrs.find(key);
    return it == attrs.end() ? std::string() : it->second;
  }
  bool has(const std::string& key) const { return attrs.count(key) != 0; }
  // Every descendant (self included) satisfying pred, in document order.
  void collect(const std::function<bool(const XmlNode&)>& pred, std::vector<const XmlNode*>& out) const {
    if (pred(*this)) out.push_back(this);
    for (const XmlNode& c : children) c.collect(pred, out);
  }
  // Pointers into this node: not on a temporary, whose pointers would dangle
  // as soon as the statement ends.
  std::vector<const XmlNode*> all(const std::string& tag, const std::string& cls = {}) const& {
    std::vector<const XmlNode*> out;
    collect([&](const XmlNode& n) { return n.name == tag && (cls.empty() || n.attr("class") == cls); }, out);
    return out;
  }
  std::vector<const XmlNode*> all(const std::string& tag, const std::string& cls = {}) const&& = delete;
};

class XmlReader {
 public:
  static XmlNode parse(const std::string& s) {
    XmlReader r(s);
    return r.document();
  }

 private:
  explicit XmlReader(const std::string& s) : s_(s) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML error at offset " + std::to_string(i_) + ": " + what);
  }
  bool startsWith(const char* p) const { return s_.compare(i_, std::char_traits<char>::length(p), p) == 0; }
  void skipSpace() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  void skipMisc() {
    for (;;) {
      skipSpace();
      if (startsWith("<?")) {
        const auto e = s_.find("?>", i_);
        if (e == std::string::npos) fail("unterminated processing instruction");
        i_ = e + 2;
      } else if (startsWith("<!--")) {
        const auto e = s_.find("-->", i_);
        if (e == std::string::npos) fail("unterminated comment");
        i_ = e + 3;
      } else {
        return;
      }
    }
  }
  std::string decode(const std::string& raw) const {
    std::string out;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      if (raw[k] == '<') fail("'<' in character data");
      if (raw[k] != '&') {
        out += raw[k];
        continue;
      }
      const auto semi = raw.find(';', k);
      if (semi == std::string::npos) fail("unterminated entity");
      const std::string ent = raw.substr(k + 1, semi - k - 1);
      if (ent == "amp") out += '&';
      else if (ent == "lt") out += '<';
      else if (ent == "gt") out += '>';
      else if (ent == "quot") out += '"';
      else if (ent == "apos") out += '\'';
      else fail("unknown entity &" + ent + ";");
      k = semi;
    }
    return out;
  }
  std::string name() {
    const std::size_t b = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' ||
                              s_[i_] == '-' || s_[i_] == ':' || s_[i_] == '.'))
      ++i_;
    if (i_ == b) fail("name expected");
    return s_.substr(b, i_ - b);
  }
  XmlNode element() {
    if (!startsWith("<")) fail("'<' expected");
    ++i_;
    XmlNode node;
    node.name = name();
    for (;;) {
      skipSpace();
      if (startsWith("/>")) {
        i_ += 2;
        return node;
      }
      if (startsWith(">")) {
        ++i_;
        break;
      }
      const std::string key = name();
      skipSpace();
      if (!startsWith("=")) fail("'=' expected after attribute " + key);
      ++i_;
      skipSpace();
      if (i_ >= s_.size() || (s_[i_] != '"' && s_[i_] != '\'')) fail("quoted value expected");
      const char q = s_[i_++];
      const auto e = s_.find(q, i_);
      if (e == std::string::npos) fail("unterminated attribute value");
      if (node.attrs.count(key)) fail("duplicate attribute " + key);
      node.attrs[key] = decode(s_.substr(i_, e - i_));
      i_ = e + 1;
    }
    for (;;) {
      const auto lt = s_.find('<', i_);
      if (lt == std::string::npos) fail("missing </" + node.name + ">");
      node.text += decode(s_.substr(i_, lt - i_));
      i_ = lt;
      if (startsWith("</")) {
        i_ += 2;
        const std::string end = name();
        if (end != node.name) fail("</" + end + "> closes <" + node.name + ">");
        skipSpace();
        if (!startsWith(">")) fail("'>' expected");
        ++i_;
        return node;
      }
      if (startsWith("<!--")) {
        skipMisc();
        continue;
      }
      node.children.push_back(element());
    }
  }
  XmlNode document() {
    skipMisc();
    XmlNode root = element();
    skipMisc();
    if (i_ != s_.size()) fail("content after the root element");
    return root;
  }

  const std::string& s_;
  std::size_t i_ = 0;
};

inline std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> v;
  for (std::string tok; in >> tok;) v.push_back(std::strtod(tok.c_str(), nullptr));
  return v;
}

// An element that reports what the test sets: section forces and hinge state.
class ReportingElement final : public test::StubElement, public HingeCarrier {
 public:
  ReportingElement(int a, int b, int material) : StubElement("reporting", material, {a, b}) {}
  Status evaluate(const ElementKinematics&, const StepRule&, bool, ElemVec& r,
                  ElemMat& k) override {
    r.setZero();
    k.setZero();
    return Status::success();
  }
  SectionForces sectionForces() const override { return forces; }
  double hingeDemand() const override { return 0; }
  void activateHinge() override { hingeInfo.active = true; }
  HingeInfo hinge() const override { return hingeInfo; }

  SectionForces forces;
  HingeInfo hingeInfo;
};

}  // namespace c2d::testing
