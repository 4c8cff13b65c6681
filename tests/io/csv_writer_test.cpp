#include "dynpos/io/csv_writer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "dynpos/io/csv_reader.hpp"
#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using testing::TempDir;

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CsvWriter, WritesHeaderWithUnitsAndBlankMissingCells) {
  TempDir dir;
  core::Log log({0.0, 0.1, 1.5});
  log.add_channel("north", "m", {1.0, core::kMissing, -2.5});
  log.add_channel("heading", "rad", {0.1, 0.2, 1e-07});
  log.add_channel("count, total", "", {1.0, 2.0, 3.0});
  write_csv(dir / "log.csv", log);
  EXPECT_EQ(contents(dir / "log.csv"),
            "time [s],north [m],heading [rad],\"count, total\"\n"
            "0,1,0.1,1\n"
            "0.1,,0.2,2\n"
            "1.5,-2.5,1e-07,3\n");
}

// Doubles of every kind the writer must reproduce bit for bit.
std::vector<double> awkward_values(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::vector<double> fixed = {0.0,
                               -0.0,
                               0.1,
                               1.0 / 3.0,
                               -2.0 / 3.0,
                               1e300,
                               -1e-300,
                               std::numeric_limits<double>::denorm_min(),
                               std::numeric_limits<double>::max(),
                               std::numeric_limits<double>::lowest(),
                               std::numeric_limits<double>::epsilon(),
                               core::kMissing,
                               123456789.123456789};
  std::vector<double> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (i < fixed.size()) {
      out.push_back(fixed[i]);
    } else {
      // Random bit patterns cover every exponent; NaN and infinity patterns become missing.
      double v = std::bit_cast<double>(engine());
      if (!std::isfinite(v)) v = core::kMissing;
      out.push_back(v);
    }
  }
  return out;
}

bool same_bits(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(CsvWriter, WriteThenReadIsExact) {
  TempDir dir;
  constexpr std::size_t kRows = 2000;
  std::vector<double> time(kRows);
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> step(1e-6, 0.3);
  double t = -12.345;
  for (auto& v : time) {
    v = t;
    t += step(engine);
  }
  core::Log log(time);
  log.add_channel("north", "m", awkward_values(kRows, 1));
  log.add_channel("command.port", "1", awkward_values(kRows, 2), core::Interp::kHold);
  log.add_channel("raw", "", awkward_values(kRows, 3));
  write_csv(dir / "log.csv", log);

  const core::Log back = read_csv_all(dir / "log.csv");
  ASSERT_EQ(back.size(), log.size());
  for (std::size_t i = 0; i < kRows; ++i) ASSERT_TRUE(same_bits(back.time()[i], time[i])) << i;
  ASSERT_EQ(back.channel_names(), log.channel_names());
  for (const auto& channel : log.channels()) {
    const auto& read = back.channel(channel.name);
    EXPECT_EQ(read.unit, channel.unit);
    EXPECT_EQ(read.interp, channel.interp);
    for (std::size_t i = 0; i < kRows; ++i) {
      ASSERT_TRUE(same_bits(read.values[i], channel.values[i]))
          << channel.name << " row " << i << ": " << channel.values[i] << " read "
          << read.values[i];
    }
  }

  // Writing what was read gives the same bytes.
  write_csv(dir / "again.csv", back);
  EXPECT_EQ(contents(dir / "again.csv"), contents(dir / "log.csv"));
}

TEST(CsvRowWriter, StreamsRowsAndCommits) {
  TempDir dir;
  {
    CsvRowWriter writer(dir / "sim.csv", {{"north", "m"}, {"rpm.port", "rps"}});
    for (int i = 0; i < 100'000; ++i) {
      const double row[] = {i * 0.25, -i * 0.5};
      writer.write_row(i * 0.01, row);
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "sim.csv"));
    writer.commit();
    EXPECT_EQ(writer.rows(), 100'000u);
  }
  const core::Log log = read_csv_all(dir / "sim.csv");
  ASSERT_EQ(log.size(), 100'000u);
  EXPECT_EQ(log.time()[12345], 123.45);
  EXPECT_EQ(log.values("north")[99'999], 99'999 * 0.25);
  EXPECT_EQ(log.values("rpm.port")[4], -2.0);
  EXPECT_EQ(log.channel("rpm.port").unit, "rps");
}

TEST(CsvRowWriter, RejectsBadRowsAndLeavesNoFileWithoutCommit) {
  TempDir dir;
  {
    CsvRowWriter writer(dir / "sim.csv", {{"x", "m"}});
    const double one[] = {1.0};
    const double two[] = {1.0, 2.0};
    writer.write_row(0.0, one);
    EXPECT_THROW(writer.write_row(1.0, two), std::invalid_argument);
    EXPECT_THROW(writer.write_row(0.0, one), std::invalid_argument);
    EXPECT_THROW(writer.write_row(-1.0, one), std::invalid_argument);
    EXPECT_THROW(writer.write_row(std::numeric_limits<double>::quiet_NaN(), one),
                 std::invalid_argument);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(CsvWriter, HeaderText) {
  EXPECT_EQ(csv_column_header("heading", "rad"), "heading [rad]");
  EXPECT_EQ(csv_column_header("flag", ""), "flag");
  EXPECT_EQ(csv_column_header("say \"hi\"", "1"), "\"say \"\"hi\"\" [1]\"");
}

}  // namespace
}  // namespace dynpos::io
