#pragma once
// [ext] Which input matters: per plan of an ensemble, Spearman's rank
// correlation of every drawn value (the named parameters, dt_factor,
// blast_1, ...) with each debris figure over the plan's runs with debris, its
// two-sided p-value under independence (MultipleTests.h) and Holm's
// correction over the plan's tests. The time-step jitter (dt_factor) is
// numerical scatter, no input of the plan: its tests are a family of their
// own and listed apart. The nodes' jitter has no single value to correlate.
// <stem>_sensitivity.csv, one row per plan, drawn value and figure:
//   plan,[name,]<swept values...>,input,kind,figure,runs,rho,p,p_holm,mark
// kind "input" or "numerical scatter"; runs: the pairs; rho, p, p_holm empty
// where a correlation is undefined (fewer than 3 runs, a constant side);
// mark "*" where p_holm < 0.05.
#include <string>

#include "macro/studies/EnsembleTable.h"

namespace c2d {

// The level at which an adjusted p-value stands out.
constexpr double kSensitivityLevel = 0.05;
// Whether a drawn value is the numerical jitter rather than an input of the plan.
bool isNumericalScatter(const std::string& input);

std::string sensitivityCsv(const EnsembleData& data);
// The log's lines: per plan, the drawn values ordered by their strongest
// correlation.
std::string sensitivityText(const EnsembleData& data);

}  // namespace c2d
