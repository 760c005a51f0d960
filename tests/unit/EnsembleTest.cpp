// An ensemble's draws (macro/studies/Ensemble): every law draws finite numbers
// or is refused at its record; a drawn parameter's random numbers are its own,
// whatever its name (a parameter named detonator or jitter is not the scatter
// drawn again); the draws of a sample depend on the seed and the sample alone.
#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "core/Error.h"
#include "macro/deck/DeckParser.h"
#include "macro/mesh/ParseDeck.h"
#include "macro/draws/CounterRandom.h"
#include "macro/draws/Distribution.h"
#include "macro/draws/Ensemble.h"

namespace c2d {
namespace {

const char* kProblem = R"(
FEAP * * a bar
  0 0 0 2 3 2

COORdinates
  1 0 0 0
  2 0 1 0

ELEMents
  1 0 1 1 2

MATErial,1
  FRAMe
    RESUltant STIFfness 1e6 1e6 1e3

END
BATCh
END

STOP
)";

EnsembleSpec specOf(const std::string& block) {
  const Deck deck = parseDeckText(block + kProblem, "draws.inp", ".");
  const auto* e = std::get_if<TopEnsemble>(&deck.items.at(0));
  EXPECT_NE(e, nullptr);
  Parameters params;
  return evaluateEnsemble(*e, params);
}

TEST(EnsembleDraws, ALawWhoseDrawsAreNotFiniteIsALocatedError) {
  for (const char* law : {"UNIForm -1e308 1e308", "LOGNormal 0.4 1e300", "NORMal 1e308 1e308",
                          "LOGNormal 1e-320 10"}) {
    try {
      specOf(std::string("ENSEmble,,3,1\n  mu = ") + law + "\n");
      ADD_FAILURE() << "accepted: " << law;
    } catch (const DeckError& e) {
      EXPECT_EQ(e.loc().line, 2) << e.what();
      EXPECT_NE(e.message().find("the law of 'mu'"), std::string::npos) << e.what();
      EXPECT_NE(e.message().find("beyond the numbers a run can compute with"), std::string::npos)
          << e.what();
    }
  }
  // Wide laws whose draws stay finite are kept.
  const EnsembleSpec s = specOf("ENSEmble,,3,1\n  mu = NORMal 1e300 1e299\n  b = UNIForm -1e307 1e307\n");
  for (int k = 1; k <= 3; ++k)
    for (const auto& [name, v] : drawSample(s, k).values) EXPECT_TRUE(std::isfinite(v)) << name;
}

TEST(EnsembleDraws, AParameterNamedLikeTheProgramsOwnDrawsHasAStreamOfItsOwn) {
  EXPECT_EQ(drawnStream("mu"), streamOf("mu"));  // every other name: as before
  for (const char* own : {"detonator", "Detonator", "jitter"})
    EXPECT_NE(drawnStream(own), streamOf(own)) << own;
  const EnsembleSpec s = specOf("ENSEmble,,20,7\n  detonator = NORMal 0 1\n");
  for (int k = 1; k <= 20; ++k) {
    const double drawn = drawSample(s, k).values.at(0).second;
    // The detonators' first draw of sample k (macro/draws/Detonators.cpp).
    const double scatter = normalQuantile(counterUniform(7, k, streamOf("detonator"), 0));
    EXPECT_NE(drawn, scatter) << "sample " << k;
  }
}

TEST(EnsembleDraws, DependOnSeedAndSampleAlone) {
  // The draws of (seed, sample) whatever the runs before: the same values
  // called in any order, and every plan's sample k sees the same.
  EXPECT_EQ(counterUniform(3, 17, streamOf("mu"), 0), counterUniform(3, 17, streamOf("MU"), 0));
  EXPECT_NE(counterUniform(3, 17, streamOf("mu"), 0), counterUniform(3, 18, streamOf("mu"), 0));
  EXPECT_NE(counterUniform(3, 17, streamOf("mu"), 0), counterUniform(4, 17, streamOf("mu"), 0));
  EnsembleSpec spec;
  spec.samples = 5;
  spec.seed = 11;
  spec.draws = {{"mu", {Law::Uniform, 0.4, 0.6}}, {"fMu", {Law::LogNormal, 1, 0.1}}};
  spec.jitter = JitterSpec{};
  const SampleDraws late = drawSample(spec, 4);
  const SampleDraws first = drawSample(spec, 1);
  EXPECT_EQ(drawSample(spec, 4).values, late.values);
  EXPECT_EQ(drawSample(spec, 4).stepFactor, late.stepFactor);
  EXPECT_NE(first.values, late.values);
  // A draw does not depend on the other records: fMu alone draws the same.
  EnsembleSpec alone = spec;
  alone.draws.erase(alone.draws.begin());
  EXPECT_EQ(drawSample(alone, 4).values[0], late.values[1]);
  for (int k = 1; k <= 5; ++k) {
    const SampleDraws d = drawSample(spec, k);
    EXPECT_GE(d.values[0].second, 0.4);
    EXPECT_LE(d.values[0].second, 0.6);
    EXPECT_GE(d.stepFactor, 0.99);
    EXPECT_LE(d.stepFactor, 1.01);
  }
}

}  // namespace
}  // namespace c2d
