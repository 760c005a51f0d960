// deckcheck: runs one regression deck and compares its results with the
// reference file beside it (<name>.ref), or rewrites that reference (--update).
//
// Reference format:
//   # free comment lines
//   # rtol 1e-6            tolerance on numbers: |got - ref| <= atol + rtol*|ref|
//   # atol 1e-9
//   # expect-exit 1        expected exit status (default 0)
//   # expect-error TEXT    text the run must print (decks that must fail)
//   # allow-crossings WHY  members may end crossing each other (otherwise a log
//                          of the run reporting crossing members fails the deck:
//                          after a collapse nothing may have passed through)
//   == <output file> ==    expected content of an output file of the run (--update
//                          rewrites the CSV files, the tables and every other
//                          file the reference already holds)
//   == <stem>.out tables == the printed tables of the log (FEAP-style spaced
//                          titles up to the next blank line)
// Words are compared exactly, numbers with the tolerance; the first mismatch is
// printed with its section, line, reference, computed value and relative error.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Reference {
  std::vector<std::string> header;  // comment lines, kept on update
  double rtol = 1e-6, atol = 1e-9;
  int expectExit = 0;
  std::vector<std::string> expectError;
  bool allowCrossings = false;
  std::vector<std::pair<std::string, std::vector<std::string>>> sections;
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> readLines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  std::string l;
  while (std::getline(in, l)) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    lines.push_back(l);
  }
  return lines;
}

Reference readReference(const fs::path& p) {
  Reference ref;
  std::vector<std::string>* body = nullptr;
  for (const std::string& l : readLines(p)) {
    if (l.rfind("== ", 0) == 0 && l.size() > 6 && l.substr(l.size() - 3) == " ==") {
      ref.sections.emplace_back(l.substr(3, l.size() - 6), std::vector<std::string>{});
      body = &ref.sections.back().second;
      continue;
    }
    if (body) {
      body->push_back(l);
      continue;
    }
    ref.header.push_back(l);
    std::istringstream is(l);
    std::string hash, key;
    is >> hash >> key;
    if (hash != "#") continue;
    if (key == "rtol") is >> ref.rtol;
    if (key == "atol") is >> ref.atol;
    if (key == "expect-exit") is >> ref.expectExit;
    if (key == "allow-crossings") ref.allowCrossings = true;
    if (key == "expect-error") {
      std::string rest;
      std::getline(is, rest);
      ref.expectError.push_back(trim(rest));
    }
  }
  for (auto& [name, lines] : ref.sections)
    while (!lines.empty() && trim(lines.back()).empty()) lines.pop_back();
  return ref;
}

// A table title in the log: FEAP's spaced letters, e.g. "   N o d a l   D i s p l a c e m e n t s":
// a capital, then letters each followed by a blank.
bool isTableTitle(const std::string& l) {
  const std::string t = trim(l);
  if (t.size() < 6 || !std::isupper(static_cast<unsigned char>(t[0]))) return false;
  for (size_t i = 0; i < 6; i += 2)
    if (!std::isalpha(static_cast<unsigned char>(t[i])) || t[i + 1] != ' ') return false;
  return true;
}

std::vector<std::string> logTables(const fs::path& p) {
  std::vector<std::string> out;
  bool in = false;
  for (const std::string& l : readLines(p)) {
    if (!in && isTableTitle(l)) in = true;
    if (!in) continue;
    if (trim(l).empty()) {
      in = false;
      out.emplace_back();
      continue;
    }
    out.push_back(l);
  }
  while (!out.empty() && out.back().empty()) out.pop_back();
  return out;
}

