#include "series.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dynpos/core/error.hpp"
#include "dynpos/core/few_valued_median.hpp"
#include "dynpos/core/huge_pages.hpp"

namespace dynpos::ident::detail {

void check_time_axis(std::span<const double> t, const std::string& name) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i])) {
      throw core::InputError({"", {}, {}, name}, "time is not finite at index " + std::to_string(i),
                             "remove or fill rows without a time stamp");
    }
    if (i > 0 && !(t[i] > t[i - 1])) {
      throw core::InputError({"", {}, {}, name},
                             "time is not strictly increasing at index " + std::to_string(i),
                             "sort the log by time and drop duplicate rows");
    }
  }
}

void check_same_length(std::size_t n_t, std::size_t n_x, const std::string& name) {
  if (n_t != n_x) {
    throw core::InputError(
        {"", {}, {}, name},
        "has " + std::to_string(n_x) + " samples but the time axis has " + std::to_string(n_t),
        "pass the channel and the time axis of the same log");
  }
}

double median(std::vector<double> values) { return median_in_place(values); }

double median_in_place(std::span<double> values) {
  if (values.empty()) return std::nan("");
  // A piecewise-constant signal's differences take few values: counted, not selected.
  if (const auto counted =
          core::few_valued_median(values.size(), [&](std::size_t i) { return values[i]; })) {
    return *counted;
  }
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

double difference_noise_sigma(std::span<const double> x) {
  // A piecewise-constant series (a command) without gaps: its differences and their deviations
  // take few values, counted as they are formed, with no copy of the series.
  if (x.size() >= 3) {
    const auto diff = [&](std::size_t i) { return x[i + 1] - x[i]; };
    if (const auto m = core::few_valued_median(x.size() - 1, diff)) {
      const auto deviation = [&](std::size_t i) { return std::abs(diff(i) - *m); };
      if (const auto mad = core::few_valued_median(x.size() - 1, deviation)) {
        return 1.4826 * *mad / std::sqrt(2.0);
      }
    }
  }
  std::vector<double> d;
  core::reserve_huge(d, x.size());
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (!std::isnan(x[i]) && !std::isnan(x[i - 1])) d.push_back(x[i] - x[i - 1]);
  }
  if (d.size() < 2) return 0.0;
  const double m = median_in_place(d);  // the order of d does not matter below
  for (double& v : d) v = std::abs(v - m);
  // 1.4826·MAD estimates the standard deviation of Gaussian differences; a difference of
  // two independent samples has √2 times the sample standard deviation.
  return 1.4826 * median_in_place(d) / std::sqrt(2.0);
}

LineFit fit_line(std::span<const double> x, std::span<const double> y) {
  LineFit fit;
  const std::size_t n = x.size();
  if (n == 0) return fit;
  double mx = 0.0;
  double my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxx = 0.0;
  double sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  fit.b = sxx > 0.0 ? sxy / sxx : 0.0;
  fit.a = my - fit.b * mx;
  double sse = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - fit.a - fit.b * x[i];
    sse += r * r;
  }
  fit.residual_sigma = n > 2 ? std::sqrt(sse / static_cast<double>(n - 2)) : 0.0;
  return fit;
}

std::string fmt(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

}  // namespace dynpos::ident::detail
