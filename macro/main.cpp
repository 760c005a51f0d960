// collapse2d: command-line entry point.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "macro/batch/BatchRunner.h"
#include "macro/DeckRunner.h"
#include "macro/Help.h"
#include "macro/deck/Parameters.h"
#include "macro/batch/Shard.h"
#include "macro/studies/Csv.h"
#include "macro/batch/Merge.h"
#include "macro/batch/ParallelRuns.h"
#include "macro/run/Interrupt.h"
#include "macro/batch/Shard.h"
#include "macro/deck/Suggest.h"
#include "solvers/linear/LinearSolver.h"

namespace {

void usage(std::ostream& os) {
  os << "usage: collapse2d [options] DECK...\n"
        "       collapse2d run [options] [-j N] DECK...\n"
        "                                     (batch: every deck in a process of its own,\n"
        "                                     N at once, then a table of the results; one\n"
        "                                     deck's study: its runs in N processes)\n"
        "       collapse2d run --shard i/n [options] DECK...\n"
        "                                     (the i-th of n interleaved parts of the decks,\n"
        "                                     or of one deck's runs; batch_part<i>of<n>.csv)\n"
        "       collapse2d merge [DIR]        (check and join the parts' tables and overlays)\n"
        "       collapse2d -iIname            (FEAP's form: deck Iname, log Oname)\n"
        "       collapse2d --help [COMMAND]   (every command, or one command's fields)\n"
        "options:\n"
        "  -o DIR          write the outputs in DIR (default: the current directory)\n"
        "  -q, --quiet     no progress line and no summary\n"
        "  --set NAME=VALUE  give the parameter NAME this value in place of the one the\n"
        "                  deck's PARAmeter records assign (repeatable; a name no record\n"
        "                  assigns is a usage error, a swept or drawn name a deck error)\n"
        "  -j N            (run) decks run at the same time (default 1)\n"
        "  --timeout S     (run) stop a deck that runs longer than S seconds (SIGTERM,\n"
        "                  then SIGKILL 5 s later); the table says \"timed out\"\n"
        "  --solver NAME   linear solver: ";
  const auto names = c2d::linearSolverNames();
  for (std::size_t i = 0; i < names.size(); ++i) os << (i ? ", " : "") << names[i];
  os << " (default auto)\n"
        "exit status: 0 success, 1 deck error, 2 analysis failed, 3 internal or I/O error\n"
        "  (an output that cannot be written), 64 usage error (unknown option or solver),\n"
        "  128+N stopped by signal N: SIGINT (130) or SIGTERM (143) stop a run at the next\n"
        "  step, keep its outputs as <stem>.interrupted.out, <stem>_tplot.interrupted.csv,\n"
        "  <stem>.interrupted.pvd (a failed run: <stem>.failed.*); a second signal ends it\n"
        "  at once (run: 0 when every deck succeeded, else the status of the first that\n"
        "  failed; a signal to the batch is passed on to every running deck)\n"
        "parameter studies: a SWEEp block before a problem runs it once per value set,\n"
        "  SWEEp\n"
        "    ks = -393 -500 -700      ! name = values; several names are zipped\n"
        "                             ! (a blank record ends the block)\n"
        "  FEAP * * ...\n"
        "  outputs <stem>_ks=-393_tplot.csv, ...; the curves of PLOT,CURVe overlaid in\n"
        "  <stem>_<y>_vs_<x>.svg with a legend entry per run (see --help SWEEp); ranges\n"
        "  x = 0:0.01:1; an ENSEmble,,n,seed block runs every plan n times with drawn\n"
        "  values (see --help ENSEmble)\n";
}

// The options of both modes: -o DIR, -q, --solver NAME. Returns 1 when argv[i]
// is one (i then stands on its last word), 0 when it is not, -1 after reporting
// an error.
int deckOption(int argc, char** argv, int& i, c2d::DeckOptions& options) {
  const std::string a = argv[i];
  if (a == "-o" && i + 1 < argc) {
    options.outDir = argv[++i];
  } else if (a == "-q" || a == "--quiet") {
    options.quiet = true;
  } else if (a == "--set" && i + 1 < argc) {
    const std::string nv = argv[++i];
    const std::size_t eq = nv.find('=');
    const std::string name = nv.substr(0, eq);
    char* end = nullptr;
    const double value = eq == std::string::npos ? 0.0 : std::strtod(nv.c_str() + eq + 1, &end);
    if (eq == std::string::npos || !c2d::Parameters::validName(name) || end == nv.c_str() + eq + 1 ||
        *end != '\0' || !std::isfinite(value)) {
      std::cerr << "collapse2d: --set needs NAME=VALUE (a parameter name and a finite number), not '"
                << nv << "'\n";
      return -1;
    }
    options.params[name] = value;
  } else if (a == "--solver" && i + 1 < argc) {
    options.solver = argv[++i];
    if (!c2d::makeLinearSolver(options.solver)) {
      std::cerr << "collapse2d: unknown linear solver '" << options.solver << "'\n";
      usage(std::cerr);
      return -1;
    }
  } else {
    return 0;
  }
  return 1;
}

// Any other word of both modes: a deck, or an unknown option (reported: false).
bool deckArgument(const std::string& a, const char* program, std::vector<std::string>& decks) {
  if (!a.empty() && a[0] == '-') {
    std::cerr << program << ": unknown option '" << a << "'\n";
    usage(std::cerr);
    return false;
  }
  decks.push_back(a);
  return true;
}

// A first word that names no file but is close to a subcommand (mrege): a
// typo, reported with the subcommand meant, not read as a deck name.
bool mistypedSubcommand(const std::string& word) {
  if (word.empty() || word[0] == '-' || std::filesystem::exists(word)) return false;
  const std::string hint = c2d::didYouMean(word, {"run", "merge"});
  if (hint.empty()) return false;
  std::cerr << "collapse2d: '" << word << "' is no deck and no command: " << hint
            << " (collapse2d --help)\n";
  return true;
}

// The most processes `run -j` starts.
constexpr int kMaxJobs = 1024;

// collapse2d run [options] [-j N] DECK...
int batchMain(int argc, char** argv, const c2d::SolutionCommands& commands) {
  c2d::BatchOptions options;
  std::vector<std::string> decks;
  c2d::ShardSpec shard;
  bool shardGiven = false;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (const int known = deckOption(argc, argv, i, options.deck); known != 0) {
      if (known < 0) return c2d::kExitUsage;
    } else if (a == "--shard" && i + 1 < argc) {
      if (shardGiven) {
        std::cerr << "collapse2d run: --shard is given twice\n";
        return c2d::kExitUsage;
      }
      shardGiven = true;
      if (!c2d::parseShard(argv[++i], shard)) {
        std::cerr << "collapse2d run: --shard needs i/n with 1 <= i <= n <= " << c2d::kMaxShards << "\n";
        return c2d::kExitUsage;
      }
    } else if (const bool attached = a.size() > 2 && a.rfind("-j", 0) == 0;  // -j4
               attached || ((a == "-j" || a == "--jobs") && i + 1 < argc)) {
      const std::string n = attached ? a.substr(2) : argv[++i];
      const auto jobs = c2d::countCell(n, 1, kMaxJobs);
      if (!jobs) {
        std::cerr << "collapse2d run: -j needs a whole number of processes from 1 to " << kMaxJobs
                  << ", got '" << n << "'\n";
        return c2d::kExitUsage;
      }
      options.jobs = *jobs;
    } else if (a == "--timeout" && i + 1 < argc) {
      char* end = nullptr;
      options.timeout = std::strtod(argv[++i], &end);
      if (end == argv[i] || *end != '\0' || !(options.timeout > 0)) {
        std::cerr << "collapse2d run: --timeout needs a positive number of seconds\n";
        return c2d::kExitUsage;
      }
    } else if (!deckArgument(a, "collapse2d run", decks)) {
      return c2d::kExitUsage;
    }
  }
  if (decks.empty()) {
    usage(std::cerr);
    return c2d::kExitUsage;
  }
  if (const std::string clash = c2d::batchStemClash(decks); !clash.empty()) {
    std::cerr << "collapse2d run: " << clash << "\n";
    return c2d::kExitUsage;
  }
  if (shard.active() && decks.size() == 1 && options.jobs > 1) {
    std::cerr << "collapse2d run: -j with --shard of one deck: its shards are the processes\n";
    return c2d::kExitUsage;
  }
  decks = c2d::shardDecks(decks, shard, options.deck);
  options.progress = !options.deck.quiet && isatty(STDERR_FILENO);
  c2d::installInterruptHandlers();
  const c2d::DeckCalls calls = c2d::deckCalls(commands);
  // One deck whose runs are a study: its runs split over the -j processes.
  if (decks.size() == 1 && !shard.active() && options.jobs > 1)
    if (const int st = c2d::runDeckInParallel(decks[0], options, calls, std::cout, std::cerr); st >= 0)
      return st;
  const auto results = c2d::runBatch(decks, options, calls, std::cout);
  if (!options.deck.quiet) c2d::printBatchTable(std::cout, results);
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "collapse2d run: I/O error: cannot write the standard output: "
              << std::strerror(errno) << "\n";
    return c2d::kExitInternal;
  }
  if (shard.active())
    c2d::writeBatchPart(options.deck.outDir.empty() ? "." : options.deck.outDir, shard, results);
  if (const int sig = c2d::pendingInterrupt(); sig != 0) return c2d::interruptExitCode(sig);
  return c2d::batchExitCode(results);
}

}  // namespace

