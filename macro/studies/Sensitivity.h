#pragma once
// [ext] Which input matters: per plan of an ensemble, Spearman's rank
// correlation of every drawn value (the named parameters, dt_factor,
// blast_1, ...) with each debris figure over the plan's runs with debris.
// <stem>_sensitivity.csv, one row per plan and drawn value:
//   plan,<swept values...>,input,left,right,left95,right95,centroid,height,outside_mass
// (empty where a correlation is undefined: fewer than 3 runs or a constant
// side). With n runs, |rho| above about 2/sqrt(n) stands out of the noise of
// unrelated values (the 95 % band of rho under independence).
#include <string>

#include "macro/studies/EnsembleTable.h"

namespace c2d {

std::string sensitivityCsv(const EnsembleData& data);
// The log's lines: per plan, the drawn values ordered by their strongest
// correlation.
std::string sensitivityText(const EnsembleData& data);

}  // namespace c2d
