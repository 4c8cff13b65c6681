#include "dynpos/core/time_spacing.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "dynpos/core/few_valued_median.hpp"

namespace dynpos::core {

double median_spacing_s(const std::vector<double>& time_s, unsigned jobs) {
  if (time_s.size() < 2) throw std::invalid_argument("median_spacing_s: fewer than two times");
  // A regular axis has few distinct spacings: counted in one pass, no copy.
  const auto spacing = [&](std::size_t i) { return time_s[i + 1] - time_s[i]; };
  if (const auto counted = few_values(time_s.size() - 1, jobs, spacing)) return counted->median();
  std::vector<double> dt;
  dt.reserve(time_s.size() - 1);
  for (std::size_t i = 0; i + 1 < time_s.size(); ++i) dt.push_back(time_s[i + 1] - time_s[i]);
  const std::size_t mid = dt.size() / 2;
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(mid), dt.end());
  const double upper = dt[mid];
  if (dt.size() % 2 == 1) return upper;
  // After nth_element the lower middle is the largest element before `mid`.
  const double lower = *std::max_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

}  // namespace dynpos::core
