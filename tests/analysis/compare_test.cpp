#include "dynpos/analysis/compare.hpp"

#include <gtest/gtest.h>

#include <string>

#include "../io/io_test_util.hpp"
#include "dynpos/core/error.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using io::testing::TempDir;
using testing::input_error;

// Two step results: the step at 20 s in A is the one at 20.5 s in B (T 2 → 2.5 s, delay 1.5 →
// null); the step at 420 s is in A only. Binary fractions, so the differences are exact.
struct Files {
  std::filesystem::path a, b;
};

Files write_steps(const TempDir& dir) {
  return {dir.write("aug.json", R"({"steps": [{"t_step": 20.0, "T": 2.0, "delay": 1.5},
                                              {"t_step": 420.0, "T": 4.0, "delay": 1.0}]})"),
          dir.write("nov.json", R"({"steps": [{"t_step": 20.5, "T": 2.5, "delay": null}]})")};
}

const report::ComparisonRow* find_row(const CompareReport& r, const std::string& figure) {
  for (const report::ComparisonRow& row : r.result.rows) {
    if (row.figure == figure) return &row;
  }
  return nullptr;
}

TEST(CompareAnalysis, StepResultsPairByStepTime) {
  TempDir dir;
  const Files f = write_steps(dir);
  CompareRequest request;
  request.a = f.a;
  request.b = f.b;
  const CompareReport report = run_compare(request);
  EXPECT_EQ(report.result.kind, "step");
  EXPECT_EQ(report.label_a, "aug.json");  // the file names by default
  EXPECT_EQ(report.label_b, "nov.json");
  const report::ComparisonRow* t = find_row(report, "steps[t_step=20].T");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->a, 2.0);
  EXPECT_EQ(t->b, 2.5);
  EXPECT_EQ(t->difference(), 0.5);
  const report::ComparisonRow* delay = find_row(report, "steps[t_step=20].delay");
  ASSERT_NE(delay, nullptr);
  EXPECT_FALSE(delay->b);
  // In both: t_step and T of the first step; delay is null in B, the second step is A's only.
  EXPECT_EQ(report.common, 2u);

  const nlohmann::json doc = to_json(report);
  for (const char* key : {"analysis", "kind", "labels", "only_in_a", "only_in_b", "rows"}) {
    EXPECT_TRUE(doc.contains(key)) << key;
  }
  EXPECT_EQ(doc.at("analysis"), "compare");
  EXPECT_EQ(doc.at("labels"), nlohmann::json({"aug.json", "nov.json"}));
  EXPECT_EQ(doc.at("rows").size(), report.result.rows.size());

  const std::string text = to_text(report);
  EXPECT_EQ(
      text.rfind("step results: aug.json = " + f.a.string() + ", nov.json = " + f.b.string() +
                     "; " + std::to_string(report.result.rows.size()) + " figures (2 in both, ",
                 0),
      0u)
      << text;
  EXPECT_NE(text.find("steps[t_step=20].T"), std::string::npos) << text;
}

TEST(CompareAnalysis, LabelsAndMarkdown) {
  TempDir dir;
  const Files f = write_steps(dir);
  CompareRequest request;
  request.a = f.a;
  request.b = f.b;
  request.labels = parse_compare_labels("Aug 2014,Nov 2014");
  request.format = table_format_from_string("markdown");
  const CompareReport report = run_compare(request);
  EXPECT_EQ(report.label_a, "Aug 2014");
  EXPECT_EQ(report.label_b, "Nov 2014");
  const std::string text = to_text(report);
  EXPECT_NE(text.find(")\n\n| figure | Aug 2014 | Nov 2014 |"), std::string::npos) << text;
}

TEST(CompareAnalysis, ValidateNamesTheOption) {
  CompareRequest request;
  EXPECT_EQ(input_error([] { table_format_from_string("html"); }).option(), "format");
  EXPECT_EQ(to_string(TableFormat::kMarkdown), "markdown");
  request.step_tolerance_s = 0.0;
  EXPECT_EQ(input_error([&] { request.validate(); }).option(), "step_tolerance");
  request.step_tolerance_s = 5.0;
  core::InputError e = input_error([] { parse_compare_labels("only one"); });
  EXPECT_EQ(e.option(), "labels");
  EXPECT_EQ(e.problem(), "'only one' is not two labels");
  EXPECT_EQ(input_error([] { parse_compare_labels("a,"); }).problem(), "an empty label in 'a,'");
  request.labels = CompareLabels{"", "b"};  // as the Python API gives a pair
  EXPECT_EQ(input_error([&] { request.validate(); }).option(), "labels");
  request.labels = parse_compare_labels("a,b");
  EXPECT_NO_THROW(request.validate());
}

TEST(CompareAnalysis, ErrorsAboutTheFilesNameThem) {
  TempDir dir;
  const Files f = write_steps(dir);
  CompareRequest request;
  request.a = f.a;
  request.b = dir.write("legs.json", R"({"legs": [{"name": "fwd", "t": 1.0}]})");
  core::InputError e = input_error([&] { run_compare(request); });
  EXPECT_EQ(e.where().file, request.b.string());
  EXPECT_NE(e.problem().find("cannot compare a 'step' result"), std::string::npos);

  request.a = dir.write("x.json", R"({"alpha": {"x": 1.0}})");
  request.b = dir.write("y.json", R"({"beta": {"x": 1.0}})");
  e = input_error([&] { run_compare(request); });
  EXPECT_EQ(e.where().file, request.b.string());
  EXPECT_NE(e.problem().find("no numeric figure in common"), std::string::npos);
}

}  // namespace
}  // namespace dynpos::analysis
