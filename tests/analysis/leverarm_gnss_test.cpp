// `leverarm gnss` as a request → report on a short simulated turning circle (antennas at the arms
// of thesis table 4.1, RTK noise, 1 Hz fixes), its request checks and its JSON.

#include "dynpos/analysis/leverarm_gnss.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>

#include "../source_dir.hpp"
#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/leverarm_mru.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/time_stamp.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {
namespace {

const std::filesystem::path kSource = DYNPOS_SOURCE_DIR;

// One simulated turning circle for every test: DIR/turning-circle/{log.csv, truth.csv,
// truth.json, gnssK.nmea}, as `dynpos demo` writes it.
class LeverarmGnss : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::filesystem::temp_directory_path() /
           ("dynpos_analysis_leverarm_gnss-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    scenario::ScenarioSpec spec =
        scenario::load_scenario(kSource / "data" / "scenarios" / "turning-circle.toml");
    spec.set_duration(200.0);
    const scenario::VesselConfig vessel =
        scenario::load_vessel_config(kSource / "data" / "vessels" / "gunnerus.toml");
    const scenario::ScenarioRun run = scenario::run_scenario(spec, vessel, 3);
    scenario::write_scenario_run(run, trial());
    start_utc_ = run.start_utc;
    for (const char* name : {"gnss1", "gnss2", "gnss3"})
      truth_[name] = run.truth.lever_arms.at(name);
  }
  static std::filesystem::path trial() { return dir_ / "turning-circle"; }

  // Motion from the reference (truth.csv), the fixes of `antennas` from the logger.
  static LeverarmGnssRequest reference_request(const std::vector<std::string>& antennas) {
    LeverarmGnssRequest q;
    q.source.log = trial() / "truth.csv";
    for (const std::string& a : antennas) q.gnss_log[a] = trial() / "log.csv";
    return q;
  }

  static std::filesystem::path dir_;
  static std::string start_utc_;
  static std::map<std::string, Eigen::Vector3d> truth_;
};

std::filesystem::path LeverarmGnss::dir_;
std::string LeverarmGnss::start_utc_;
std::map<std::string, Eigen::Vector3d> LeverarmGnss::truth_;

// The key of the option error `request.validate()` throws ("" if none).
std::string error_key(const LeverarmGnssRequest& request) {
  try {
    request.validate();
  } catch (const core::InputError& e) {
    return e.option();
  }
  return {};
}

// Least squares on 200 s of the reference motion: the estimator's own 1σ is a few mm in x and y
// and about 1.5 cm in z here, so each arm is held to 4σ + 1 mm of the truth (as in the
// validation test), and to 5 cm absolute so that a wrong arm of decimetres fails.
TEST_F(LeverarmGnss, ReferenceMotionRecoversTheTrueArms) {
  const LeverarmGnssReport r = run_leverarm_gnss(reference_request({"gnss1", "gnss2", "gnss3"}));
  ASSERT_EQ(r.result.status, core::Status::kOk);
  EXPECT_NEAR(r.gnss_rate_hz, 1.0, 1e-9);  // from the fix spacing of the 1 Hz receivers
  ASSERT_EQ(r.result.arms.size(), 3U);
  for (const calib::ArmEstimate& a : r.result.arms) {
    const Eigen::Vector3d& l = truth_.at(a.name);
    for (int j = 0; j < 3; ++j) {
      const double err = std::abs(a.l_b_m(j) - l(j));
      EXPECT_LT(err, 4.0 * a.std_m(j) + 1e-3) << a.name << " axis " << j;
      EXPECT_LT(err, 0.05) << a.name << " axis " << j;
    }
  }
  const std::string text = to_text(r);
  EXPECT_EQ(
      text.rfind((trial() / "truth.csv").string() + ": GNSS lever arms, method lsq, 3 antenna(s), ",
                 0),
      0U);
  EXPECT_NE(text.find("GNSS time offset: 0.000 s (given)"), std::string::npos);
}