std::vector<std::string> tokens(const std::string& l) {
  std::vector<std::string> t;
  std::string cur;
  for (char c : l) {
    if (c == ' ' || c == '\t' || c == ',') {
      if (!cur.empty()) t.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) t.push_back(cur);
  return t;
}

bool number(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end && *end == '\0' && end != s.c_str();
}

bool compare(const std::string& section, const std::vector<std::string>& ref,
             const std::vector<std::string>& got, const Reference& tol) {
  std::vector<std::string> g = got;
  while (!g.empty() && trim(g.back()).empty()) g.pop_back();
  if (ref.size() != g.size()) {
    std::cerr << "mismatch in [" << section << "]: " << ref.size() << " reference lines, "
              << g.size() << " computed\n";
    const size_t n = std::min(ref.size(), g.size());
    for (size_t i = 0; i < n; ++i)
      if (ref[i] != g[i]) {
        std::cerr << "  first differing line " << i + 1 << ":\n    ref: " << ref[i]
                  << "\n    got: " << g[i] << "\n";
        break;
      }
    return false;
  }
  for (size_t i = 0; i < ref.size(); ++i) {
    const auto a = tokens(ref[i]), b = tokens(g[i]);
    if (a.size() != b.size()) {
      std::cerr << "mismatch in [" << section << "] line " << i + 1 << ":\n    ref: " << ref[i]
                << "\n    got: " << g[i] << "\n";
      return false;
    }
    for (size_t k = 0; k < a.size(); ++k) {
      double x = 0, y = 0;
      if (number(a[k], x) && number(b[k], y)) {
        const double err = std::abs(y - x);
        if (!(err <= tol.atol + tol.rtol * std::abs(x))) {
          std::cerr << "mismatch in [" << section << "] line " << i + 1 << " field " << k + 1
                    << ": reference " << a[k] << ", computed " << b[k] << ", relative error "
                    << (x != 0 ? err / std::abs(x) : err) << "\n    ref: " << ref[i]
                    << "\n    got: " << g[i] << "\n";
          return false;
        }
      } else if (a[k] != b[k]) {
        std::cerr << "mismatch in [" << section << "] line " << i + 1 << ": '" << a[k]
                  << "' expected, '" << b[k] << "' found\n";
        return false;
      }
    }
  }
  return true;
}

int run(const std::string& exe, const fs::path& deck, const fs::path& dir, std::string& output) {
  const fs::path log = dir / "deckcheck.console";
  // The batch path (a child process per deck), as `collapse2d run` runs decks.
  const std::string cmd = "'" + exe + "' run --quiet -o '" + dir.string() + "' '" + deck.string() +
                          "' > '" + log.string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  output = ss.str();
  fs::remove(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

}  // namespace

int main(int argc, char** argv) {
  std::string exe, deckArg;
  bool update = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--exe" && i + 1 < argc) exe = argv[++i];
    else if (a == "--deck" && i + 1 < argc) deckArg = argv[++i];
    else if (a == "--update") update = true;
    else {
      std::cerr << "usage: deckcheck --exe collapse2d --deck DECK.inp [--update]\n";
      return 2;
    }
  }
  if (exe.empty() || deckArg.empty()) {
    std::cerr << "usage: deckcheck --exe collapse2d --deck DECK.inp [--update]\n";
    return 2;
  }
  const fs::path deck = fs::absolute(deckArg);
  const fs::path refPath = fs::path(deck).replace_extension(".ref");
  const std::string stem = deck.stem().string();
  Reference ref;
  if (fs::exists(refPath)) ref = readReference(refPath);

  char tmpl[] = "/tmp/deckcheck.XXXXXX";
  if (!mkdtemp(tmpl)) {
    std::perror("mkdtemp");
    return 2;
  }
  const fs::path dir = tmpl;
  std::string output;
  const int code = run(exe, deck, dir, output);

  int failures = 0;
  if (code != ref.expectExit) {
    std::cerr << deck.string() << ": exit status " << code << ", expected " << ref.expectExit
              << "\n" << output;
    ++failures;
  }
  for (const std::string& e : ref.expectError)
    if (output.find(e) == std::string::npos) {
      std::cerr << deck.string() << ": expected message not printed: " << e << "\n--- output:\n"
                << output;
      ++failures;
    }

  // The final geometry: members that pass through each other are reported in
  // the logs ("warning: members a and b cross at t = ...").
  if (!ref.allowCrossings)
    for (const auto& ent : fs::directory_iterator(dir)) {
      if (ent.path().extension() != ".out") continue;
      for (const std::string& l : readLines(ent.path()))
        if (l.find("warning: members ") != std::string::npos &&
            l.find(" cross at t = ") != std::string::npos) {
          std::cerr << deck.string() << ": members cross at the end of the run ("
                    << ent.path().filename().string() << "):" << l << "\n";
          ++failures;
          break;
        }
    }

  auto produced = [&](const std::string& name) -> std::vector<std::string> {
    if (name == stem + ".out tables") return logTables(dir / (stem + ".out"));
    return readLines(dir / name);
  };

  if (update) {
    std::vector<std::string> names;
    if (ref.expectExit == 0) {
      std::vector<std::string> csv;
      for (const auto& ent : fs::directory_iterator(dir))
        // A study's <stem>_timing.csv holds CPU seconds: never a reference.
        if (ent.path().extension() == ".csv" && !ent.path().stem().string().ends_with("_timing"))
          csv.push_back(ent.path().filename().string());
      std::sort(csv.begin(), csv.end());
      if (fs::exists(dir / (stem + ".out")) && !logTables(dir / (stem + ".out")).empty())
        names.push_back(stem + ".out tables");
      names.insert(names.end(), csv.begin(), csv.end());
      // Other result files the reference already compares (.pvd, .vtu) stay compared.
      for (const auto& [name, lines] : ref.sections)
        if (std::find(names.begin(), names.end(), name) == names.end() && fs::exists(dir / name))
          names.push_back(name);
    }
    std::ofstream out(refPath);
    if (ref.header.empty()) out << "# reference results of " << deck.filename().string() << "\n";
    for (const auto& h : ref.header) out << h << "\n";
    for (const auto& n : names) {
      out << "== " << n << " ==\n";
      for (const auto& l : produced(n)) out << l << "\n";
    }
    std::cout << "wrote " << refPath.string() << " (" << names.size() << " sections)\n";
  } else {
    for (const auto& [name, lines] : ref.sections) {
      if (name != stem + ".out tables" && !fs::exists(dir / name)) {
        std::cerr << deck.string() << ": the run did not write " << name << "\n";
        ++failures;
        continue;
      }
      if (!compare(name, lines, produced(name), ref)) ++failures;
    }
    if (ref.sections.empty() && ref.expectError.empty()) {
      std::cerr << refPath.string() << ": no results to compare\n";
      ++failures;
    }
  }
  fs::remove_all(dir);
  if (failures) std::cerr << deck.filename().string() << ": FAILED\n";
  return failures ? 1 : 0;
}
