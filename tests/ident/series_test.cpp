// The medians of ident/series.hpp: exact order statistics, whichever way they are found (counted
// for few distinct values, bracketed by a sample for a long series, selected otherwise), against
// a full sort.

#include "series.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace dynpos::ident::detail {
namespace {

double sorted_median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t mid = v.size() / 2;
  return v.size() % 2 == 1 ? v[mid] : 0.5 * (v[mid - 1] + v[mid]);
}

TEST(Median, ExactForLongNoisySeriesWithOutliersAndPatterns) {
  std::mt19937_64 engine(5);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (std::size_t n : {1u, 2u, 999u, 16'383u, 16'384u, 16'385u, 30'000u, 30'001u, 250'000u}) {
    std::vector<double> v(n);
    for (double& x : v) x = noise(engine);
    for (std::size_t i = 0; i < n; i += 97) v[i] = 5.0 + static_cast<double>(i % 3);  // outliers
    EXPECT_EQ(median(v), sorted_median(v)) << "noise, n = " << n;
    std::vector<double> ramp(n);  // sorted: every strided sample is of one end
    for (std::size_t i = 0; i < n; ++i) ramp[i] = std::sqrt(static_cast<double>(i));
    EXPECT_EQ(median(ramp), sorted_median(ramp)) << "ramp, n = " << n;
    std::vector<double> saw(n);  // a period of the sample's stride: a sample unlike the series
    for (std::size_t i = 0; i < n; ++i) saw[i] = static_cast<double>(i % 1024) + 1e-6 * i;
    EXPECT_EQ(median(saw), sorted_median(saw)) << "saw, n = " << n;
  }
}

TEST(Median, AZeroMedianIsPlusZeroWhateverTheSignsOfTheZeros) {
  for (std::size_t n : {5u, 1001u, 40'001u}) {
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) {
      v[i] = i % 3 == 0 ? -0.0 : (i % 3 == 1 ? 0.0 : (i % 2 == 0 ? 1.0 : -1.0) * (1.0 + i));
    }
    const double m = median(v);
    EXPECT_EQ(m, 0.0) << n;
    EXPECT_FALSE(std::signbit(m)) << n;
  }
}

TEST(Median, DifferenceNoiseOfAWhiteSeries) {
  std::mt19937_64 engine(9);
  std::normal_distribution<double> noise(0.0, 0.2);
  std::vector<double> x(200'000);
  for (double& v : x) v = 3.0 + noise(engine);
  // σ̂ of the differences' MAD: within 1 % of σ for 200 000 samples (its relative standard
  // error is about 1.67/√n ≈ 0.4 %).
  EXPECT_NEAR(difference_noise_sigma(x), 0.2, 0.002);
}

}  // namespace
}  // namespace dynpos::ident::detail
