#include "dynpos/report/comparison.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "dynpos/core/error.hpp"

namespace dynpos::report {
namespace {

using nlohmann::json;

const ComparisonRow* find_row(const ComparisonResult& r, const std::string& figure) {
  for (const ComparisonRow& row : r.rows) {
    if (row.figure == figure) return &row;
  }
  return nullptr;
}

TEST(Comparison, KindFromKeysOrAnalysisKey) {
  EXPECT_EQ(result_kind(json::parse(R"({"steps":[]})")), "step");
  EXPECT_EQ(result_kind(json::parse(R"({"legs":[],"total":{}})")), "four-corner");
  EXPECT_EQ(result_kind(json::parse(R"({"directions":[]})")), "agility");
  EXPECT_EQ(result_kind(json::parse(R"({"method":"gnss","arms":[]})")), "leverarm");
  EXPECT_EQ(result_kind(json::parse(R"({"position_std_m":{"north":1}})")), "station-keeping");
  EXPECT_EQ(result_kind(json::parse(R"({"analysis":"thrust-map","thrusters":[]})")), "thrust-map");
  EXPECT_EQ(result_kind(json::parse(R"({"case":"dp","variant":"hybrid"})")), "hybrid dp");
  EXPECT_EQ(result_kind(json::parse(R"({"x":1})")), "generic");
}

TEST(Comparison, DifferenceAndRelativeDifference) {
  // Exact binary fractions, so the expected values are exact.
  const auto r = compare_results(json::parse(R"({"a":{"x":4.0,"y":-2.0,"z":0.0}})"),
                                 json::parse(R"({"a":{"x":5.0,"y":-1.0,"z":1.0}})"));
  const ComparisonRow* x = find_row(r, "a.x");
  ASSERT_NE(x, nullptr);
  EXPECT_EQ(x->difference().value(), 1.0);
  EXPECT_EQ(x->relative_difference_pct().value(), 25.0);
  // Relative to |A|: from -2 to -1 is an increase of 50 %.
  EXPECT_EQ(find_row(r, "a.y")->relative_difference_pct().value(), 50.0);
  // A = 0: no relative difference, but the absolute one stays.
  EXPECT_FALSE(find_row(r, "a.z")->relative_difference_pct().has_value());
  EXPECT_EQ(find_row(r, "a.z")->difference().value(), 1.0);
}

TEST(Comparison, NullsAndOneSidedFiguresStayMissing) {
  const auto r = compare_results(json::parse(R"({"T":null,"K":2.0,"only_a":1.0})"),
                                 json::parse(R"({"T":3.0,"K":null,"only_b":7.0})"));
  EXPECT_FALSE(find_row(r, "T")->a.has_value());
  EXPECT_EQ(find_row(r, "T")->b.value(), 3.0);
  EXPECT_FALSE(find_row(r, "T")->difference().has_value());
  EXPECT_FALSE(find_row(r, "K")->b.has_value());
  EXPECT_FALSE(find_row(r, "only_a")->b.has_value());
  EXPECT_FALSE(find_row(r, "only_b")->a.has_value());
  EXPECT_EQ(r.only_in_a, 1U);
  EXPECT_EQ(r.only_in_b, 1U);
  const Table t = comparison_table(r, "Aug", "Nov");
  EXPECT_EQ(t.header[1], "Aug");
  for (const auto& row : t.rows) {
    if (row[0] == "T") {
      EXPECT_EQ(row[1], "—");
      EXPECT_EQ(row[3], "—");
      EXPECT_EQ(row[4], "—");
    }
  }
  const json j = comparison_json(r, "Aug", "Nov");
  EXPECT_TRUE(j["rows"][0].contains("a"));
  for (const json& row : j["rows"]) {
    if (row["figure"] == "T") {
      EXPECT_TRUE(row["a"].is_null());
    }
  }
}

TEST(Comparison, LegsAndArmsPairByNameNotPosition) {
  const auto r = compare_results(
      json::parse(R"({"legs":[{"name":"fwd","duration_s":10},{"name":"stb","duration_s":20}]})"),
      json::parse(R"({"legs":[{"name":"stb","duration_s":25},{"name":"aft","duration_s":5}]})"));
  EXPECT_EQ(find_row(r, "legs[name=stb].duration_s")->difference().value(), 5.0);
  EXPECT_FALSE(find_row(r, "legs[name=fwd].duration_s")->b.has_value());
  EXPECT_FALSE(find_row(r, "legs[name=aft].duration_s")->a.has_value());
}

TEST(Comparison, DirectionsPairByAngleAndCase) {
  const auto r = compare_results(
      json::parse(R"({"directions":[{"direction_deg":0,"case":"a","response_s":{"port":2}},
                                    {"direction_deg":90,"case":"a","response_s":{"port":4}}]})"),
      json::parse(R"({"directions":[{"direction_deg":90,"case":"a","response_s":{"port":3}},
                                    {"direction_deg":0,"case":"b","response_s":{"port":9}}]})"));
  EXPECT_EQ(find_row(r, "directions[direction_deg=90,a].response_s.port")->difference().value(),
            -1.0);
  EXPECT_FALSE(find_row(r, "directions[direction_deg=0,a].response_s.port")->b.has_value());
  EXPECT_FALSE(find_row(r, "directions[direction_deg=0,b].response_s.port")->a.has_value());
}