// The NMEA fixes are UTC seconds of day: placed on the log's clock by utc_at_zero they give the
// arms of the same fixes in log.csv within 2 mm (NMEA rounds positions to about 0.2 mm); without
// it they do not overlap the log and the request's utc_at_zero is named, with the file.
TEST_F(LeverarmGnss, NmeaFixesOnTheLogClock) {
  LeverarmGnssRequest q;
  q.source.log = trial() / "truth.csv";
  q.nmea = {{"gnss1", trial() / "gnss1.nmea"}, {"gnss2", trial() / "gnss2.nmea"}};
  q.utc_at_zero = parse_utc_at_zero(start_utc_);
  const LeverarmGnssReport nmea = run_leverarm_gnss(q);
  const LeverarmGnssReport csv = run_leverarm_gnss(reference_request({"gnss1", "gnss2"}));
  ASSERT_EQ(nmea.result.arms.size(), 2U);
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_LT((nmea.result.arms[k].l_b_m - csv.result.arms[k].l_b_m).cwiseAbs().maxCoeff(), 2e-3);
  ASSERT_EQ(nmea.input_notes.size(), 2U);
  EXPECT_NE(nmea.input_notes[0].find("gnss1: "), std::string::npos);
  EXPECT_NE(nmea.input_notes[0].find("NMEA sentences from"), std::string::npos);

  q.utc_at_zero.reset();
  try {
    run_leverarm_gnss(q);
    FAIL() << "NMEA times outside the log's were accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "utc_at_zero");
    EXPECT_EQ(e.where().file, (trial() / "gnss1.nmea").string());
  }
}

// `file` with each line through `edit`.
void rewrite(const std::filesystem::path& from, const std::filesystem::path& to,
             const std::function<std::string(const std::string&)>& edit) {
  std::ifstream in(from);
  std::ofstream out(to);
  for (std::string line; std::getline(in, line);) out << edit(line) << '\n';
}

// An NMEA sentence's checksum: the XOR of the characters between '$' and '*'.
std::string with_checksum(const std::string& sentence) {
  const std::size_t star = sentence.find('*');
  unsigned sum = 0;
  for (std::size_t i = 1; i < star; ++i) sum ^= static_cast<unsigned char>(sentence[i]);
  return sentence.substr(0, star) + fmt::format("*{:02X}", sum);
}

// A receiver after a GPS week-number rollover dates its RMC 1024 weeks early (1995-01-11 for
// 2014-08-27). Beside a log with date-time stamps its capture is aligned by the whole weeks,
// noted in its input entry, and gives the arms the rightly dated capture gives; with strict it
// is an error naming the capture.
TEST_F(LeverarmGnss, ACaptureDatedBeforeAWeekRolloverIsAlignedAndNoted) {
  const std::int64_t t0_ns = io::parse_iso8601(start_utc_)->ns;
  const std::filesystem::path dated = trial() / "truth-dated.csv";
  rewrite(trial() / "truth.csv", dated, [&](const std::string& line) {
    const std::size_t comma = line.find(',');
    if (line.rfind("time", 0) == 0) return fmt::format("time{}", line.substr(comma));
    const double t_s = std::stod(line.substr(0, comma));
    return io::format_iso8601(t0_ns + std::llround(t_s * 1e9), 0) + line.substr(comma);
  });
  const std::string day = io::format_iso8601(t0_ns, 0);  // YYYY-MM-DDT…
  const std::string early_day = io::format_iso8601(t0_ns - 7168 * 86'400'000'000'000, 0);
  const auto ddmmyy = [](const std::string& iso) {
    return fmt::format(",{}{}{},", iso.substr(8, 2), iso.substr(5, 2), iso.substr(2, 2));
  };
  EXPECT_EQ(early_day.substr(0, 10), "1995-01-11");
  const std::filesystem::path early = trial() / "gnss1-early.nmea";
  std::size_t dates = 0;
  rewrite(trial() / "gnss1.nmea", early, [&](const std::string& line) {
    const std::size_t at = line.find(ddmmyy(day));
    if (line.rfind("$GNRMC", 0) != 0 || at == std::string::npos) return line;
    ++dates;
    return with_checksum(line.substr(0, at) + ddmmyy(early_day) + line.substr(at + 8));
  });
  ASSERT_GT(dates, 100U);

  LeverarmGnssRequest q;
  q.source.log = dated;
  q.nmea = {{"gnss1", trial() / "gnss1.nmea"}};
  const LeverarmGnssReport right = run_leverarm_gnss(q);
  q.nmea = {{"gnss1", early}};
  const LeverarmGnssReport r = run_leverarm_gnss(q);
  ASSERT_EQ(r.result.arms.size(), 1U);
  EXPECT_EQ(r.result.arms[0].l_b_m, right.result.arms[0].l_b_m);
  const io::FileReport* capture = r.input.file(early.string());
  ASSERT_NE(capture, nullptr);
  bool noted = false;
  for (const std::string& note : capture->notes) {
    noted = noted || note.find(
                         "its absolute time stamps are 1024 weeks (19.6 years) before the "
                         "main log's") != std::string::npos;
  }
  EXPECT_TRUE(noted) << ::testing::PrintToString(capture->notes);

  q.source.strict = true;
  try {
    run_leverarm_gnss(q);
    FAIL() << "a capture dated 1024 weeks early was accepted with strict";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, early.string());
    EXPECT_NE(e.problem().find("refused with --strict"), std::string::npos) << e.what();
  }
}

