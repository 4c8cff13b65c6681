// ROS 2 bags (MCAP) as logs: the same roles, and the same results, as a CSV of the same data.

#include <fmt/core.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../io/io_test_util.hpp"
#include "../io/mcap_test_writer.hpp"
#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/step.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::analysis {
namespace {

using io::testing::caught_input_error;
using io::testing::CdrWriter;
using io::testing::McapLayout;
using io::testing::McapWriter;
using io::testing::TempDir;
using ::testing::HasSubstr;

constexpr std::int64_t kStart = 1'714'557'600'000'000'000LL;  // 2024-05-01T10:00:00Z
const std::string kFeedbackMsg = "std_msgs/Header header\nfloat64 rpm\nfloat64[3] extra\n" +
                                 std::string(io::testing::kHeaderDeps);

// The step test's first-order response with dead time: input 0 → 1 at 10 s, → 0.5 at 40 s.
double response(double t) {
  const auto step = [](double t, double t_step, double du) {
    const double s = t - t_step - 1.0;
    return s > 0.0 ? 2.0 * du * (1.0 - std::exp(-s / 3.0)) : 0.0;
  };
  return step(t, 10.0, 1.0) + step(t, 40.0, -0.5);
}
double command(double t) { return t < 10.0 ? 0.0 : (t < 40.0 ? 1.0 : 0.5); }

// /cmd (Float64, receive time) and /feedback (header.stamp, received 7 ms later) at 10 Hz; with
// `slow`, /feedback at 2 Hz from 0.05 s.
std::filesystem::path write_bag(const TempDir& dir, const std::string& name, McapLayout layout,
                                bool slow = false) {
  McapWriter w(std::move(layout));
  const std::uint16_t cmd = w.channel(w.schema("std_msgs/msg/Float64", "float64 data\n"), "/cmd");
  const std::uint16_t fb = w.channel(w.schema("test_msgs/msg/Feedback", kFeedbackMsg), "/feedback");
  for (int k = 0; k <= 700; ++k) {
    const std::int64_t ns = kStart + 100'000'000LL * k;
    w.message(cmd, static_cast<std::uint64_t>(ns), CdrWriter().put(command(0.1 * k)).bytes());
    if (slow && k % 5 != 0) continue;
    const std::int64_t stamp = ns + (slow ? 50'000'000 : 0);
    const double t = static_cast<double>(stamp - kStart) * 1e-9;
    CdrWriter m;
    m.header(stamp).put(response(t)).put(1.0).put(2.0).put(3.0 * k);
    w.message(fb, static_cast<std::uint64_t>(stamp + 7'000'000), m.bytes());
  }
  const auto path = dir / name;
  w.write(path);
  return path;
}

// The same data as CSV, every number with 17 significant digits.
std::filesystem::path write_csv(const TempDir& dir, const std::string& name, bool slow_only,
                                bool fast_only) {
  std::string csv = fast_only ? "time,cmd\n" : (slow_only ? "time,rpm\n" : "time,cmd,rpm\n");
  for (int k = 0; k <= 700; ++k) {
    if (slow_only && k % 5 != 0) continue;
    const std::int64_t stamp = kStart + 100'000'000LL * k + (slow_only ? 50'000'000 : 0);
    const double t = static_cast<double>(stamp - kStart) * 1e-9;
    csv += fmt::format("{:.17g}", t);
    if (!slow_only) csv += fmt::format(",{:.17g}", command(0.1 * k));
    if (!fast_only) csv += fmt::format(",{:.17g}", response(t));
    csv += "\n";
  }
  return dir.write(name, csv);
}

// Whether two JSON documents agree, numbers within `rel` relative; the keys `skip` ignored.
void expect_same(const nlohmann::json& a, const nlohmann::json& b, const std::string& at) {
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    EXPECT_LE(std::abs(x - y), 1e-12 * std::max({std::abs(x), std::abs(y), 1e-300})) << at;
    return;
  }
  ASSERT_EQ(a.type(), b.type()) << at;
  if (a.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it) {
      if (it.key() == "input" || it.key() == "log") continue;
      ASSERT_TRUE(b.contains(it.key())) << at << "." << it.key();
      expect_same(it.value(), b[it.key()], at + "." + it.key());
    }
  } else if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << at;
    for (std::size_t i = 0; i < a.size(); ++i) expect_same(a[i], b[i], at + fmt::format("[{}]", i));
  } else {
    EXPECT_EQ(a, b) << at;
  }
}

TEST(BagLog, IdentifyStepFromABagEqualsItsCsv) {
  const TempDir dir;
  StepRequest from_csv;
  from_csv.source.log = write_csv(dir, "steps.csv", false, false);
  from_csv.source.columns = {"input=cmd", "output=rpm"};
  const nlohmann::json expected = to_json(run_step(from_csv));
  for (const McapLayout& layout :
       {McapLayout{false, "", 0, false, true}, McapLayout{true, "zstd", 64, true, true},
        McapLayout{true, "lz4", 100, false, true}}) {
    StepRequest from_bag;
    from_bag.source.log = write_bag(dir, "steps.mcap", layout);
    from_bag.source.columns = {"input=/cmd.data", "output=/feedback.rpm"};
    const StepReport report = run_step(from_bag);
    ASSERT_EQ(report.steps.size(), 2u);
    expect_same(expected, to_json(report), "step");
    const io::InputReport& input = report.input;
    ASSERT_EQ(input.files.size(), 2u);
    EXPECT_EQ(input.files[0].format, "mcap");
    EXPECT_EQ(input.files[0].topic, "/cmd");
    EXPECT_EQ(input.files[0].time_format, "receive time");
    EXPECT_EQ(input.files[1].topic, "/feedback");
    EXPECT_EQ(input.files[1].time_format, "header.stamp");
    EXPECT_EQ(input.origin, "2024-05-01T10:00:00Z");
  }
}

