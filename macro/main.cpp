// collapse2d: command-line entry point.
#include <unistd.h>

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "macro/DeckRunner.h"
#include "macro/Help.h"
#include "solvers/LinearSolver.h"

namespace {

void usage(std::ostream& os) {
  os << "usage: collapse2d [options] DECK...\n"
        "       collapse2d -iIname            (FEAP's form: deck Iname, log Oname)\n"
        "       collapse2d --help [COMMAND]   (every command, or one command's fields)\n"
        "options:\n"
        "  -o DIR          write the outputs in DIR (default: the current directory)\n"
        "  -q, --quiet     no progress line and no summary\n"
        "  --solver NAME   linear solver: ";
  const auto names = c2d::linearSolverNames();
  for (std::size_t i = 0; i < names.size(); ++i) os << (i ? ", " : "") << names[i];
  os << " (default auto)\n"
        "exit status: 0 success, 1 deck error, 2 analysis failed, 3 internal error\n";
}

}  // namespace

int main(int argc, char** argv) {
  c2d::DeckOptions options;
  std::vector<std::string> decks;
  const c2d::SolutionCommands commands;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      if (i + 1 < argc) return c2d::printCommandHelp(std::cout, commands, argv[i + 1]) ? 0 : 1;
      usage(std::cout);
      std::cout << "\n";
      c2d::printAllHelp(std::cout, commands);
      return 0;
    }
    if (a == "-o" && i + 1 < argc) {
      options.outDir = argv[++i];
    } else if (a == "-q" || a == "--quiet") {
      options.quiet = true;
    } else if (a == "--solver" && i + 1 < argc) {
      options.solver = argv[++i];
      if (!c2d::makeLinearSolver(options.solver)) {
        std::cerr << "collapse2d: unknown linear solver '" << options.solver << "'\n";
        usage(std::cerr);
        return 64;
      }
    } else if (a.rfind("-i", 0) == 0 && a.size() > 2) {
      // FEAP: -iIname reads Iname and writes the log Oname.
      const std::string in = a.substr(2);
      decks.push_back(in);
      const std::string base = std::filesystem::path(in).filename().string();
      if (!base.empty() && (base[0] == 'I' || base[0] == 'i')) options.logName = "O" + base.substr(1);
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << "collapse2d: unknown option '" << a << "'\n";
      usage(std::cerr);
      return 64;
    } else {
      decks.push_back(a);
    }
  }
  if (decks.empty()) {
    usage(std::cerr);
    return 64;
  }
  options.progress = !options.quiet && isatty(STDERR_FILENO);
  int status = 0;
  for (const std::string& deck : decks) {
    const c2d::DeckOutcome o = c2d::runDeck(deck, options, commands, std::cout);
    if (o.exitCode != 0) {
      std::cerr << o.message << "\n";
      if (status == 0) status = o.exitCode;
    }
  }
  return status;
}
