#include "did_you_mean.h"

#include <algorithm>
#include <cctype>

namespace lucent {

size_t editDistance(std::string_view a, std::string_view b) {
  auto lower = [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  };
  // One row of the dynamic programme (Wagner–Fischer).
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t above = row[j];
      size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string closestName(std::string_view word, const std::vector<std::string_view>& candidates) {
  size_t limit = std::min<size_t>(2, (word.size() + 1) / 2);
  size_t best = limit + 1;
  std::string_view bestName;
  for (std::string_view c : candidates) {
    if (c == word) continue;
    size_t d = editDistance(word, c);
    if (d < best) {
      best = d;
      bestName = c;
    }
  }
  return std::string(bestName);
}

std::string didYouMean(std::string_view word, const std::vector<std::string_view>& candidates) {
  std::string best = closestName(word, candidates);
  return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates) {
  std::vector<std::string_view> views(candidates.begin(), candidates.end());
  return didYouMean(word, views);
}

}  // namespace lucent
