// Fixes joined at a log's rows (src/ident/fix_spline.hpp): exact on a line, close on wave motion
// sampled 7 times a period, and gaps longer than asked (dropouts) left missing.

#include "fix_spline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace dynpos::ident::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Rows every 0.1 s for `duration` s; x(t) at the whole seconds, NaN between.
template <class F>
void rows(double duration, F x, std::vector<double>& t, std::vector<double>& v) {
  for (int k = 0; k <= static_cast<int>(std::lround(duration * 10.0)); ++k) {
    t.push_back(0.1 * k);
    v.push_back(k % 10 == 0 ? x(t.back()) : kNaN);
  }
}

TEST(FixSpline, ALineIsJoinedExactly) {
  std::vector<double> t, v;
  rows(
      20.0, [](double s) { return 3.0 - 0.25 * s; }, t, v);
  const std::vector<double> out = fill_between_fixes(t, v, 2.0);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(out[i], 3.0 - 0.25 * t[i], 1e-12);
}

TEST(FixSpline, WaveMotionAtOneHertzIsJoinedWithinAFewThousandths) {
  // 1 m of a 7 s wave: the rows between the fixes within 0.5 % of it (away from the ends,
  // where the natural spline's zero curvature holds), their largest value within 0.5 %.
  const double w = 2.0 * std::numbers::pi / 7.0;
  std::vector<double> t, v;
  rows(
      120.0, [&](double s) { return std::sin(w * s + 0.3); }, t, v);
  const std::vector<double> out = fill_between_fixes(t, v, 2.0);
  double worst = 0.0, top = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < 10.0 || t[i] > 110.0) continue;
    worst = std::max(worst, std::abs(out[i] - std::sin(w * t[i] + 0.3)));
    top = std::max(top, out[i]);
  }
  EXPECT_LT(worst, 0.005);
  EXPECT_NEAR(top, 1.0, 0.005);
}

TEST(FixSpline, DropoutsAndTheEndsStayMissing) {
  std::vector<double> t, v;
  rows(
      20.0, [](double s) { return s * s; }, t, v);
  for (std::size_t i = 50; i < 120; ++i) v[i] = kNaN;  // no fix from 5 s to 11.9 s
  v[0] = kNaN;                                         // the first row has no fix
  const std::vector<double> out = fill_between_fixes(t, v, 2.0);
  EXPECT_TRUE(std::isnan(out[5]));     // before the first fix (1 s)
  EXPECT_TRUE(std::isnan(out[80]));    // in the 8 s dropout
  EXPECT_FALSE(std::isnan(out[135]));  // between the fixes at 13 s and 14 s
  EXPECT_NEAR(out[135], 13.5 * 13.5, 0.05);
  EXPECT_EQ(out[40], 16.0);  // a fix is kept as it is
  // Two fixes alone are joined by a line.
  std::vector<double> t2 = {0.0, 0.5, 1.0}, v2 = {1.0, kNaN, 3.0};
  EXPECT_DOUBLE_EQ(fill_between_fixes(t2, v2, 2.0)[1], 2.0);
  EXPECT_TRUE(std::isnan(fill_between_fixes(t2, v2, 0.5)[1]));
}

}  // namespace
}  // namespace dynpos::ident::detail