int main(int argc, char** argv) {
  c2d::DeckOptions options;
  std::vector<std::string> decks;
  const c2d::SolutionCommands commands;
  if (argc > 1 && std::string(argv[1]) == "run") return batchMain(argc, argv, commands);
  if (argc > 1 && std::string(argv[1]) == "merge") {
    if (argc > 3) {
      std::cerr << "collapse2d merge: one folder only, got '" << argv[3]
                << "' too (collapse2d merge [DIR])\n";
      return c2d::kExitUsage;
    }
    return c2d::mergeParts(argc > 2 ? argv[2] : ".", std::cout, std::cerr);
  }
  if (argc > 1 && mistypedSubcommand(argv[1])) return c2d::kExitUsage;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    // A subcommand after options (collapse2d -o out run -j 2 deck.inp): the
    // subcommand comes first; read as a deck name it would leave its own
    // options unknown.
    if ((a == "run" || a == "merge") && !std::filesystem::exists(a)) {
      std::cerr << "collapse2d: '" << a << "' comes first, before the options: collapse2d " << a
                << " [options] ...\n";
      return c2d::kExitUsage;
    }
    if (a == "--help" || a == "-h") {
      if (i + 1 < argc) return c2d::printCommandHelp(std::cout, commands, argv[i + 1]) ? 0 : 1;
      usage(std::cout);
      std::cout << "\n";
      c2d::printAllHelp(std::cout, commands);
      return 0;
    }
    if (const int known = deckOption(argc, argv, i, options); known != 0) {
      if (known < 0) return c2d::kExitUsage;
    } else if (a.rfind("-i", 0) == 0 && a.size() > 2) {
      // FEAP: -iIname reads Iname and writes the log Oname.
      const std::string in = a.substr(2);
      decks.push_back(in);
      const std::string base = std::filesystem::path(in).filename().string();
      if (!base.empty() && (base[0] == 'I' || base[0] == 'i'))
        options.logName = 'O' + base.substr(1);
    } else if (!deckArgument(a, "collapse2d", decks)) {
      return c2d::kExitUsage;
    }
  }
  if (decks.empty()) {
    usage(std::cerr);
    return c2d::kExitUsage;
  }
  options.progress = !options.quiet && isatty(STDERR_FILENO);
  c2d::installInterruptHandlers();
  int status = 0;
  for (const std::string& deck : decks) {
    const c2d::DeckOutcome o = c2d::runDeck(deck, options, commands, std::cout);
    if (o.exitCode != 0) {
      std::cerr << o.message << "\n";
      if (status == 0) status = o.exitCode;
    }
    if (o.interrupted != 0) return o.exitCode;  // the decks after it are not run
  }
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "collapse2d: I/O error: cannot write the standard output: " << std::strerror(errno)
              << "\n";
    return c2d::kExitInternal;
  }
  return status;
}
