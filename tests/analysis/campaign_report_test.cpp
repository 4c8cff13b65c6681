#include "dynpos/analysis/campaign_report.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace dynpos::analysis {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<scenario::RunSummary> two_runs() {
  scenario::RunSummary a;
  a.name = "alpha";
  a.description = "First <test>";
  a.duration_s = 60.0;
  a.rows = 601;
  a.seed = 11;
  a.max_speed_mps = 1852.0 / 3600.0;  // 1 kn
  a.energy_kJ = 1234.4;
  a.wall_time_s = 0.5;
  scenario::RunSummary b = a;
  b.name = "beta";
  b.duration_s = 30.0;
  b.wall_time_s = 0.2;
  return {a, b};
}

scenario::VesselConfig vessel() {
  scenario::VesselConfig v;
  v.name = "Test vessel";
  return v;
}

TEST(CampaignReport, WritesTheTableAndTheTitledSectionsInOrder) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("dynpos_campaign_report_test-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::vector<ReportSection> sections = {
      {"Steps & such", "<p>step html</p>\n", "step markdown\n"},
      {"", "<p>nothing</p>\n", "nothing\n"},  // no title: the analysis has nothing to add
      {"Hybrid", "<p>hybrid html</p>\n", "hybrid markdown\n"}};
  write_campaign_report(two_runs(), vessel(), 5, dir, sections);

  const std::string md = read(dir / "summary.md");
  EXPECT_THAT(md, testing::StartsWith("# Virtual sea trial: Test vessel\n\nMaster seed 5.\n\n"));
  EXPECT_THAT(md, HasSubstr("| alpha | 60 | 601 | 1.00 | 0.00 | 0 | 1234 | "
                            "[alpha/log.csv](alpha/log.csv) |\n"));
  const std::size_t steps = md.find("\n## Steps & such\n\nstep markdown\n");
  const std::size_t hybrid = md.find("\n## Hybrid\n\nhybrid markdown\n");
  ASSERT_NE(steps, std::string::npos);
  ASSERT_NE(hybrid, std::string::npos);
  EXPECT_LT(steps, hybrid);
  EXPECT_THAT(md, Not(HasSubstr("nothing")));

  const std::string html = read(dir / "index.html");
  EXPECT_THAT(html, HasSubstr("<h2>Steps &amp; such</h2>\n<p>step html</p>\n"));
  EXPECT_THAT(html, HasSubstr("<td>First &lt;test&gt;</td>"));
  EXPECT_THAT(html, Not(HasSubstr("nothing")));
  EXPECT_LT(html.find("step html"), html.find("hybrid html"));

  const nlohmann::json summary = nlohmann::json::parse(read(dir / "summary.json"));
  EXPECT_EQ(summary["vessel"], "Test vessel");
  EXPECT_EQ(summary["master_seed"], 5);
  ASSERT_EQ(summary["scenarios"].size(), 2u);
  EXPECT_EQ(summary["scenarios"][1]["name"], "beta");
  EXPECT_EQ(summary["scenarios"][1]["truth"], "beta/truth.json");
  EXPECT_FALSE(summary["scenarios"][0].contains("wall_time_s"));  // not reproducible
  std::filesystem::remove_all(dir);
}

TEST(CampaignReport, TextHasOneLinePerRunAndTheTotals) {
  const std::string text = campaign_text(two_runs(), "out");
  EXPECT_EQ(text,
            "alpha                        60 s simulated in  0.50 s  max  1.00 kn      1234 kJ\n"
            "beta                         30 s simulated in  0.20 s  max  1.00 kn      1234 kJ\n"
            "2 scenarios, 90 s of sea trial in 0.7 s\n"
            "report: out/index.html\n");
}

}  // namespace
}  // namespace dynpos::analysis
