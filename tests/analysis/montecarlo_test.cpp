// Monte Carlo over seeds (analysis/montecarlo.hpp): the summary's statistics by hand, the same
// document for any number of jobs and for shards merged, and the checks on ranges and shards.

#include "dynpos/analysis/montecarlo.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "dynpos/core/error.hpp"
#include "dynpos/io/json_writer.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using ::testing::HasSubstr;

MonteCarloSample sample(std::uint64_t seed, double value, std::optional<double> truth) {
  MonteCarloSample s;
  s.seed = seed;
  s.values["T_s"] = value;
  if (truth) s.truth["T_s"] = *truth;
  return s;
}

TEST(MonteCarlo, SummaryStatisticsByHand) {
  // Values 1, 2, 4 against a truth of 2: mean 7/3, sample std √(7/3), bias 1/3,
  // rms error √((1 + 0 + 4)/3).
  const auto summary = summarise({sample(1, 1.0, 2.0), sample(2, 2.0, 2.0), sample(3, 4.0, 2.0)});
  const MonteCarloStats& s = summary.at("T_s");
  EXPECT_EQ(s.n, 3u);
  EXPECT_DOUBLE_EQ(s.mean, 7.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(7.0 / 3.0));
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(*s.truth, 2.0);
  EXPECT_DOUBLE_EQ(*s.bias, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(*s.rms_error, std::sqrt(5.0 / 3.0));
  // A truth missing for one seed: no bias rather than a bias of some seeds only.
  const auto partial = summarise({sample(1, 1.0, 2.0), sample(2, 3.0, std::nullopt)});
  EXPECT_FALSE(partial.at("T_s").bias);
  EXPECT_DOUBLE_EQ(partial.at("T_s").std, std::sqrt(2.0));
}

TEST(MonteCarlo, SeedRangesAndShards) {
  MonteCarloRequest q;
  q.scenario = "turning-circle";
  q.seeds = parse_seed_range("10..19");
  EXPECT_EQ(q.seeds.first, 10u);
  EXPECT_EQ(q.seeds.last, 19u);
  q.shard = parse_shard("3/4");
  EXPECT_EQ(q.shard.index, 3u);
  EXPECT_EQ(q.shard.count, 4u);
  EXPECT_EQ(q.shard_seeds(), (std::pair<std::uint64_t, std::uint64_t>{15, 16}));
  // The shards tile the range: 10 seeds in 4 shards of 2, 3, 2, 3.
  std::uint64_t next = 10;
  for (std::size_t i = 1; i <= 4; ++i) {
    q.shard.index = i;
    const auto [first, last] = q.shard_seeds();
    EXPECT_EQ(first, next);
    next = last + 1;
  }
  EXPECT_EQ(next, 20u);
  q.seeds = parse_seed_range("18446744073709551615");
  EXPECT_EQ(q.seeds.first, q.seeds.last);
  // Text errors name the request key; the range rules are validate()'s.
  EXPECT_EQ(testing::option_key_of([] { parse_seed_range("5..-1"); }), "seeds");
  EXPECT_EQ(testing::option_key_of([] { parse_seed_range("a..b"); }), "seeds");
  EXPECT_EQ(testing::option_key_of([] { parse_shard("0"); }), "shard");
  q.seeds = {5, 4};
  EXPECT_EQ(testing::option_key_of([&] { q.validate(); }), "seeds");
  q.seeds = {1, 2};
  q.shard = {5, 4};
  EXPECT_EQ(testing::option_key_of([&] { q.validate(); }), "shard");
  q.shard = {};
  EXPECT_EQ(testing::option_key_of([&] { q.validate(); }), "no error");
  EXPECT_EQ(testing::option_key_of([] { montecarlo_measure_from_string("everything"); }),
            "measure");
  EXPECT_EQ(montecarlo_measure_from_string("station-keeping"), MonteCarloMeasure::kStationKeeping);
  EXPECT_EQ(to_string(MonteCarloMeasure::kLeverArms), "lever-arms");
}

class MonteCarloRuns : public ::testing::Test {
 protected:
  static std::string run(unsigned jobs, std::size_t shard, std::size_t shards) {
    MonteCarloRequest q;
    q.scenario = "turning-circle";
    q.seeds = {1, 3};
    q.jobs = jobs;
    q.shard = {shard, shards};
    return io::json_text(to_json(run_montecarlo(q)));
  }
};

TEST_F(MonteCarloRuns, TheSameDocumentForAnyJobsAndForShardsMerged) {
  const std::string one = run(1, 1, 1);
  EXPECT_EQ(run(3, 1, 1), one);
  const auto dir = std::filesystem::temp_directory_path() / "dynpos-montecarlo-test";
  std::filesystem::create_directories(dir);
  std::vector<std::filesystem::path> files;
  for (std::size_t i = 1; i <= 2; ++i) {
    files.push_back(dir / ("shard" + std::to_string(i) + ".json"));
    std::ofstream(files.back()) << run(2, i, 2);
  }
  EXPECT_EQ(io::json_text(to_json(merge_montecarlo({files[1], files[0]}))), one);
  // Shard 1/2 of seeds 1..3 is seed 1 alone. A shard missing, or given twice, is an error.
  try {
    merge_montecarlo({files[0]});
    FAIL() << "expected core::InputError";
  } catch (const core::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("2 of the 3 seeds are missing, the first 2"));
  }
  try {
    merge_montecarlo({files[0], files[0]});
    FAIL() << "expected core::InputError";
  } catch (const core::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("is in more than one shard"));
  }
  std::filesystem::remove_all(dir);
  // The lever arms of the turning circle against truth: the thesis method with the logger's 1 Hz
  // speed log is off by centimetres to decimetres (docs/theory.md), never by metres.
  const nlohmann::json doc = nlohmann::json::parse(one);
  ASSERT_TRUE(doc["summary"].contains("gnss1.x_m"));
  for (const auto& [key, stats] : doc["summary"].items()) {
    EXPECT_EQ(stats["n"], 3) << key;
    EXPECT_LT(std::abs(stats["bias"].get<double>()), 0.3) << key;
  }
}

}  // namespace
}  // namespace dynpos::analysis
