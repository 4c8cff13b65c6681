#pragma once
// Synthetic step-test data for the ident tests: time axes with jitter and gaps, seeded noise.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace dynpos::ident::testing {

// Expects `statement` to throw `Exception` whose what() matches the regular expression.
#define EXPECT_THROW_MATCHING(statement, Exception, regex)                     \
  EXPECT_THROW(                                                                \
      {                                                                        \
        try {                                                                  \
          statement;                                                           \
        } catch (const Exception& e) {                                         \
          EXPECT_THAT(std::string(e.what()), ::testing::ContainsRegex(regex)); \
          throw;                                                               \
        }                                                                      \
      },                                                                       \
      Exception)

/// Seeded standard normal samples by Box–Muller on a 64-bit Mersenne twister, so the data are
/// the same with every standard library.
class Normal {
 public:
  explicit Normal(std::uint64_t seed) : engine_(seed) {}
  double operator()() {
    const double u1 = (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53;
    const double u2 = (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  double uniform() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

/// Times t₀ + k·dt for k = 0 … n−1, each moved by up to ±jitter·dt (uniform, seeded).
inline std::vector<double> time_axis(double t0, double dt, std::size_t n, double jitter = 0.0,
                                     std::uint64_t seed = 1) {
  Normal rng(seed);
  std::vector<double> t(n);
  for (std::size_t k = 0; k < n; ++k) {
    t[k] = t0 + dt * static_cast<double>(k) + jitter * dt * (2.0 * rng.uniform() - 1.0);
  }
  return t;
}

/// f(t) at every time plus white Gaussian noise of standard deviation sigma (seeded).
inline std::vector<double> sample(const std::vector<double>& t,
                                  const std::function<double(double)>& f, double sigma = 0.0,
                                  std::uint64_t seed = 2) {
  Normal rng(seed);
  std::vector<double> y(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) y[k] = f(t[k]) + sigma * rng();
  return y;
}

/// Sets the samples with t in [from, to] to NaN (a logging gap).
inline void make_gap(const std::vector<double>& t, std::vector<double>& x, double from, double to) {
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] >= from && t[k] <= to) x[k] = std::nan("");
  }
}

}  // namespace dynpos::ident::testing
