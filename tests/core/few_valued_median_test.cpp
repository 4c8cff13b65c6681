// core::few_valued_median: the exact median of a series with few distinct values, against
// selection (nth_element) on the same values.

#include "dynpos/core/few_valued_median.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <vector>

namespace dynpos::core {
namespace {

double selected_median(std::vector<double> v) {
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
  const double upper = v[mid];
  if (v.size() % 2 == 1) return upper;
  return 0.5 * (*std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid)) + upper);
}

std::optional<double> counted(const std::vector<double>& v) {
  return few_valued_median(v.size(), [&](std::size_t i) { return v[i]; });
}

TEST(FewValuedMedian, EqualsSelectionForOddAndEvenCounts) {
  std::mt19937_64 engine(7);
  std::uniform_int_distribution<int> pick(0, 40);
  for (std::size_t n : {1u, 2u, 3u, 10u, 11u, 1000u, 1001u}) {
    std::vector<double> v(n);
    for (double& x : v) x = 0.01 * pick(engine) - 0.2;  // 41 distinct values, some negative
    ASSERT_TRUE(counted(v)) << n;
    EXPECT_EQ(*counted(v), selected_median(v)) << n;
  }
  // The spacings of a logged 100 Hz axis, t printed with two decimals and read back.
  std::vector<double> t(100'001), dt;
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = std::stod(std::to_string(0.01 * k));
  for (std::size_t k = 1; k < t.size(); ++k) dt.push_back(t[k] - t[k - 1]);
  ASSERT_TRUE(counted(dt));
  EXPECT_EQ(*counted(dt), selected_median(dt));
}

TEST(FewValuedMedian, DeclinesManyValuesNaNAndEmpty) {
  std::vector<double> many(1000);
  for (std::size_t i = 0; i < many.size(); ++i) many[i] = std::sqrt(static_cast<double>(i));
  EXPECT_FALSE(counted(many));
  EXPECT_FALSE(counted({1.0, std::nan(""), 1.0}));
  EXPECT_FALSE(counted({}));
}

}  // namespace
}  // namespace dynpos::core

namespace dynpos::core {
namespace {

TEST(FewValues, SortedDistinctValuesWithTheirCounts) {
  const std::vector<double> v = {0.0, 4.0, 0.0, -1.0, 0.0, 4.0, 0.0};
  const auto few = few_values(v.size(), [&](std::size_t i) { return v[i]; });
  ASSERT_TRUE(few.has_value());
  ASSERT_EQ(few->distinct, 3u);
  EXPECT_EQ(few->n, 7u);
  EXPECT_EQ(few->counts[0], (std::pair<double, std::size_t>{-1.0, 1}));
  EXPECT_EQ(few->counts[1], (std::pair<double, std::size_t>{0.0, 4}));
  EXPECT_EQ(few->counts[2], (std::pair<double, std::size_t>{4.0, 2}));
  std::vector<double> sorted = v;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t rank = 0; rank < v.size(); ++rank) EXPECT_EQ(few->at_rank(rank), sorted[rank]);
}

}  // namespace
}  // namespace dynpos::core

namespace dynpos::core {
namespace {

// The table that finds a value holds up to kMaxDistinct of them, in any order of arrival, and
// tells values apart as == does: +0 and −0 are one value.
TEST(FewValues, UpToTheLimitInAnyOrderAndSignedZerosAsOne) {
  std::mt19937_64 engine(11);
  std::vector<double> v;
  for (std::size_t k = 0; k < FewValues::kMaxDistinct; ++k) {
    for (std::size_t r = 0; r <= k % 5; ++r) v.push_back(1e-3 * static_cast<double>(k * k) - 1.0);
  }
  std::shuffle(v.begin(), v.end(), engine);
  const auto few = few_values(v.size(), [&](std::size_t i) { return v[i]; });
  ASSERT_TRUE(few.has_value());
  EXPECT_EQ(few->distinct, FewValues::kMaxDistinct);
  std::vector<double> sorted = v;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t rank = 0; rank < v.size(); ++rank) EXPECT_EQ(few->at_rank(rank), sorted[rank]);
  v.push_back(12345.0);  // one value more than the table holds
  EXPECT_FALSE(few_values(v.size(), [&](std::size_t i) { return v[i]; }));