TEST(BagLog, TopicsAtTheirOwnRatesAlignAsFilesDo) {
  const TempDir dir;
  LogSource csv;
  csv.log = write_csv(dir, "fast.csv", false, true);
  const auto slow = write_csv(dir, "slow.csv", true, false);
  csv.columns = {"input=cmd", "output=rpm@" + slow.string()};
  const LoadedLog expected = csv.load([](const std::string&) { return false; });
  LogSource bag;
  bag.log = write_bag(dir, "two.mcap", McapLayout{true, "zstd", 50, true, true}, true);
  bag.columns = {"input=/cmd.data", "output=/feedback.rpm", "thrust.port=/feedback.extra[2]"};
  const LoadedLog got = bag.load([](const std::string&) { return false; });
  ASSERT_EQ(got.log.time(), expected.log.time());
  for (const char* role : {"input", "output"}) {
    const std::vector<double>& a = expected.log.values(role);
    const std::vector<double>& b = got.log.values(role);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (std::isnan(a[i])) {
        EXPECT_TRUE(std::isnan(b[i])) << role << i;
      } else {
        EXPECT_NEAR(b[i], a[i], 1e-12 * std::max(1.0, std::abs(a[i]))) << role << i;
      }
    }
  }
  ASSERT_EQ(got.input.roles.size(), 3u);
  EXPECT_EQ(got.input.roles[1].topic, "/feedback");
  EXPECT_NEAR(*got.input.roles[1].rate_hz, 2.0, 1e-9);  // on its own clock
  // At 10 s, between the stamps 9.55 s (k = 95) and 10.05 s (k = 100); kN → N.
  EXPECT_NEAR(got.log.values("thrust.port")[100], (0.1 * 285.0 + 0.9 * 300.0) * 1000, 1e-6);
  // --bag-time receive: the feedback 7 ms later.
  bag.bag_time = "receive";
  const LoadedLog received = bag.load([](const std::string&) { return false; });
  EXPECT_EQ(received.input.files[1].time_format, "receive time");
  EXPECT_NEAR(received.input.files[1].clock_offset_s, 0.057, 1e-9);
}

TEST(BagLog, BagBesideACsvLog) {
  const TempDir dir;
  const auto bag = write_bag(dir, "run.mcap", McapLayout{true, "lz4", 100, true, true});
  LogSource source;
  source.log = write_csv(dir, "fast.csv", false, true);
  source.columns = {"input=cmd", "output=/feedback.rpm@" + bag.string()};
  source.time_format = "seconds";
  const LoadedLog got = source.load([](const std::string&) { return false; });
  EXPECT_NEAR(got.log.values("output")[200], response(20.0), 1e-12);
}

std::string error_of(LogSource source) {
  const auto e = caught_input_error([&] { source.load([](const std::string&) { return false; }); });
  return e ? e->what() : "";
}

TEST(BagLog, BadMappingsAndBagsAreErrorsNamingFileOffsetAndTopic) {
  const TempDir dir;
  LogSource source;
  source.log = write_bag(dir, "run.mcap", McapLayout{true, "zstd", 100, true, true});
  source.columns = {"input=/cmd.data", "output=/feedbak.rpm"};
  EXPECT_THAT(error_of(source), HasSubstr("run.mcap (/feedbak): the bag has no topic '/feedbak' "
                                          "(role 'output'); its topics: /cmd, /feedback"));
  source.columns = {"input=/cmd.data", "output=/feedback.rmp"};
  EXPECT_THAT(error_of(source),
              ::testing::MatchesRegex(".*run.mcap \\(/feedback\\): at byte [0-9]+ of the records "
                                      "of the chunk at byte [0-9]+: 'rmp': "
                                      "test_msgs/Feedback has no field 'rmp' \\(its fields: "
                                      "header, rpm, extra\\).*"));
  source.columns = {"input=/cmd"};
  EXPECT_THAT(error_of(source), HasSubstr("'/cmd' names no field of a topic"));
  source.columns = {"input=/cmd.data"};
  source.bag_time = "header";
  EXPECT_THAT(error_of(source),
              HasSubstr("(/cmd): at byte 519 of the records of the chunk at byte 40: "
                        "std_msgs/msg/Float64 has no header.stamp; read its "
                        "receive time with --bag-time"));
  source.bag_time = "sent";
  EXPECT_THAT(error_of(source), HasSubstr("unknown bag time 'sent'"));

  McapWriter w(McapLayout{false, "", 0, false, true});
  const std::uint16_t c = w.channel(w.schema("foxglove.Log", "{}", "jsonschema"), "/log", "json");
  w.message(c, 1, {'{', '}'});
  LogSource json;
  json.log = dir / "json.mcap";
  w.write(json.log);
  json.columns = {"input=/log.level"};
  EXPECT_THAT(error_of(json), HasSubstr("json.mcap (/log): at byte "));
  EXPECT_THAT(error_of(json), HasSubstr("the topic's schema encoding is 'jsonschema' and its "
                                        "message encoding 'json'; dynpos reads ROS 2 bags"));
}

}  // namespace
}  // namespace dynpos::analysis
