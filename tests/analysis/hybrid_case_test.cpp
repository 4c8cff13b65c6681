#include "dynpos/analysis/hybrid_case.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>

#include <filesystem>
#include <limits>
#include <string>

#include "dynpos/core/error.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using ::testing::ContainsRegex;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// The request key of the option error validate() throws, or "" if it does not throw.
std::string failing_key(const HybridCaseRequest& request, std::string* message = nullptr) {
  try {
    request.validate();
  } catch (const core::InputError& e) {
    if (message) *message = e.what();
    return e.option();
  }
  return "";
}

HybridCaseRequest dp_request() {
  HybridCaseRequest r;
  r.study_case = HybridCase::kDp;
  return r;
}

// The thesis configuration runs; each run takes tens of milliseconds, so run each once.
const HybridCaseReport& first_order_report() {
  static const HybridCaseReport r = run_hybrid_case(HybridCaseRequest{});
  return r;
}

TEST(HybridCaseRequest, DefaultsAreTheThesisFirstOrderCase) {
  const HybridCaseRequest r;
  EXPECT_EQ(r.study_case, HybridCase::kFirstOrder);
  EXPECT_EQ(r.seed, 1u);
  EXPECT_FALSE(r.no_jumps || r.sampled || r.solve_p);
  EXPECT_EQ(failing_key(r), "");
  EXPECT_EQ(failing_key(dp_request()), "");
}

TEST(HybridCaseRequest, ErrorsNameTheirOption) {
  EXPECT_EQ(analysis::testing::option_key_of([] { (void)hybrid_case_from_string("second-order"); }),
            "case");
  EXPECT_EQ(hybrid_case_from_string("dp"), HybridCase::kDp);
  EXPECT_EQ(to_string(HybridCase::kFirstOrder), "first-order");

  HybridCaseRequest r = dp_request();
  r.no_jumps = true;
  r.sampled = true;
  EXPECT_EQ(failing_key(r), "sampled");

  r = HybridCaseRequest{};
  r.heading_deg = 90.0;
  EXPECT_EQ(failing_key(r), "heading");

  r = dp_request();
  r.ki = 2.0;
  EXPECT_EQ(failing_key(r), "ki");
  r.ki.reset();
  r.solve_p = true;
  EXPECT_EQ(failing_key(r), "solve_p");

  r = dp_request();
  r.sample_period_s = 0.0305;  // off the 1 ms grid
  std::string message;
  EXPECT_EQ(failing_key(r, &message), "sample_period");  // the one option, not all four
  EXPECT_THAT(message, HasSubstr("sample_period"));
  EXPECT_THAT(message, ::testing::Not(HasSubstr("CaseTiming")));  // no library names

  r = HybridCaseRequest{};
  r.lambda = -1.0;
  EXPECT_EQ(failing_key(r, &message), "lambda");
  EXPECT_THAT(message, HasSubstr("lambda = -1 must be > 0"));
}

TEST(HybridCaseRequest, StepsOutsideTheRunAndANonFiniteHeadingAreOptionErrors) {
  // The first-order disturbance steps at 20 s and the DP bias steps lie beyond a 2 s run.
  HybridCaseRequest r;
  r.end_time_s = 2.0;
  std::string message;
  EXPECT_EQ(failing_key(r, &message), "end_time");
  EXPECT_THAT(message, HasSubstr("step 1 time must be in [0, end_time)"));
  r = dp_request();
  r.end_time_s = 2.0;
  EXPECT_EQ(failing_key(r), "end_time");
  r = dp_request();
  r.heading_deg = std::nan("");
  EXPECT_EQ(failing_key(r), "heading");
  // A heading beyond a turn (400° was taken as 40°) is refused, as in scenario files.
  for (const double heading : {400.0, -361.0}) {
    r = dp_request();
    r.heading_deg = heading;
    EXPECT_EQ(failing_key(r, &message), "heading") << heading;
    EXPECT_THAT(message, HasSubstr("within ±360°"));
  }
  r = dp_request();
  r.heading_deg = -360.0;
  EXPECT_EQ(failing_key(r), "");
  // A run of 1e5 s hung and 1e9 s ran out of memory: an hour is the most a case study takes.
  for (const double end : {1e5, 1e9, std::numeric_limits<double>::infinity()}) {
    r = dp_request();
    r.end_time_s = end;
    EXPECT_EQ(failing_key(r), "end_time") << end;
  }
}

TEST(HybridCaseRequest, ViolatedTheoremSixIsRefusedUnlessPIsSolvedFor) {
  HybridCaseRequest r;
  r.ki = 30.0;
  std::string message;
  EXPECT_EQ(failing_key(r, &message), "ki");
  EXPECT_THAT(message, HasSubstr("Theorem 6 fail"));
  EXPECT_THAT(message, HasSubstr("negative definite (5.24)"));
  r.solve_p = true;
  EXPECT_EQ(failing_key(r), "");
}

