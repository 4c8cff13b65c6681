// `leverarm mru` as a request → report on a short simulated turning circle (MRUs at the arms of
// thesis table 4.6, MRU noise 0.01 m/s²), its request checks and its JSON.

#include "dynpos/analysis/leverarm_mru.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {
namespace {

const std::filesystem::path kSource = DYNPOS_SOURCE_DIR;

// One simulated 120 s turning circle for every test, written as `dynpos demo` writes it.
class LeverarmMru : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::filesystem::temp_directory_path() /
           ("dynpos_analysis_leverarm_mru-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    scenario::ScenarioSpec spec =
        scenario::load_scenario(kSource / "data" / "scenarios" / "turning-circle.toml");
    spec.set_duration(120.0);
    const scenario::VesselConfig vessel =
        scenario::load_vessel_config(kSource / "data" / "vessels" / "gunnerus.toml");
    const scenario::ScenarioRun run = scenario::run_scenario(spec, vessel, 1);
    scenario::write_scenario_run(run, trial());
    for (const char* name : {"mru1", "mru2"}) truth_[name] = run.truth.lever_arms.at(name);
  }
  static std::filesystem::path trial() { return dir_ / "turning-circle"; }

  // Motion from the reference (truth.csv), the accelerations of both MRUs from the logger.
  static LeverarmMruRequest reference_request() {
    LeverarmMruRequest q;
    q.source.log = trial() / "truth.csv";
    for (const char* m : {"mru1", "mru2"}) q.mru_log[m] = trial() / "log.csv";
    return q;
  }

  static std::filesystem::path dir_;
  static std::map<std::string, Eigen::Vector3d> truth_;
};

std::filesystem::path LeverarmMru::dir_;
std::map<std::string, Eigen::Vector3d> LeverarmMru::truth_;

std::string error_key(const LeverarmMruRequest& request) {
  try {
    request.validate();
  } catch (const core::InputError& e) {
    return e.option();
  }
  return {};
}

// Least squares reaches a few mm on this log (as the CLI test): 2 cm per axis is the target.
TEST_F(LeverarmMru, ReferenceMotionRecoversTheTrueArms) {
  const LeverarmMruReport r = run_leverarm_mru(reference_request());
  ASSERT_EQ(r.result.status, core::Status::kOk);
  ASSERT_EQ(r.result.arms.size(), 2U);
  for (const calib::ArmEstimate& a : r.result.arms) {
    EXPECT_LT((a.l_b_m - truth_.at(a.name)).cwiseAbs().maxCoeff(), 0.02) << a.name;
  }
  EXPECT_GT(r.result.excitation.rank3_fraction, 0.5);
  const std::string text = to_text(r);
  EXPECT_EQ(text.rfind((trial() / "truth.csv").string() +
                           ": MRU lever arms (lsq), BODY from the control origin\n",
                       0),
            0U);
}

// The observer (4.80) is asked for by name; its arms are the mean over the second half of the
// used span (the converged interval), where least squares uses all of it.
TEST_F(LeverarmMru, ObserverAveragesOverTheConvergedInterval) {
  LeverarmMruRequest q = reference_request();
  q.method = calib::MruMethod::kObserver;
  const LeverarmMruReport o = run_leverarm_mru(q);
  const LeverarmMruReport l = run_leverarm_mru(reference_request());
  EXPECT_EQ(o.result.method, calib::MruMethod::kObserver);
  EXPECT_EQ(to_json(o)["method"], "observer");
  EXPECT_EQ(o.result.interval_to_s, l.result.interval_to_s);
  const double middle = 0.5 * (l.result.interval_from_s + l.result.interval_to_s);
  EXPECT_NEAR(o.result.interval_from_s, middle, 0.1);
  ASSERT_EQ(o.result.history_l_b_m.size(), 2U);
  EXPECT_EQ(o.result.history_l_b_m[0].size(), o.result.history_t_s.size());
}

TEST_F(LeverarmMru, ValidateNamesTheBadOption) {
  const LeverarmMruRequest good = reference_request();
  EXPECT_EQ(error_key(good), "");
  LeverarmMruRequest q = good;
  q.tau_s = 0.0;
  EXPECT_EQ(error_key(q), "tau_s");
  q = good;
  q.window_s = 3e7;  // overflowed the smoother's sample count
  EXPECT_EQ(error_key(q), "window_s");
  q = good;
  q.window_s = std::nan("");
  EXPECT_EQ(error_key(q), "window_s");
  q = good;
  q.mru_log = {{"mru1", ""}};
  EXPECT_EQ(error_key(q), "mru_log");
  for (const double w1 : {-1.0, 0.0, std::nan(""), HUGE_VAL}) {
    q = good;
    q.w1 = w1;  // was a std::invalid_argument of the observer naming "w1_per_s"
    EXPECT_EQ(error_key(q), "w1") << w1;
  }
}