TEST(Comparison, StepsPairByNearestStepTime) {
  // B found an extra step at 55 s and its steps are detected 0.5 s later: the 20 s and 100 s
  // steps pair with 20.5 s and 100.5 s (within the 5 s tolerance), 55 s stands alone.
  const auto r = compare_results(
      json::parse(R"({"steps":[{"t_step":20,"T":2.0},{"t_step":100,"T":4.0}]})"),
      json::parse(
          R"({"steps":[{"t_step":20.5,"T":2.5},{"t_step":55,"T":9},{"t_step":100.5,"T":3.0}]})"));
  EXPECT_EQ(find_row(r, "steps[t_step=20].T")->difference().value(), 0.5);
  EXPECT_EQ(find_row(r, "steps[t_step=100].T")->difference().value(), -1.0);
  EXPECT_EQ(find_row(r, "steps[t_step=55].T")->b.value(), 9.0);
  EXPECT_FALSE(find_row(r, "steps[t_step=55].T")->a.has_value());
}

// A fuzz finding: steps at repeated times (and legs of repeated names) paired crosswise, so a
// result compared with itself showed differences. Of equally near items the first in B pairs.
TEST(Comparison, ADocumentComparedWithItselfDiffersNowhere) {
  const json doc = json::parse(R"({"steps":[{"t_step":20,"T":2},{"t_step":820,"T":8},
      {"t_step":420,"T":4},{"t_step":820,"T":2},{"t_step":817,"T":3},{"t_step":823,"T":5}],
      "legs":[{"name":"fwd","x":1},{"name":"fwd","x":2},{"name":"aft","x":3}]})");
  // A later finding: a step whose time is not a number (an object, null) paired with nothing.
  const json untimed = json::parse(
      R"({"steps":[{"t_step":{"K":0.02},"T":1},{"t_step":null,"T":2},{"t_step":5,"T":3}]})");
  const auto u = compare_results(untimed, untimed);
  EXPECT_EQ(u.only_in_a + u.only_in_b, 0u);
  for (const ComparisonRow& row : u.rows) EXPECT_EQ(row.a, row.b) << row.figure;
  const auto r = compare_results(doc, doc);
  EXPECT_EQ(r.only_in_a + r.only_in_b, 0u);
  ASSERT_EQ(r.rows.size(), 15u);  // t_step and T of six steps, x of three legs
  for (const ComparisonRow& row : r.rows) EXPECT_EQ(row.difference(), 0.0) << row.figure;
}

TEST(Comparison, EquallyNearStepsPairTheFirstInB) {
  // 10 s lies 2 s from both 8 s and 12 s: the first of them in B (12 s) pairs with it.
  const auto r =
      compare_results(json::parse(R"({"steps":[{"t_step":10,"T":1}]})"),
                      json::parse(R"({"steps":[{"t_step":12,"T":2},{"t_step":8,"T":3}]})"));
  EXPECT_EQ(find_row(r, "steps[t_step=10].T")->b.value(), 2.0);
  EXPECT_EQ(find_row(r, "steps[t_step=8].T")->b.value(), 3.0);
  EXPECT_EQ(r.only_in_b, 2u);  // the 8 s step's t_step and T
}

