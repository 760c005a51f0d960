// collapse2d._core: the deck runner of the command line (macro/DeckRunner.h),
// called from Python. It runs a deck into a folder exactly as `collapse2d -o
// DIR --set NAME=VALUE ... DECK` does and returns what the run says of itself;
// the Python package (collapse2d/__init__.py) reads the tables it wrote.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <mutex>
#include <sstream>
#include <string>

#include "macro/DeckRunner.h"
#include "macro/run/Interrupt.h"

namespace py = pybind11;

namespace {

py::dict summaryDict(const c2d::RunSummary& s) {
  py::dict d;
  d["steps"] = s.steps;
  d["iterations"] = s.iterations;
  d["factorizations"] = s.factorizations;
  d["cuts"] = s.cuts;
  d["hinges"] = s.hinges;
  d["joints_formed"] = s.jointsFormed;
  d["joints_ruptured"] = s.jointsRuptured;
  d["removed"] = s.removed;
  d["energy_error"] = s.energyError;
  d["energy_gained"] = s.energyGained;
  d["max_moment_ratio"] = s.maxMomentRatio;
  d["crossings"] = s.crossings;
  d["folded"] = s.folded;
  d["sunk"] = s.sunk;
  d["blasts_not_made"] = s.blastsNotMade;
  d["debris_runs"] = s.debrisRuns;
  d["outside_runs"] = s.outsideRuns;
  d["moving_runs"] = s.movingRuns;
  d["seconds"] = s.seconds;
  d["text"] = c2d::runSummaryText(s);
  return d;
}

// One deck at a time: the interrupt flag and the signal handlers are the
// process's own.
std::mutex runLock;

py::dict runDeck(const std::string& deck, const std::map<std::string, double>& params,
                 const std::string& out, const std::string& solver) {
  c2d::DeckOptions options;
  options.outDir = out;
  options.params = params;
  options.solver = solver;
  const c2d::SolutionCommands commands;
  std::ostringstream console;
  c2d::DeckOutcome o;
  {
    // The run holds no Python object: other Python threads go on meanwhile.
    // SIGINT and SIGTERM stop it at its next safe point as on the command line
    // (Python's own handler would only set a flag nobody reads until the end).
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(runLock);
    const c2d::ScopedInterruptHandlers handlers;
    o = c2d::runDeck(deck, options, commands, console);
  }
  py::dict r;
  r["exit_code"] = o.exitCode;
  r["message"] = o.message;
  r["interrupted"] = o.interrupted;
  r["console"] = console.str();
  r["runs"] = o.runs;
  r["failed_runs"] = o.failedRuns;
  r["summary"] = summaryDict(o.total);
  if (o.errorAt) r["error_at"] = py::make_tuple(o.errorAt->file, o.errorAt->line, o.errorAt->col);
  py::list warnings;
  for (const c2d::DeckWarning& w : o.warnings) warnings.append(w.str());
  r["warnings"] = warnings;
  return r;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "collapse2d's deck runner (use collapse2d.run)";
  m.def("run_deck", &runDeck, py::arg("deck"), py::arg("params"), py::arg("out"),
        py::arg("solver") = "auto",
        "Runs a deck into the folder out as the command line does; returns a dict of "
        "its exit code, message, error location, console text and summary.");
}
