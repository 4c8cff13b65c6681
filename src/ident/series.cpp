#include "series.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>

#include "dynpos/core/error.hpp"
#include "dynpos/core/few_valued_median.hpp"
#include "dynpos/core/time_order.hpp"

namespace dynpos::ident::detail {

void check_time_axis(std::span<const double> t, const std::string& name, unsigned jobs) {
  const std::size_t i = core::first_unordered_time(t, jobs);
  if (i == t.size()) return;
  if (!std::isfinite(t[i])) {
    throw core::InputError({"", {}, {}, name}, "time is not finite at index " + std::to_string(i),
                           "remove or fill rows without a time stamp");
  }
  throw core::InputError({"", {}, {}, name},
                         "time is not strictly increasing at index " + std::to_string(i),
                         "sort the log by time and drop duplicate rows");
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

namespace {

// The mean of the values of ranks r0 and r1 = r0 or r0 + 1 of a long series, exactly, with one
// pass over it: two order statistics of a strided sample bracket them (Floyd and Rivest's
// idea), and only the values between those are selected from. nullopt when the bracket misses
// (a sample unlike the series), a NaN, or a short series: then select from all.
std::optional<double> bracketed_ranks(std::span<const double> values, std::size_t r0,
                                      std::size_t r1) {
  constexpr std::size_t kSample = 1024;
  constexpr std::size_t kMargin = 64;  // 4σ of a sample rank near the median (σ ≈ √(1024/4))
  const std::size_t n = values.size();
  if (n < 16 * kSample) return std::nullopt;
  std::array<double, kSample> sample{};
  const std::size_t stride = n / kSample;
  for (std::size_t k = 0; k < kSample; ++k) sample[k] = values[k * stride];
  if (std::any_of(sample.begin(), sample.end(), [](double x) { return std::isnan(x); })) {
    return std::nullopt;
  }
  // The sample's order statistics centre ∓ kMargin, each selected (not the whole sample sorted).
  const std::size_t centre = r0 / stride;
  const double inf = std::numeric_limits<double>::infinity();
  double lo = -inf;
  double hi = inf;
  auto rest = sample.begin();
  if (centre >= kMargin) {
    rest = sample.begin() + static_cast<std::ptrdiff_t>(centre - kMargin);
    std::nth_element(sample.begin(), rest, sample.end());
    lo = *rest;
  }
  if (centre + kMargin < kSample) {
    const auto at = sample.begin() + static_cast<std::ptrdiff_t>(centre + kMargin);
    std::nth_element(rest, at, sample.end());
    hi = *at;
  }
  // Without branches: a value far from the median is as likely below as above it.
  std::size_t below = 0;
  std::size_t above = 0;
  std::size_t kept = 0;
  // Room for a quarter of the values (about an eighth fall between the bounds), checked a chunk
  // at a time: a bracket holding more is given up.
  constexpr std::size_t kChunk = 4096;
  const std::size_t room = n / 4;
  const auto buffer = std::make_unique_for_overwrite<double[]>(room + kChunk);
  for (std::size_t begin = 0; begin < n; begin += kChunk) {
    if (kept > room) return std::nullopt;
    const std::size_t end = std::min(n, begin + kChunk);
    for (std::size_t i = begin; i < end; ++i) {
      const double x = values[i];
      below += static_cast<std::size_t>(x < lo);
      above += static_cast<std::size_t>(x > hi);
      buffer[kept] = x;
      kept += static_cast<std::size_t>((x >= lo) & (x <= hi));
    }
  }
  if (below + above + kept != n || below > r0 || below + kept <= r1) {
    return std::nullopt;  // a NaN, or the ranks outside the bracket
  }
  const std::span<double> between(buffer.get(), kept);
  const auto k1 = static_cast<std::ptrdiff_t>(r1 - below);
  std::nth_element(between.begin(), between.begin() + k1, between.end());
  const double upper = between[static_cast<std::size_t>(k1)];
  if (r0 == r1) return upper;
  return 0.5 * (*std::max_element(between.begin(), between.begin() + k1) + upper);
}

double selected_median(std::span<double> values) {
  // A piecewise-constant signal's differences take few values: counted, not selected.
  if (const auto counted =
          core::few_valued_median(values.size(), [&](std::size_t i) { return values[i]; })) {
    return *counted;
  }
  const std::size_t mid = values.size() / 2;
  if (const auto bracketed = bracketed_ranks(values, values.size() % 2 == 1 ? mid : mid - 1, mid)) {
    return *bracketed;
  }
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

}  // namespace

double median_in_place(std::span<double> values) {
  if (values.empty()) return std::nan("");
  const double m = selected_median(values);
  // −0 and +0 are one value to a selection, which may give either: always +0.
  return m == 0.0 ? 0.0 : m;
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
  d.reserve(x.size());
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

double time_rounding_slack_s(double t_a, double t_b) {
  return 16.0 * std::numeric_limits<double>::epsilon() *
         std::max({1.0, std::abs(t_a), std::abs(t_b)});
}

}  // namespace dynpos::ident::detail
