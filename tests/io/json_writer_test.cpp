#include "dynpos/io/json_writer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <sstream>

#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using testing::TempDir;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(JsonWriter, MissingNumbersBecomeNull) {
  EXPECT_TRUE(json_number(kNaN).is_null());
  EXPECT_TRUE(json_number(kInf).is_null());
  EXPECT_TRUE(json_number(-kInf).is_null());
  EXPECT_TRUE(json_number(std::optional<double>{}).is_null());
  EXPECT_EQ(json_number(1.5), nlohmann::json(1.5));
  EXPECT_EQ(json_number(std::optional<double>(-0.25)), nlohmann::json(-0.25));
  const double values[] = {1.0, kNaN, 3.0};
  EXPECT_EQ(json_numbers(values).dump(), "[1.0,null,3.0]");
}

TEST(JsonWriter, WritesPrettyJsonWithTrailingNewline) {
  TempDir dir;
  nlohmann::json doc = {{"T_s", json_number(4.5)}, {"delta_s", json_number(kNaN)}};
  write_json(dir / "result.json", doc);
  EXPECT_EQ(contents(dir / "result.json"), "{\n  \"T_s\": 4.5,\n  \"delta_s\": null\n}\n");
  EXPECT_EQ(json_text(doc), contents(dir / "result.json"));
}

TEST(JsonWriter, DashMeansStdout) {
  ::testing::internal::CaptureStdout();
  write_json("-", nlohmann::json{{"ok", true}});
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "{\n  \"ok\": true\n}\n");
}

TEST(JsonWriter, FailureLeavesNothingAndNamesThePath) {
  TempDir dir;
  try {
    write_json(dir / "missing" / "result.json", nlohmann::json::object());
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("result.json"));
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace dynpos::io
