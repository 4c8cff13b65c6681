#include "dynpos/ident/channel_integrals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "dynpos/core/error.hpp"

namespace dynpos::ident {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> axis(double t0, double dt, std::size_t n) {
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = t0 + dt * static_cast<double>(i);
  return t;
}

TEST(ChannelIntegral, ConstantThrustGivesThrustTimesDuration) {
  // 20 kN for 300 s is 6000 kNs, whatever the sampling.
  const auto t = axis(0.0, 0.1, 4001);  // 0 … 400 s
  const std::vector<double> x(t.size(), 20e3);
  const ChannelIntegral r = integrate_channel(t, x, 50.0, 350.0);
  ASSERT_TRUE(r.integral);
  EXPECT_NEAR(*r.integral, 20e3 * 300.0, 1e-6);
  EXPECT_NEAR(*r.mean, 20e3, 1e-9);
  EXPECT_NEAR(r.coverage, 1.0, 1e-12);
}

TEST(ChannelIntegral, TrapezoidIsExactForARampAndAbsoluteFoldsTheSign) {
  // x = t − 100 on [0, 200]: ∫x = 0, ∫|x| = 2·½·100² = 10 000 (exact for a piecewise-linear
  // signal sampled at its kinks).
  const auto t = axis(0.0, 1.0, 201);
  std::vector<double> x(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) x[i] = t[i] - 100.0;
  EXPECT_NEAR(*integrate_channel(t, x, 0.0, 200.0).integral, 0.0, 1e-9);
  ChannelIntegralOptions abs;
  abs.absolute = true;
  EXPECT_NEAR(*integrate_channel(t, x, 0.0, 200.0, abs).integral, 10000.0, 1e-9);
}

TEST(ChannelIntegral, SlowChannelOfAMixedRateLogUsesItsOwnSamples) {
  // A 1 Hz channel in a 10 Hz log: blanks between samples are not zeros.
  const auto t = axis(0.0, 0.1, 1001);
  std::vector<double> x(t.size(), kNaN);
  for (std::size_t i = 0; i < t.size(); i += 10) x[i] = 5.0;
  const ChannelIntegral r = integrate_channel(t, x, 0.0, 100.0);
  ASSERT_TRUE(r.integral);
  EXPECT_NEAR(*r.integral, 500.0, 1e-9);
  EXPECT_EQ(r.samples, 101u);
}

TEST(ChannelIntegral, LongGapIsLeftOutAndReported) {
  const auto t = axis(0.0, 1.0, 101);
  std::vector<double> x(t.size(), 2.0);
  for (std::size_t i = 40; i < 60; ++i) x[i] = kNaN;  // 21 s between samples 39 and 60
  ChannelIntegralOptions o;
  o.min_coverage = 0.5;
  const ChannelIntegral r = integrate_channel(t, x, 0.0, 100.0, o);
  EXPECT_NEAR(r.longest_gap_s, 21.0, 1e-12);
  EXPECT_NEAR(r.covered_s, 79.0, 1e-12);
  ASSERT_TRUE(r.integral);
  EXPECT_NEAR(*r.integral, 158.0, 1e-9);
  EXPECT_NEAR(*r.mean, 2.0, 1e-12);
  // With the default 90 % coverage the figure is missing, never a partial sum.
  EXPECT_FALSE(integrate_channel(t, x, 0.0, 100.0).integral);
}

TEST(ChannelIntegral, NoDataIsMissingAndBadWindowIsAnError) {
  const auto t = axis(0.0, 1.0, 11);
  const std::vector<double> x(t.size(), kNaN);
  const ChannelIntegral r = integrate_channel(t, x, 0.0, 10.0);
  EXPECT_FALSE(r.integral);
  EXPECT_FALSE(r.mean);
  EXPECT_EQ(r.samples, 0u);
  EXPECT_THROW(integrate_channel(t, x, 5.0, 5.0), core::InputError);
  EXPECT_THROW(integrate_channel(t, std::vector<double>(3, 1.0), 0.0, 1.0), core::InputError);
}

}  // namespace
}  // namespace dynpos::ident
