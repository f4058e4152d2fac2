// "Did you mean" hints for misspelled element, attribute, enum, parameter and id names.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace lucent {

// Levenshtein edit distance (insertions, deletions, substitutions), ASCII case-insensitive.
size_t editDistance(std::string_view a, std::string_view b);

// The closest candidate within a small edit distance (at most 2, and at most half the
// word's length rounded up, so short words do not match everything), or "" if none is close.
std::string closestName(std::string_view word, const std::vector<std::string_view>& candidates);

// " (did you mean 'x'?)" or "".
std::string didYouMean(std::string_view word, const std::vector<std::string_view>& candidates);
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace lucent