TEST_F(LeverarmGnss, ValidateNamesTheBadOption) {
  const LeverarmGnssRequest good = reference_request({"gnss1"});
  EXPECT_EQ(error_key(good), "");
  LeverarmGnssRequest q = good;
  q.lag = 0;
  EXPECT_EQ(error_key(q), "lag");
  q = good;
  q.w1 = Eigen::Vector3d(1, 2, NAN);
  EXPECT_EQ(error_key(q), "w1");
  q = good;
  q.L = Eigen::Vector3d(1, 0, 1);
  EXPECT_EQ(error_key(q), "L");
  q = good;
  q.init = {{"gnss1", Eigen::Vector3d(1, 2, INFINITY)}};
  EXPECT_EQ(error_key(q), "init");
  q = good;
  q.imu_arm = Eigen::Vector3d(NAN, 0, 0);
  EXPECT_EQ(error_key(q), "imu_arm");
  q = good;
  q.utc_at_zero = 86'400.0;
  EXPECT_EQ(error_key(q), "utc_at_zero");
  q = good;
  q.antennas = {"gps1"};
  EXPECT_EQ(error_key(q), "antennas");
  q = good;
  q.time_offset = 0.1;
  q.estimate_time_offset = true;
  EXPECT_EQ(error_key(q), "time_offset");
  q = good;
  q.max_time_offset = 0.01;
  EXPECT_EQ(error_key(q), "max_time_offset");
  q.max_time_offset = 1e9;  // the offset search stepped through it for hours
  EXPECT_EQ(error_key(q), "max_time_offset");
  q = good;
  q.converged_from = 1.0;
  EXPECT_EQ(error_key(q), "converged_from");
  q = good;
  q.pe_window = 0.0;
  EXPECT_EQ(error_key(q), "pe_window");
  q = good;
  q.gnss_std = -1.0;
  EXPECT_EQ(error_key(q), "gnss_std");
  q = good;
  q.gnss_log = {{"gps1", trial() / "log.csv"}};
  EXPECT_EQ(error_key(q), "gnss_log");
  q = good;
  q.gnss_log = {{"gnss1", dir_ / "no-such.csv"}};
  try {
    q.validate();
    FAIL() << "a missing file was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "gnss_log");
    EXPECT_EQ(e.where().file, (dir_ / "no-such.csv").string());
  }
}

