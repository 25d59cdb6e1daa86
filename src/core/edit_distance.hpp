// The Levenshtein distance between two words (insertions, deletions and substitutions, each 1),
// and the nearest of a list: for "did you mean" in the messages of an unknown command or key.
#pragma once

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

namespace rollnoise {

inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// The word of `words` nearest to `given`, if it is near enough to be a typing slip (at most
/// max(2, a third of its length) edits); empty otherwise.
inline std::string nearest_word(const std::string& given, const std::vector<std::string>& words) {
  const std::string* best = nullptr;
  std::size_t best_distance = 0;
  for (const auto& w : words) {
    const std::size_t d = edit_distance(given, w);
    if (!best || d < best_distance) best = &w, best_distance = d;
  }
  return best && best_distance <= std::max<std::size_t>(2, best->size() / 3) ? *best : std::string();
}

}  // namespace rollnoise
