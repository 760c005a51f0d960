#pragma once
// "Did you mean" hints: the candidate nearest to a misspelt word.
#include <string>
#include <string_view>
#include <vector>

namespace c2d {

// Edit distance (insert, delete, substitute, swap of neighbours), case-insensitive.
int editDistance(std::string_view a, std::string_view b);

// The candidate nearest to word (at most about a third of its letters wrong), or "".
std::string nearestWord(std::string_view word, const std::vector<std::string>& candidates);

// "did you mean 'x'?" for the nearest candidate, or "".
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace c2d