// utc_at_zero given as text is read at the edge; a bad one is an error of its key, not of the
// column "time" of the NMEA reader.
TEST(LeverarmGnssText, UtcAtZeroIsReadAsSecondsOfDayAndABadOneNamesItsKey) {
  EXPECT_DOUBLE_EQ(parse_utc_at_zero("10:00:01.5"), 36'001.5);
  EXPECT_DOUBLE_EQ(parse_utc_at_zero("2014-08-27T10:00:00Z"), 36'000.0);
  try {
    parse_utc_at_zero("25:00:00");
    FAIL() << "25:00:00 was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "utc_at_zero");
    EXPECT_NE(e.problem().find("is not a UTC time"), std::string::npos) << e.problem();
  }
  for (const auto m : kLeverarmGnssMethods) EXPECT_FALSE(to_string(m).empty());
  EXPECT_EQ(to_string(LeverarmGnssMethod::kIns), "ins");
  // Enums by name, in any case; another name is an error of the request key.
  EXPECT_EQ(gnss_method_from_name("LSQ"), LeverarmGnssMethod::kLsq);
  EXPECT_EQ(accel_from_name("Specific-Force"), calib::MruAccel::kSpecificForce);
  EXPECT_EQ(mru_method_from_name("observer"), calib::MruMethod::kObserver);
  for (const auto& [key, lookup] :
       std::vector<std::pair<std::string, std::function<void(const std::string&)>>>{
           {"method", [](const std::string& n) { gnss_method_from_name(n); }},
           {"accel", [](const std::string& n) { accel_from_name(n); }},
           {"method", [](const std::string& n) { mru_method_from_name(n); }}}) {
    try {
      lookup("fast");
      FAIL() << key << ": 'fast' was accepted";
    } catch (const core::InputError& e) {
      EXPECT_EQ(e.option(), key);
      EXPECT_NE(e.problem().find("'fast'"), std::string::npos) << e.problem();
    }
  }
}

// An initial arm for an antenna that is not estimated needs the data to be found: run names it.
TEST_F(LeverarmGnss, InitialArmOfAnUnknownAntennaIsAnOptionError) {
  LeverarmGnssRequest q = reference_request({"gnss1"});
  q.method = LeverarmGnssMethod::kLuenberger;
  q.init = {{"gnss2", Eigen::Vector3d(0, 0, -13)}};
  try {
    run_leverarm_gnss(q);
    FAIL() << "an initial arm of gnss2 was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "init");
  }
}

TEST_F(LeverarmGnss, JsonHasTheDocumentedKeys) {
  LeverarmGnssRequest q = reference_request({"gnss1", "gnss2"});
  q.method = LeverarmGnssMethod::kAdaptive;
  const nlohmann::json j = to_json(run_leverarm_gnss(q));
  for (const char* key : {"method", "arms", "arms_frame", "interval_s", "p0", "excitation",
                          "adaptive_gamma", "time_offset_s", "time_offset_estimated",
                          "time_offset_std_s", "residual_rms_m", "epochs", "notes", "log"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["method"], "adaptive");
  EXPECT_EQ(j["log"], (trial() / "truth.csv").string());
  ASSERT_EQ(j["arms"].size(), 2U);
  for (const char* key :
       {"name", "x", "y", "z", "std", "determined", "interval_mean", "interval_std"})
    EXPECT_TRUE(j["arms"][0].contains(key)) << key;
  for (const char* key : {"rank3_fraction", "pe_window_min_eig_rad2ps", "gramian_condition",
                          "predicted_arm_std_m", "verdict", "advice"})
    EXPECT_TRUE(j["excitation"].contains(key)) << key;
  EXPECT_TRUE(j["time_offset_std_s"].is_null());  // not estimated
  // The adaptive gain chosen from the data is noted; the motion's notes follow.
  ASSERT_FALSE(j["notes"].empty());
  EXPECT_NE(j["notes"][0].get<std::string>().find("adaptive gain"), std::string::npos);
}

TEST_F(LeverarmGnss, LogShorterThanOneExcitationWindowNamesTheWindow) {
  LeverarmGnssRequest q = reference_request({"gnss1"});
  q.pe_window = 500.0;
  try {
    run_leverarm_gnss(q);
    FAIL() << "a 200 s log was accepted with a 500 s window";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "pe_window");
    EXPECT_EQ(e.where().file, (trial() / "truth.csv").string());
  }
}

TEST_F(LeverarmGnss, DemoSectionComparesWithTheTruth) {
  const ReportSection s = leverarm_gnss_demo_section(dir_);
  EXPECT_EQ(s.title, "GNSS lever arms (turning circle)");
  EXPECT_NE(s.markdown.find("x true [m]"), std::string::npos);
  EXPECT_NE(s.markdown.find("| ins "), std::string::npos);  // the logger-only rows
  const std::filesystem::path out = dir_ / "analysis" / "leverarm";
  for (const char* f : {"gnss.json", "arm-gnss1.svg", "arm-gnss3.svg", "p0-ne.svg",
                        "excitation.svg", "gnss-ins.json", "residuals.svg"})
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  EXPECT_EQ(leverarm_gnss_demo_section(dir_ / "no-campaign").title, "");
}

}  // namespace
}  // namespace dynpos::analysis
