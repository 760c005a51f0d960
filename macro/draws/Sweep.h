#pragma once
// [ext] The concise parameter sweep (SWEEp block, macro/deck/Deck.h TopSweep): how a
// run of a sweep is named. Each run's outputs carry its values in the file
// names, "<stem>_ks=-393_tplot.csv" (several variables joined by '_'), and its
// curves in an overlay carry them in the legend, "ks = -393".
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "macro/deck/Deck.h"

namespace c2d {

// (name as written, value) of each sweep variable of one run.
using SweepValues = std::vector<std::pair<std::string, double>>;

// A value as file names and legends show it: %g (six significant digits).
std::string formatSweepValue(double value);
// A swept value as the study tables write it: the shortest text that reads
// back to the same double (as the drawn values: 0.1234567, 1.0000000000000002e+16,
// 1e-310), a zero as 0.
std::string exactSweepValue(double value);
// "ks=-393_mu=100": letters, digits, '.', '-', '+', '=' and '_' only.
std::string sweepTag(const SweepValues& values);
// A run's output stem within file-name limits: a stem longer than max
// characters is cut and ends in '_' and a hash of the whole stem (8 hex
// digits), so that it stays distinct and the same from run to run.
std::string fitFileStem(const std::string& stem, std::size_t max = 160);
// "ks = -393, mu = 100".
std::string sweepLabel(const SweepValues& values);

// A variable's values: each range lo:step:hi gives lo + k step for k = 0, 1,
// ... up to hi (the last value is hi itself when the steps land on it within
// 1e-9 of a step; at most DeckLimits::kMaxRuns values).
std::vector<double> sweepValues(const SweepVariable& v, const Parameters& params);
// The value sets of a sweep, one per run (its variables zipped): a DeckError at
// a variable whose number of values differs from the first's.
std::vector<SweepValues> sweepRuns(const TopSweep& sweep, const Parameters& params);

// [ext] Named plans: the SWEEp record 'PLAN = name1 name2 ...' names the value
// sets (zipped with the variables as one of them; a name is a letter, then
// letters, digits or '_', the names distinct). It sets no parameter: plan k's
// runs are <stem>_<name k> (then _s07 in an ensemble), and its legend entries,
// picture titles, log lines and the tables' `name` column say name k.
bool isPlanNames(const SweepVariable& v);
// The sweep's plan names in value-set order, empty without a PLAN record;
// DeckError at a name that is no name, a repeated one or a range.
std::vector<std::string> sweepPlanNames(const TopSweep& sweep);

}  // namespace c2d