// Errors of the calibration library name options by their request key, and errors about the
// log name the log as given.
TEST(LeverarmMruErrors, CalibNamesTheKeyAndTheAnalysisTheLog) {
  calib::MruSignalOptions so;
  so.smooth_window_s = 0.0;
  try {
    calib::mru_signals_from_samples(calib::MruRawSamples{}, so);
    FAIL() << "a window of 0 s was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "window_s");
  }
  LeverarmMruRequest q;
  q.source.log = std::filesystem::path(DYNPOS_SOURCE_DIR) / "tests" / "cli" / "short_steps.csv";
  try {
    run_leverarm_mru(q);
    FAIL() << "a log without an MRU was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, q.source.log.string());
    EXPECT_NE(e.problem().find("no MRU acceleration channels"), std::string::npos) << e.what();
  }
}

TEST_F(LeverarmMru, SmoothingWindowLongerThanTheLogAllowsIsAnInputError) {
  LeverarmMruRequest q = reference_request();
  q.window_s = 40.0;  // the smoothing window alone spans a third of the log
  try {
    run_leverarm_mru(q);
    FAIL() << "a 40 s window on 120 s was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("too short"), std::string::npos) << e.what();
  }
}

TEST_F(LeverarmMru, JsonHasTheDocumentedKeys) {
  const nlohmann::json j = to_json(run_leverarm_mru(reference_request()));
  for (const char* key : {"method", "arms", "interval_s", "excitation", "notes", "units"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_FALSE(j.contains("log"));  // the CLI's document has none; the demo's adds it
  ASSERT_EQ(j["arms"].size(), 2U);
  EXPECT_EQ(j["arms"][0]["name"], "mru1");
  for (const char* key : {"name", "x", "y", "z", "std", "determinacy"})
    EXPECT_TRUE(j["arms"][0].contains(key)) << key;
  for (const char* key :
       {"g_rank3_fraction", "g_min_singular_value_median_per_s3", "g_condition_median",
        "information_min_eigenvalue_per_s4", "information_condition", "advice"})
    EXPECT_TRUE(j["excitation"].contains(key)) << key;
}

// The demo's section reads the logger alone: in a campaign without truth.csv it runs, its arms
// from MRU 1, and the true arms' difference (truth.json) is only its check.
TEST_F(LeverarmMru, DemoSectionRunsFromTheLoggerAloneAndChecksAgainstTheTruth) {
  const std::filesystem::path campaign = dir_ / "logger-only";
  std::filesystem::create_directories(campaign / "turning-circle");
  for (const char* f : {"log.csv", "truth.json"}) {
    std::filesystem::copy_file(trial() / f, campaign / "turning-circle" / f,
                               std::filesystem::copy_options::overwrite_existing);
  }
  const ReportSection s = leverarm_mru_demo_section(campaign);
  EXPECT_EQ(s.title, "MRU lever arms");
  EXPECT_NE(s.markdown.find("error x, y, z [mm]"), std::string::npos);
  EXPECT_NE(s.markdown.find("--reference mru1"), std::string::npos);
  const std::filesystem::path out = campaign / "analysis" / "leverarm";
  for (const char* f : {"mru.json", "mru2.svg", "mru-excitation.svg"})
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  EXPECT_FALSE(std::filesystem::exists(out / "mru1.svg"));  // the reference: no arm of its own
  std::ifstream in(out / "mru.json");
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["reference"], "mru1");
  ASSERT_EQ(doc["input"]["files"].size(), 1U);
  EXPECT_EQ(doc["input"]["files"][0]["path"], "turning-circle/log.csv");
  ASSERT_EQ(doc["arms"].size(), 1U);
  EXPECT_EQ(doc["arms"][0]["name"], "mru2");
  const Eigen::Vector3d arm(doc["arms"][0]["x"].get<double>(), doc["arms"][0]["y"].get<double>(),
                            doc["arms"][0]["z"].get<double>());
  EXPECT_LT((arm - (truth_.at("mru2") - truth_.at("mru1"))).cwiseAbs().maxCoeff(), 0.02) << arm;
  EXPECT_EQ(leverarm_mru_demo_section(dir_ / "no-campaign").title, "");
}

// A reference MRU: the other MRUs' arms from it with no velocity read; a name that is no MRU
// prefix, and MRUs in files of their own, are errors of the option.
TEST_F(LeverarmMru, ReferenceMruNeedsNoVelocity) {
  LeverarmMruRequest q;
  q.source.log = trial() / "log.csv";
  q.reference = "mru1";
  const LeverarmMruReport r = run_leverarm_mru(q);
  ASSERT_EQ(r.result.arms.size(), 1U);
  EXPECT_EQ(r.reference, "mru1");
  for (const io::RoleOrigin& role : r.input.roles) {
    EXPECT_TRUE(role.role != "u" && role.role != "v" && role.role != "w") << role.role;
  }
  EXPECT_EQ(to_json(r)["units"], "m, BODY (x forward, y starboard, z down) from mru1");
  EXPECT_NE(to_text(r).find("BODY from mru1\n"), std::string::npos);
  LeverarmMruRequest bad = q;
  bad.reference = "gnss1";
  EXPECT_EQ(error_key(bad), "reference");
  bad = q;
  bad.mru_log = {{"mru2", trial() / "log.csv"}};
  EXPECT_EQ(error_key(bad), "reference");
  bad = q;
  bad.reference = "mru3";  // not in the log
  EXPECT_THROW(run_leverarm_mru(bad), core::InputError);
}

}  // namespace
}  // namespace dynpos::analysis