  const std::vector<double> zeros = {-0.0, 1.0, 0.0, -0.0, 0.0, 2.0};
  const auto z = few_values(zeros.size(), [&](std::size_t i) { return zeros[i]; });
  ASSERT_TRUE(z.has_value());
  ASSERT_EQ(z->distinct, 3u);
  EXPECT_EQ(z->counts[0].second, 4u);
  EXPECT_TRUE(std::signbit(z->counts[0].first));  // kept as first seen
}

// The two values seen last are counted apart from the table: a series that switches between two
// values at random, with runs, returns to older values and new ones in between, gets the counts a
// plain tally gives.
TEST(FewValues, SwitchingValuesAreCountedAsATallyCountsThem) {
  std::mt19937_64 engine(23);
  std::uniform_int_distribution<int> move(0, 9);
  std::uniform_int_distribution<int> any(0, 29);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> v = {0.5};
    double before = -1.5;
    for (int i = 0; i < 5000; ++i) {
      const int m = move(engine);
      double next = v.back();                        // a run
      if (m < 4) next = before;                      // back to the one before
      if (m == 9) next = 0.125 * any(engine) - 2.0;  // any value, seen or new
      if (next != v.back()) before = v.back();
      v.push_back(next == 0.0 && i % 2 == 0 ? -0.0 : next);
    }
    std::map<double, std::size_t> tally;  // keys compare as == does: +0 and −0 are one
    for (double x : v) ++tally[x];
    const auto few = few_values(v.size(), [&](std::size_t i) { return v[i]; });
    ASSERT_TRUE(few.has_value()) << trial;
    ASSERT_EQ(few->distinct, tally.size()) << trial;
    std::size_t k = 0;
    for (const auto& [value, count] : tally) {
      EXPECT_EQ(few->counts[k].first, value) << trial;
      EXPECT_EQ(few->counts[k].second, count) << trial << " value " << value;
      ++k;
    }
  }
}

// Counted in pieces on several threads and joined, a series gives what it gives counted whole:
// the same values, counts and zero sign, and no answer when the pieces hold too many values
// together or one holds a NaN.
TEST(FewValues, CountedInPiecesAsWhole) {
  const std::size_t n = 2 * (std::size_t{1} << 18) + 3;
  std::mt19937_64 engine(5);
  std::uniform_int_distribution<int> pick(-20, 20);
  std::vector<double> v(n);
  for (double& x : v) x = 0.25 * pick(engine);
  v[n - 1] = -0.0;  // the last piece's zero comes after the first piece's +0
  const auto whole = few_values(n, [&](std::size_t i) { return v[i]; });
  ASSERT_TRUE(whole.has_value());
  for (unsigned jobs : {1u, 2u, 3u, 0u}) {
    const auto pieces = few_values(n, jobs, [&](std::size_t i) { return v[i]; });
    ASSERT_TRUE(pieces.has_value()) << jobs;
    ASSERT_EQ(pieces->distinct, whole->distinct);
    EXPECT_EQ(pieces->n, n);
    for (std::size_t k = 0; k < whole->distinct; ++k) {
      EXPECT_EQ(pieces->counts[k].second, whole->counts[k].second) << k;
      EXPECT_EQ(std::signbit(pieces->counts[k].first), std::signbit(whole->counts[k].first));
      EXPECT_EQ(pieces->counts[k].first, whole->counts[k].first);
    }
    EXPECT_EQ(pieces->median(), whole->median());
  }
  std::vector<double> halves(n);  // 40 values in the first half, 40 others in the second
  for (std::size_t i = 0; i < n; ++i) halves[i] = static_cast<double>(i % 40 + (2 * i / n) * 40);
  EXPECT_TRUE(few_values(n / 2, 2, [&](std::size_t i) { return halves[i]; }));
  EXPECT_FALSE(few_values(n, 2, [&](std::size_t i) { return halves[i]; }));
  v[n - 2] = std::nan("");
  EXPECT_FALSE(few_values(n, 3, [&](std::size_t i) { return v[i]; }));
}

// The counts of f(v) from the counts of v are those of the series f(v): values f maps together
// are merged, and a NaN result gives no counts.
TEST(FewValues, MappedCountsAreTheCountsOfTheMappedSeries) {
  std::mt19937_64 engine(9);
  std::uniform_int_distribution<int> pick(-12, 12);
  std::vector<double> v(5001);
  for (double& x : v) x = 0.1 * pick(engine);
  const auto few = few_values(v.size(), [&](std::size_t i) { return v[i]; });
  ASSERT_TRUE(few.has_value());
  const double m = few->median();
  const auto check = [&](auto f) {
    const auto mapped = few->mapped(f);
    const auto direct = few_values(v.size(), [&](std::size_t i) { return f(v[i]); });
    ASSERT_TRUE(mapped && direct);
    ASSERT_EQ(mapped->distinct, direct->distinct);
    for (std::size_t k = 0; k < direct->distinct; ++k)
      EXPECT_EQ(mapped->counts[k], direct->counts[k]);
    EXPECT_EQ(mapped->median(), direct->median());
  };
  check([](double x) { return x * x; });
  check([m](double x) { return std::abs(x - m); });
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(few->mapped([inf](double x) { return x * 0.0 * inf; }));
}

}  // namespace
}  // namespace dynpos::core
