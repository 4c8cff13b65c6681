#include "dynpos/analysis/demo.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include "dynpos/analysis/campaign_report.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::analysis {
namespace {

// The whole demo takes a minute; its output is checked end to end (tests/cli/demo_report.sh).
// Here: the request and the text.

TEST(DemoRequest, DefaultsAndTheOutputFolderKey) {
  DemoRequest r;
  EXPECT_EQ(r.out_dir, "dynpos-demo");
  EXPECT_EQ(r.seed, 1u);
  EXPECT_FALSE(r.data_dir.has_value());
  EXPECT_NO_THROW(r.validate());
  r.out_dir.clear();
  try {
    r.validate();
    FAIL() << "an empty report folder was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "out");
  }
}

TEST(Demo, TextIsTheCampaignsLinesAndWhereTheReportIs) {
  DemoReport report;
  report.out_dir = "demo";
  scenario::RunSummary run;
  run.name = "yaw-steps";
  run.duration_s = 600.0;
  report.runs = {run};
  const std::string text = to_text(report);
  EXPECT_EQ(text, campaign_text(report.runs, "demo"));
  EXPECT_NE(text.find("yaw-steps"), std::string::npos);
  EXPECT_NE(text.find("report: demo/index.html\n"), std::string::npos);
}

TEST(Demo, MissingDataFolderIsAnInputError) {
  DemoRequest r;
  r.out_dir =
      std::filesystem::temp_directory_path() / ("dynpos_demo_test-" + std::to_string(::getpid()));
  r.data_dir = std::filesystem::temp_directory_path() /
               ("dynpos_demo_test_no_data-" + std::to_string(::getpid()));
  std::filesystem::remove_all(*r.data_dir);
  EXPECT_THROW(run_demo(r), core::InputError);
  std::filesystem::remove_all(r.out_dir);
}

}  // namespace
}  // namespace dynpos::analysis