TEST(Comparison, PlainArraysPairByPosition) {
  const auto r = compare_results(json::parse(R"({"x":{"std":[1.0,2.0]}})"),
                                 json::parse(R"({"x":{"std":[1.5]}})"));
  EXPECT_EQ(find_row(r, "x.std[1]")->difference().value(), 0.5);
  EXPECT_FALSE(find_row(r, "x.std[2]")->b.has_value());
}

TEST(Comparison, TextFiguresShownOnlyWhenTheyDiffer) {
  const auto r = compare_results(
      json::parse(R"({"steps":[{"t_step":1,"status":"ok","method":"lsq","log":"a.csv"}]})"),
      json::parse(R"({"steps":[{"t_step":1,"status":"poor_fit","method":"lsq","log":"b.csv"}]})"));
  const ComparisonRow* s = find_row(r, "steps[t_step=1].status");
  ASSERT_NE(s, nullptr);
  EXPECT_TRUE(s->text);
  EXPECT_EQ(s->b_text, "poor_fit");
  EXPECT_EQ(find_row(r, "steps[t_step=1].method"), nullptr);
  EXPECT_EQ(find_row(r, "steps[t_step=1].log"), nullptr);  // not a figure
}

TEST(Comparison, DifferentKindsAreRejectedNamingBoth) {
  try {
    compare_results(json::parse(R"({"steps":[]})"), json::parse(R"({"legs":[]})"));
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'step'"), std::string::npos);
    EXPECT_NE(what.find("'four-corner'"), std::string::npos);
  }
}

TEST(Comparison, LineColumnOfByteOffset) {
  const std::string text = "{\n  \"a\": 1,\n  \"b\": x\n}";
  // nlohmann reports the count of characters read; 'x' is the 20th character.
  EXPECT_EQ(line_column_of(text, 20), (std::pair<std::size_t, std::size_t>{3, 8}));
  EXPECT_EQ(line_column_of(text, 1), (std::pair<std::size_t, std::size_t>{1, 1}));
}

TEST(Comparison, InvalidJsonFileNamesLineAndColumn) {
  const auto path = std::filesystem::temp_directory_path() / "dynpos_comparison_bad.json";
  {
    std::ofstream out(path);
    out << "{\n  \"a\": 1,\n  \"b\": x\n}\n";
  }
  try {
    load_json_file(path);
    FAIL() << "no exception";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().line.value(), 3U);
    EXPECT_EQ(e.where().column.value(), 8U);
  }
  std::filesystem::remove(path);
}

// A hostile document: nesting far beyond any result's, and a number beyond double's range.
TEST(Comparison, DeepNestingAndHugeNumbersAreLocatedErrors) {
  const auto path = std::filesystem::temp_directory_path() / "dynpos_comparison_deep.json";
  {
    std::ofstream out(path);
    out << "{\"a\": \"[[[\",\n \"b\": " << std::string(20000, '[') << std::string(20000, ']')
        << "}";
  }
  try {
    load_json_file(path);
    FAIL() << "no exception";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().line.value(), 2U);          // the brackets inside the string do not count
    EXPECT_EQ(e.where().column.value(), 7U + 63U);  // the 64th bracket, inside the object
    EXPECT_NE(e.problem().find("nested deeper than 64"), std::string::npos);
  }
  {
    std::ofstream out(path);
    out << "{\n  \"steps\": [{\"K\": 1e400}]\n}\n";
  }
  try {
    load_json_file(path);
    FAIL() << "no exception";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().line.value(), 2U);
    EXPECT_NE(e.problem().find("number overflow"), std::string::npos);
  }
  std::filesystem::remove(path);
}

// A file of more than 64 MiB is not a result: refused by its size, not read into memory.
TEST(Comparison, AJsonFileOfMoreThan64MiBIsRefused) {
  const auto path = std::filesystem::temp_directory_path() / "dynpos_comparison_big.json";
  std::ofstream(path) << "{}";
  std::filesystem::resize_file(path, (std::uintmax_t{64} << 20) + 1);
  try {
    load_json_file(path);
    FAIL() << "no exception";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, path.string());
    EXPECT_NE(e.problem().find("more than 64 MiB (67108865 bytes)"), std::string::npos)
        << e.problem();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace dynpos::report
