// The plateaus of a step detector's input scanned in pieces, one per thread, and joined: the same
// plateaus as one scan of the whole input, however the pieces' edges fall against steps, holds
// and drifts.

#include "plateaus.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "synthetic.hpp"

namespace dynpos::ident::detail {
namespace {

using testing::sample;
using testing::time_axis;

void expect_same_plateaus(const std::vector<Plateau>& a, const std::vector<Plateau>& b,
                          const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].begin, b[k].begin) << what << " plateau " << k;
    EXPECT_EQ(a[k].end, b[k].end) << what << " plateau " << k;
    EXPECT_EQ(a[k].start_level, b[k].start_level) << what << " plateau " << k;
    EXPECT_EQ(a[k].end_level, b[k].end_level) << what << " plateau " << k;
    EXPECT_EQ(a[k].head_level, b[k].head_level) << what << " plateau " << k;
    EXPECT_EQ(a[k].tail_level, b[k].tail_level) << what << " plateau " << k;
  }
}

// Where a piece starts inside a drift, its own scan starts a plateau at another level than the
// whole scan's, and splits it elsewhere: the join must scan on until both hold the same level.
// A piece inside a noisy hold never meets such a point and is scanned again whole.
TEST(Plateaus, SameOnAnyNumberOfThreads) {
  const std::vector<double> t = time_axis(0.0, 0.01, 400'001, 0.3, 23);  // 4000 s at 100 Hz
  const std::vector<double> u = sample(
      t,
      [](double x) {
        if (x < 300.0) return 0.0;
        if (x < 1500.0) return 0.2 + 4e-5 * (x - 300.0);  // a drift of 0.048 over 1200 s
        if (x < 1510.0) return 0.1;
        if (x < 2600.0) return 0.1 + 0.01 * std::sin(x / 50.0);  // a slow swing
        return 0.4;                                              // a hold of 1400 s
      },
      0.002, 29);
  const double h = 0.01, w = 3.0;
  const std::vector<Plateau> serial = find_plateaus(t, u, h, w, 1);
  ASSERT_GE(serial.size(), 8u);  // the drift and the swing split their plateaus
  for (unsigned jobs : {2u, 3u, 5u, 8u, 16u, 24u}) {
    expect_same_plateaus(serial, find_plateaus(t, u, h, w, jobs), std::to_string(jobs));
  }
}

}  // namespace
}  // namespace dynpos::ident::detail
