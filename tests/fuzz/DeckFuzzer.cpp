// libFuzzer target for the deck reader: the input is a deck's text. It is lexed
// (INCLude expanded), parsed, and every problem is bound as the check pass of a
// run binds it (mesh built into a Model, BATCh blocks bound, TPLOt columns
// checked); nothing is computed and nothing is written. A DeckError is the
// expected answer to a bad deck; any other exception, a crash or a sanitizer
// report is a finding.
//
// Top-level LOOP, SWEEp and ENSEmble passes are capped at kMaxPasses per item, so that a
// deck asking for a billion passes does not read as a hang.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <variant>

#include "core/Error.h"
#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/run/ProblemRun.h"
#include "macro/deck/SolutionCommand.h"
#include "macro/draws/Sweep.h"
#include "macro/draws/Ensemble.h"

namespace {

constexpr int kMaxPasses = 3;

void checkItems(const std::vector<c2d::TopItem>& items, c2d::Parameters& params,
                const c2d::SolutionCommands& commands, const c2d::SampleDraws* sample = nullptr) {
  for (const c2d::TopItem& item : items) {
    if (const auto* pb = std::get_if<c2d::ParamBlock>(&item)) {
      pb->apply(params);
    } else if (const auto* loop = std::get_if<c2d::TopLoop>(&item)) {
      const int n = loop->count.evalInt(params, "loop count");
      for (int i = 0; i < n && i < kMaxPasses; ++i) checkItems(loop->body, params, commands, sample);
    } else if (const auto* sweep = std::get_if<c2d::TopSweep>(&item)) {
      const auto sets = c2d::sweepRuns(*sweep, params);
      for (std::size_t i = 0; i < sets.size() && i < kMaxPasses; ++i) {
        for (const auto& [name, v] : sets[i]) params.set(name, v);
        checkItems(sweep->body, params, commands, sample);
      }
    } else if (const auto* e = std::get_if<c2d::TopEnsemble>(&item)) {
      const c2d::EnsembleSpec spec = c2d::evaluateEnsemble(*e, params);
      for (int k = 1; k <= spec.samples && k <= kMaxPasses; ++k) {
        const c2d::SampleDraws draws = c2d::drawSample(spec, k);
        for (const auto& [name, v] : draws.values) params.set(name, v);
        checkItems(e->body, params, commands, &draws);
      }
    } else {
      std::ostringstream discard;
      c2d::RunOptions ro;
      ro.outDir = "/nonexistent-fuzz-output";
      ro.sample = sample;  // an ensemble's jitter and detonators in the binding
      c2d::ProblemRun run(std::get<c2d::Problem>(item), params, commands, ro, discard);
      run.bind(false);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const c2d::SolutionCommands commands;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // INCLude paths are relative to a directory that does not exist: the
    // fuzzer's answers do not depend on the files around it.
    const c2d::Deck deck = c2d::parseDeckText(text, "fuzz.inp", "/nonexistent-fuzz-input");
    c2d::Parameters params;
    checkItems(deck.items, params, commands);
  } catch (const c2d::DeckError&) {
    // A bad deck, reported as such: the answer expected.
  }
  return 0;
}
