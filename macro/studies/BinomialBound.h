#pragma once
// [ext] How many runs an answer needs: the exact binomial (Clopper-Pearson)
// upper confidence bound on a probability from k events in n runs, and the
// runs without an event that would show it below a level.
//
// The one-sided upper bound at confidence c is the p at which k or fewer
// events in n runs have probability 1 - c: P(X <= k; n, p) = 1 - c (p = 1 at
// k = n). At k = 0 it is 1 - (1 - c)^(1/n): showing p < 1 % at 95 % takes
// n >= ln(0.05)/ln(0.99) = 298.1, 299 clean runs. (The Wilson interval's upper
// end, z = 1.96, needs 381 for the same; it is an approximation, the program
// uses the exact bound.)
namespace c2d {

// The upper bound (0..1) for k events in n runs (n = 0: 1).
double clopperPearsonUpper(int k, int n, double confidence);

// The least number of runs N >= n such that k events in N runs (the runs
// after the n all without an event) give an upper bound below `level`; -1 when
// none does below 1e9 runs.
long long runsToShowBelow(int k, int n, double level, double confidence);

}  // namespace c2d