TEST(HybridCase, FirstOrderRunsBothDesigns) {
  const HybridCaseReport& r = first_order_report();
  ASSERT_TRUE(r.hybrid.has_value());
  EXPECT_TRUE(r.hybrid->ok()) << r.hybrid->message;
  EXPECT_EQ(r.hybrid->jump_set, hybrid::JumpSet::kIdeal);
  EXPECT_EQ(r.conventional.jump_set, hybrid::JumpSet::kNone);
  // docs/cli.md: 19 jumps of the ideal jump set, none for the conventional design.
  EXPECT_EQ(r.hybrid->metrics.jumps, 19);
  EXPECT_EQ(r.conventional.metrics.jumps, 0);
  ASSERT_TRUE(std::holds_alternative<FirstOrderStudy>(r.study));
  EXPECT_TRUE(std::get<FirstOrderStudy>(r.study).check.ok());
}

TEST(HybridCase, TextIsTheSideBySideTable) {
  const std::string text = to_text(first_order_report());
  EXPECT_THAT(text, StartsWith("dynpos hybrid first-order: ideal jump set vs conventional\n"
                               "Theorem 6: satisfied (beta = 6, gamma = 9.6; "));
  EXPECT_THAT(text, HasSubstr("settle after step +100 at 5 s [s]"));
  EXPECT_THAT(text, HasSubstr("settle after step -50 at 30 s [s]"));
  EXPECT_THAT(text, ContainsRegex("\njumps +19 +0\n"));
}

TEST(HybridCase, JsonHasThePrimaryRunAtTheTopLevel) {
  const nlohmann::json j = to_json(first_order_report(), {"a/first-order_states.svg"});
  EXPECT_EQ(j["case"], "first-order");
  EXPECT_EQ(j["jump_set"], "ideal");
  EXPECT_EQ(j["variant"], "hybrid");
  EXPECT_EQ(j["jumps"], 19);
  EXPECT_EQ(j["jumps"], j["hybrid"]["jumps"]);
  EXPECT_EQ(j["conventional"]["jumps"], 0);
  EXPECT_EQ(j["stability"]["theorem"], 6);
  EXPECT_EQ(j["parameters"]["lambda"], 3.0);
  EXPECT_EQ(j["parameters"]["timing"]["dt_s"], 1e-3);
  EXPECT_EQ(j["parameters"]["steps"].size(), 2u);
  EXPECT_EQ(j["plots"], nlohmann::json::array({"a/first-order_states.svg"}));
  for (const char* key : {"seed", "settle_s", "iae", "peak_error", "v_increase_at_jumps"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
}

TEST(HybridCase, DpWithoutJumpsReportsTheConventionalRunOnly) {
  HybridCaseRequest request = dp_request();
  request.no_jumps = true;
  request.end_time_s = 20.0;
  const HybridCaseReport r = run_hybrid_case(request);
  EXPECT_FALSE(r.hybrid.has_value());
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["jump_set"], "none");
  EXPECT_EQ(j["variant"], "conventional");
  EXPECT_FALSE(j.contains("hybrid"));
  EXPECT_EQ(j["stability"]["theorem"], 7);
  EXPECT_EQ(j["parameters"]["timing"]["end_time_s"], 20.0);
  EXPECT_TRUE(j["conventional"].contains("heading_iae_rad_s"));
  EXPECT_THAT(to_text(r), StartsWith("dynpos hybrid dp: conventional only (--no-jumps)\n"
                                     "Theorem 7: satisfied"));

  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("dynpos_hybrid_case_test-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const auto written = write_figures(r, dir / "plots");
  ASSERT_EQ(written.size(), 4u);
  EXPECT_EQ(written.front().filename(), "dp-conventional_position.svg");
  for (const auto& p : written) EXPECT_GT(std::filesystem::file_size(p), 1000u) << p;
  std::filesystem::remove_all(dir);
}

TEST(HybridCaseOutputs, JsonMayGoIntoTheFigureFolderButNotIntoAMissingOne) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("dynpos_hybrid_case_outputs-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  EXPECT_NO_THROW(check_hybrid_case_outputs(dir, (dir / "r.json").string()));
  EXPECT_NO_THROW(check_hybrid_case_outputs({}, "-"));
  try {
    check_hybrid_case_outputs({}, (dir / "no" / "r.json").string());
    FAIL() << "a missing JSON folder was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "json");
    EXPECT_THAT(e.what(), HasSubstr("does not exist"));
  }
}

}  // namespace
}  // namespace dynpos::analysis
