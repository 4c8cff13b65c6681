#pragma once
// Small text utilities shared by the io sources (private to the module).

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace dynpos::io::detail {

/// `text` without leading and trailing spaces, tabs and carriage returns.
inline std::string_view trim(std::string_view text) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  if (!text.empty() && !space(text.front()) && !space(text.back())) return text;  // the usual
  constexpr std::string_view kSpace = " \t\r\n";
  const auto first = text.find_first_not_of(kSpace);
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(kSpace);
  return text.substr(first, last - first + 1);
}

/// Levenshtein distance, case-insensitive (so "hdg" is close to "HDG").
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  const auto lower = [](char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  };
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// The candidate closest to `name`, or empty when even the best needs more edits than about a
/// third of the longer string (then a suggestion would only confuse).
inline std::string closest_match(std::string_view name,
                                 const std::vector<std::string>& candidates) {
  // The distance is at least the difference of the lengths: when that alone fails the test
  // below for every candidate, nothing is suggested, and a long name (a 16 KiB cell) costs no
  // distance at all; a candidate that cannot beat the best so far is skipped. Both are exact.
  const auto length_gap = [&name](const std::string& c) {
    return name.size() > c.size() ? name.size() - c.size() : c.size() - name.size();
  };
  const bool any_can_pass = std::any_of(candidates.begin(), candidates.end(), [&](const auto& c) {
    return length_gap(c) * 3 <= std::max(name.size(), c.size()) + 2;
  });
  if (!any_can_pass) return {};
  std::string best;
  std::size_t best_distance = 0;
  for (const auto& candidate : candidates) {
    if (!best.empty() && length_gap(candidate) >= best_distance) continue;
    const std::size_t d = edit_distance(name, candidate);
    if (best.empty() || d < best_distance) {
      best = candidate;
      best_distance = d;
    }
  }
  const std::size_t longer = std::max(name.size(), best.size());
  if (best.empty() || best_distance * 3 > longer + 2) return {};
  return best;
}

/// "a, b, c".
inline std::string join(const std::vector<std::string>& items, std::string_view separator = ", ") {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += separator;
    out += items[i];
  }
  return out;
}

}  // namespace dynpos::io::detail
