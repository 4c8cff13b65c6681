#include "dynpos/analysis/step.hpp"

#include <fmt/core.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../ident/synthetic.hpp"
#include "../io/io_test_util.hpp"
#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/csv_reader.hpp"

namespace dynpos::analysis {
namespace {

using io::testing::TempDir;
using ::testing::HasSubstr;

// The analytic FOPDT (3.7) with K = 2, T = 3 s, δ = 1 s, sampled at 10 Hz over 70 s: the input
// steps 0 → 1 at 10 s and 1 → 0.5 at 40 s, the output is the sum of both step responses.
constexpr double kGain = 2.0, kTimeConstant = 3.0, kDeadTime = 1.0;

std::string fopdt_csv(double origin_s = 0.0) {
  const auto response = [](double t, double t_step, double du) {
    const double s = t - t_step - kDeadTime;
    return s > 0.0 ? kGain * du * (1.0 - std::exp(-s / kTimeConstant)) : 0.0;
  };
  std::string csv = "time [s],cmd [1],response [m],u [m/s],v [m/s]\n";
  for (int k = 0; k <= 700; ++k) {
    const double t = 0.1 * k;
    const double u = t < 10.0 ? 0.0 : (t < 40.0 ? 1.0 : 0.5);
    const double y = response(t, 10.0, 1.0) + response(t, 40.0, -0.5);
    // Sway-test shape for --derive total-speed: √(u² + v²) = y with u = 0.6·y, v = 0.8·y.
    csv += fmt::format("{:.1f},{},{:.12g},{:.12g},{:.12g}\n", origin_s + t, u, y, 0.6 * y, 0.8 * y);
  }
  return csv;
}

StepRequest request_for(const std::filesystem::path& log) {
  StepRequest r;
  r.source.log = log;
  r.source.columns = {"input=cmd", "output=response"};
  return r;
}

// The request key of the InputError `f` throws, and its message.
template <class F>
std::pair<std::string, std::string> option_error_of(F&& f) {
  try {
    f();
  } catch (const core::InputError& e) {
    return {e.option(), e.what()};
  }
  ADD_FAILURE() << "expected a core::InputError";
  return {};
}

TEST(RunStep, LeastSquaresRecoversBothStepsOfAnAnalyticLog) {
  const TempDir dir;
  const StepReport report = run_step(request_for(dir.write("steps.csv", fopdt_csv())));
  EXPECT_EQ(report.method, StepMethod::kLeastSquares);
  EXPECT_EQ(report.timing, StepTimingSource::kCommand);
  EXPECT_EQ(report.output_unit, "m");
  ASSERT_TRUE(report.input_unit.has_value());
  ASSERT_EQ(report.steps.size(), 2u);
  EXPECT_NEAR(report.steps[0].step.t_step, 10.0, 1e-9);
  EXPECT_NEAR(report.steps[1].step.t_step, 40.0, 1e-9);
  for (const StepFit& fit : report.steps) {
    EXPECT_EQ(fit.status, core::Status::kOk) << fit.message;
    // Noise-free data at 10 Hz: least squares recovers K, T and δ to well within 1 % (the
    // first response is within K·e^{−29/3} ≈ 1.3·10⁻⁴ of its level when the second starts).
    ASSERT_TRUE(fit.gain && fit.time_constant_s && fit.dead_time_s);
    EXPECT_NEAR(*fit.gain, kGain, 0.02);
    EXPECT_NEAR(*fit.time_constant_s, kTimeConstant, 0.03);
    EXPECT_NEAR(*fit.dead_time_s, kDeadTime, 0.01);
    EXPECT_TRUE(fit.fopdt.has_value());
    EXPECT_FALSE(fit.second_order.has_value());
  }
  // y after the second step: K·0.5 = 1.
  ASSERT_TRUE(report.steps[1].y_after);
  EXPECT_NEAR(*report.steps[1].y_after, 1.0, 0.01);
}

// A clock with a huge origin (seconds since year 1, MATLAB datenum × 86400: 6.4·10¹⁰ s) gives
// the fits of a clock from 0. Its stamps round to 7.6 µs, 8·10⁻⁵ of the 0.1 s spacing: K, T
// and δ agree to 10⁻³ (they failed before, the windows widened by 64 s into the other step).
TEST(RunStep, AHugeClockOriginGivesTheSameFits) {
  const TempDir dir;
  constexpr double kOrigin = 6.4e10;
  const StepReport zero = run_step(request_for(dir.write("zero.csv", fopdt_csv())));
  const StepReport huge = run_step(request_for(dir.write("huge.csv", fopdt_csv(kOrigin))));
  ASSERT_EQ(huge.steps.size(), zero.steps.size());
  for (std::size_t i = 0; i < huge.steps.size(); ++i) {
    const StepFit& a = zero.steps[i];
    const StepFit& b = huge.steps[i];
    EXPECT_EQ(b.status, core::Status::kOk) << b.message;
    EXPECT_NEAR(b.step.t_step - kOrigin, a.step.t_step, 1e-4);
    ASSERT_TRUE(b.gain && b.time_constant_s && b.dead_time_s);
    EXPECT_NEAR(*b.gain, *a.gain, 1e-3);
    EXPECT_NEAR(*b.time_constant_s, *a.time_constant_s, 1e-3);
    EXPECT_NEAR(*b.dead_time_s, *a.dead_time_s, 1e-3);
  }
}

TEST(RunStep, SecondOrderMethodsReportTheirOwnDetails) {
  const TempDir dir;
  StepRequest r = request_for(dir.write("steps.csv", fopdt_csv()));
  r.method = StepMethod::kRangaiahKrishnaswamy;
  const StepReport report = run_step(r);
  ASSERT_EQ(report.steps.size(), 2u);
  EXPECT_FALSE(report.steps[0].fopdt.has_value());
  ASSERT_TRUE(report.steps[0].second_order.has_value());
  EXPECT_EQ(report.steps[0].time_constant_s, report.steps[0].second_order->time_constant_1_s);
}

TEST(RunStep, WindowGivesOneStep) {
  const TempDir dir;
  StepRequest r = request_for(dir.write("steps.csv", fopdt_csv()));
  r.from_s = 30.0;
  r.to_s = 70.0;
  const StepReport report = run_step(r);
  ASSERT_EQ(report.steps.size(), 1u);
  EXPECT_NEAR(report.steps[0].step.t_step, 40.0, 1e-9);
  ASSERT_TRUE(report.steps[0].gain);
  EXPECT_NEAR(*report.steps[0].gain, kGain, 0.02);
}

TEST(RunStep, AWindowIsAllThatIsRead) {
  // Finding M2 of the reliability review: with --from/--to only the window's rows are read
  // (301 of the 701), and the step in it is the one the whole log holds.
  const TempDir dir;
  StepRequest r = request_for(dir.write("steps.csv", fopdt_csv()));
  r.from_s = 30.0;
  r.to_s = 60.0;
  const StepReport windowed = run_step(r);
  ASSERT_EQ(windowed.input.files.size(), 1u);
  EXPECT_EQ(windowed.input.files[0].records, 301u);
  ASSERT_EQ(windowed.steps.size(), 1u);
  EXPECT_NEAR(windowed.steps[0].step.t_step, 40.0, 1e-9);
  EXPECT_EQ(windowed.steps[0].step.t_end, 60.0);
  ASSERT_TRUE(windowed.steps[0].gain && windowed.steps[0].time_constant_s);
  EXPECT_NEAR(*windowed.steps[0].gain, kGain, 0.02);
  EXPECT_NEAR(*windowed.steps[0].time_constant_s, kTimeConstant, 0.05 * kTimeConstant);
  // A log taken whole (in memory, or an NMEA capture) is cut to the window: the same result.
  StepRequest in_memory = r;
  in_memory.source.memory =
      std::make_shared<const core::Log>(io::read_csv_all(r.source.log, {}, {}));
  nlohmann::json a = to_json(windowed), b = to_json(run_step(in_memory));
  for (nlohmann::json* j : {&a, &b}) {
    j->erase("input");
    j->erase("log");
  }
  EXPECT_EQ(a.dump(), b.dump());
  // One end past the log: no row in the window (LogSource's one message, key "from/to"),
  // however the log was read.
  in_memory.from_s = 500.0;
  in_memory.to_s.reset();
  auto [key, what] = option_error_of([&] { run_step(in_memory); });
  EXPECT_EQ(key, "from/to");
  EXPECT_THAT(what, HasSubstr("the window from 500 s on starts after the log's last row at 70 s"));
  in_memory.from_s.reset();
  in_memory.to_s = -5.0;
  std::tie(key, what) = option_error_of([&] { run_step(in_memory); });
  EXPECT_EQ(key, "from/to");
  EXPECT_THAT(what, HasSubstr("the window up to -5 s ends before the log's first row at 0 s"));
  r.from_s.reset();
  r.to_s = -5.0;  // the same when the reading stops at the log's first row
  std::tie(key, what) = option_error_of([&] { run_step(r); });
  EXPECT_EQ(key, "from/to");
  EXPECT_THAT(what, HasSubstr("the window up to -5 s ends before the log's first row at 0 s"));
  // A window between two rows holds none; one reaching past the end is outside the log.
  r.from_s = 30.01;
  r.to_s = 30.02;
  std::tie(key, what) = option_error_of([&] { run_step(r); });
  EXPECT_EQ(key, "from/to");
  EXPECT_THAT(
      what,
      HasSubstr(
          "the window 30.01 … 30.02 s falls between two rows of the log (the next at 30.1 s)"));
  r.from_s = 65.0;
  r.to_s = 80.0;
  std::tie(key, what) = option_error_of([&] { run_step(r); });
  EXPECT_EQ(key, "from/to");
  EXPECT_THAT(what, HasSubstr("window [65, 80] s is outside the log [0, 70] s"));
}

TEST(RunStep, WindowErrorsAreTheLogSourcesForEveryAnalysis) {
  // The step analysis' window errors are LogSource::load's: the same message any windowed
  // analysis gives for the same log and window (an empty window, one without a row).
  const TempDir dir;
  StepRequest r = request_for(dir.write("steps.csv", fopdt_csv()));
  for (const auto& [from, to] : {std::pair{40.0, 30.0}, {30.01, 30.02}, {100.0, 200.0}}) {
    r.from_s = from;
    r.to_s = to;
    LogSource source = r.source;
    source.window_from_s = from;
    source.window_to_s = to;
    const auto step_error = option_error_of([&] { run_step(r); });
    const auto source_error =
        option_error_of([&] { source.load([](const std::string&) { return false; }); });
    EXPECT_EQ(step_error.first, "from/to");
    EXPECT_EQ(step_error, source_error);
    EXPECT_THAT(step_error.second, HasSubstr(r.source.log.string()));
  }
}

TEST(RunStep, TotalSpeedIsDerivedFromUAndV) {
  const TempDir dir;
  StepRequest r;
  r.source.log = dir.write("steps.csv", fopdt_csv());
  r.source.columns = {"input=cmd"};
  r.derive = StepDerive::kTotalSpeed;
  const StepReport report = run_step(r);
  EXPECT_EQ(report.output_unit, "m/s");
  ASSERT_EQ(report.steps.size(), 2u);
  ASSERT_TRUE(report.steps[0].time_constant_s);
  EXPECT_NEAR(*report.steps[0].time_constant_s, kTimeConstant, 0.03);
}

TEST(StepRequest, ValidateNamesTheBadKey) {
  StepRequest r;
  r.min_plateau_s = 0.0;
  auto [key, what] = option_error_of([&] { r.validate(); });
  EXPECT_EQ(key, "min_plateau");
  EXPECT_THAT(what, HasSubstr("the shortest plateau must be > 0 s"));
  r.min_plateau_s = 3.0;
  r.step_at_s = std::nan("");
  std::tie(key, what) = option_error_of([&] { r.validate(); });
  EXPECT_EQ(key, "step_at");
  r.step_at_s.reset();
  r.method = StepMethod::kSmith;
  r.derive = StepDerive::kTotalSpeed;
  EXPECT_NO_THROW(r.validate());
}

TEST(StepRequest, MethodsAndDerivedOutputsHaveTheirNames) {
  for (const auto& [name, method] : step_method_names()) EXPECT_EQ(to_string(method), name);
  EXPECT_EQ(to_string(StepMethod::kLeastSquares), "lsq");
  EXPECT_EQ(to_string(StepMethod::kRangaiahKrishnaswamy), "rk");
  EXPECT_EQ(to_string(StepDerive::kTotalSpeed), "total-speed");
  EXPECT_EQ(to_string(StepDerive::kNone), "");
  EXPECT_EQ(step_method_names().size(), 4u);
}

TEST(RunStep, MissingColumnsAreNamedByTheirRole) {
  const TempDir dir;
  const auto log = dir.write("steps.csv", fopdt_csv());
  StepRequest r = request_for(log);
  r.source.columns = {"input=cmd"};
  EXPECT_EQ(option_error_of([&] { run_step(r); }).first, "col:output");
  r.source.columns = {"output=response"};
  EXPECT_EQ(option_error_of([&] { run_step(r); }).first, "col:input");
  // A column the log does not have is an error in the file, named by it.
  r.source.columns = {"input=cmd", "output=no_such_column"};
  EXPECT_THAT(option_error_of([&] { run_step(r); }).second, HasSubstr("no_such_column"));
}

TEST(StepReport, JsonHasTheContractKeys) {
  const TempDir dir;
  const nlohmann::json doc = to_json(run_step(request_for(dir.write("s.csv", fopdt_csv()))));
  for (const char* key : {"log", "method", "output_unit", "input_unit", "timing", "step_threshold",
                          "step_threshold_source", "input_noise_sigma", "notes", "steps"}) {
    EXPECT_TRUE(doc.contains(key)) << key;
  }
  EXPECT_EQ(doc["timing"], "command");
  ASSERT_EQ(doc["steps"].size(), 2u);
  const nlohmann::json& step = doc["steps"][0];
  for (const char* key :
       {"t_step", "t_end", "u_before", "u_after", "y_before", "y_after", "K", "T", "delay",
        "r_squared", "status", "warnings", "sigma", "K_levels", "rms_residual"}) {
    EXPECT_TRUE(step.contains(key)) << key;
  }
  EXPECT_FALSE(step.contains("T1"));
  EXPECT_EQ(step["status"], "ok");
  EXPECT_NEAR(step["T"].get<double>(), kTimeConstant, 0.03);
  EXPECT_TRUE(step["sigma"]["T"].is_number());
}

// A sea-trial order log at 2 Hz: orders [deg, written as plain numbers] that ramp over
// `ramp_s`, an output that is the FOPDT (3.7) response to the order as ramped (K, T, δ), with
// white noise, and optional held wiggles of the order (±wiggle, redrawn every 5 s, which the
// output follows too). The response is integrated exactly for an input held over 0.01 s steps.
struct Order {
  double at;  // [s] start of the ramp
  double to;  // new level
};

struct TrialLog {
  std::vector<Order> orders;
  double duration_s = 5400.0;
  double ramp_s = 2.0;  // four samples at 2 Hz
  double gain = 0.5, time_constant_s = 8.0, dead_time_s = 1.0;
  double noise = 0.05;
  double wiggle = 0.0;
  double missing_from_s = -1.0, missing_to_s = -1.0;  // output not logged in between

  double order(double t) const {
    double u = 0.0;
    double from = 0.0;
    for (const Order& o : orders) {
      if (t < o.at) break;
      u = from + (o.to - from) * std::min((t - o.at) / ramp_s, 1.0);
      from = o.to;
    }
    return u;
  }

  std::string csv(std::uint64_t seed) const {
    ident::testing::Normal rng(seed);
    std::string text = "time [s],order [1],response [1]\n";
    double y = 0.0;
    double offset = 0.0;
    const double dt = 0.01;
    const double a = 1.0 - std::exp(-dt / time_constant_s);
    for (int k = 0; 0.5 * k <= duration_s; ++k) {
      const double t = 0.5 * k;
      if (k % 10 == 0) offset = wiggle * (2.0 * rng.uniform() - 1.0);
      const auto held = [&](double x) {
        const bool ramping = std::any_of(orders.begin(), orders.end(), [&](const Order& o) {
          return x >= o.at && x <= o.at + ramp_s + 0.5;
        });
        return order(x) + (ramping ? 0.0 : offset);
      };
      const std::string out = t >= missing_from_s && t < missing_to_s
                                  ? std::string("")
                                  : fmt::format("{:.6f}", y + noise * rng());
      text += fmt::format("{:.1f},{:.4f},{}\n", t, held(t), out);
      for (int j = 0; j < 50; ++j) y += a * (gain * held(t + j * dt - dead_time_s) - y);
    }
    return text;
  }
};

// Twenty orders in 1.5 h, one every 270 s: a zig-zag of ±35°, turning orders of ±20° and 10°
// steps from several baselines.
std::vector<Order> twenty_orders() {
  const double levels[] = {35, -35, 35, -35, 0,   20,  -20, 0, 10, 20,
                           30, 20,  10, 0,   -10, -30, -35, 0, 25, 0};
  std::vector<Order> orders;
  for (int k = 0; k < 20; ++k) orders.push_back({150.0 + 270.0 * k, levels[k]});
  return orders;
}

StepRequest trial_request(const std::filesystem::path& log) {
  StepRequest r;
  r.source.log = log;
  r.source.columns = {"input=order", "output=response"};
  return r;
}

TEST(RunStep, EveryStepOfAnHourAndAHalfLogIsFoundSortedAndFitted) {
  TrialLog trial;
  trial.orders = twenty_orders();
  trial.wiggle = 0.5;
  const TempDir dir;
  const StepReport report = run_step(trial_request(dir.write("trial.csv", trial.csv(11))));
  // The largest change, 70°, sets the threshold to 3.5°; the wiggles move 1° at most.
  ASSERT_TRUE(report.step_threshold);
  EXPECT_NEAR(*report.step_threshold, 3.5, 0.1);
  EXPECT_FALSE(report.threshold_from_min_step);
  ASSERT_EQ(report.steps.size(), 20u);
  for (std::size_t k = 0; k < 20; ++k) {
    const StepFit& fit = report.steps[k];
    SCOPED_TRACE(fit.step.t_step);
    if (k > 0) {
      EXPECT_LT(report.steps[k - 1].step.t_step, fit.step.t_step);
    }
    // Timed at the ramp's start, within one sample.
    EXPECT_NEAR(fit.step.t_step, trial.orders[k].at, 0.5);
    ASSERT_EQ(fit.status, core::Status::kOk) << fit.message;
    // The held wiggles (±0.5°, σ = 0.29°) move the order's levels, medians of 12 of them in the
    // 60 s next to the step, by about 0.1° each, and the output's levels through the response
    // alike: K within 0.3°/|Δu| (two of those σ's, 6 % for the 5° order) + 1 % (the output
    // noise); T within 10 %. The 2 s ramp
    // delays the response by its mid-point, 1 s, which the dead time takes up: δ = 1 + 1 s, within
    // one sample (0.5 s): the wiggles shift the levels a 10° ramp is timed against by up to 5 % of
    // it (0.1 s), and the output's response to them is up to 5 % of the smallest Δy (measured: 0.39
    // s at most).
    EXPECT_NEAR(*fit.gain, trial.gain, trial.gain * (0.01 + 0.3 / std::abs(*fit.step.delta_u())));
    EXPECT_NEAR(*fit.time_constant_s, trial.time_constant_s, 0.1 * trial.time_constant_s);
    EXPECT_NEAR(*fit.dead_time_s, trial.dead_time_s + 0.5 * trial.ramp_s, 0.5);
  }
}

TEST(RunStep, MinStepOverridesTheAdaptedThreshold) {
  // Of the twenty orders, nine change by 25° or more; the others are not steps (their levels
  // are one), and nothing below --min-step is reported.
  TrialLog trial;
  trial.orders = twenty_orders();
  const TempDir dir;
  StepRequest r = trial_request(dir.write("trial.csv", trial.csv(16)));
  r.min_step = 25.0;
  const StepReport report = run_step(r);
  EXPECT_TRUE(report.threshold_from_min_step);
  ASSERT_TRUE(report.step_threshold);
  EXPECT_EQ(*report.step_threshold, 25.0);
  ASSERT_EQ(report.steps.size(), 9u);
  for (const StepFit& fit : report.steps) EXPECT_GE(std::abs(*fit.step.delta_u()), 25.0);
  EXPECT_EQ(to_json(report)["step_threshold_source"], "min_step");
}

TEST(RunStep, AWindowAroundOneWiggledOrderHasOneStep) {
  // 100 s around the order from 35° to −35° at 420 s, with ±1° held wiggles before and after:
  // the whole log's threshold (3.5°) applies in the window, so the wiggles are not steps.
  TrialLog trial;
  trial.orders = twenty_orders();
  trial.wiggle = 1.0;
  const TempDir dir;
  StepRequest r = trial_request(dir.write("trial.csv", trial.csv(17)));
  r.from_s = 370.0;
  r.to_s = 470.0;
  const StepReport report = run_step(r);
  ASSERT_EQ(report.steps.size(), 1u);
  EXPECT_NEAR(report.steps[0].step.t_step, 420.0, 0.5);
  EXPECT_EQ(report.steps[0].status, core::Status::kOk) << report.steps[0].message;
}

TEST(RunStep, ARampOverFourSamplesIsOneStepWithTheRightGainAndTimeConstant) {
  // One 30° order ramped over four 2 Hz samples, the output noise 1 % of Δy = 15.
  TrialLog trial;
  trial.orders = {{100.4, 30.0}};
  trial.duration_s = 300.0;
  trial.noise = 0.15;
  const TempDir dir;
  const StepReport report = run_step(trial_request(dir.write("ramp.csv", trial.csv(12))));
  ASSERT_EQ(report.steps.size(), 1u);
  const StepFit& fit = report.steps[0];
  ASSERT_EQ(fit.status, core::Status::kOk) << fit.message;
  EXPECT_NEAR(fit.step.t_step, 100.4, 1e-6);  // the ramp samples are exact
  // 600 samples with σ = 1 % of Δy: K within 2 %, T within 5 % (about 5 of their σ's);
  // δ takes up half the ramp, as above.
  EXPECT_NEAR(*fit.gain, 0.5, 0.01);
  EXPECT_NEAR(*fit.time_constant_s, 8.0, 0.4);
  EXPECT_NEAR(*fit.dead_time_s, 2.0, 0.3);
}

TEST(RunStep, AStepThatCannotBeFittedIsARowAndTheRunGoesOn) {
  // The output logger drops out 2 s after the second order until the third: four valid
  // samples after that step.
  TrialLog trial;
  trial.orders = {{100.0, 20.0}, {400.0, -20.0}, {700.0, 0.0}};
  trial.duration_s = 1000.0;
  trial.missing_from_s = 402.0;
  trial.missing_to_s = 700.0;
  const TempDir dir;
  const StepReport report = run_step(trial_request(dir.write("gap.csv", trial.csv(13))));
  ASSERT_EQ(report.steps.size(), 3u);
  EXPECT_EQ(report.steps[0].status, core::Status::kOk) << report.steps[0].message;
  EXPECT_EQ(report.steps[1].status, core::Status::kFailed);
  EXPECT_THAT(report.steps[1].message, HasSubstr("too short"));
  EXPECT_FALSE(report.steps[1].gain.has_value());
  EXPECT_EQ(report.steps[2].status, core::Status::kOk) << report.steps[2].message;
  const nlohmann::json doc = to_json(report);
  EXPECT_EQ(doc["steps"][1]["status"], "failed");
  EXPECT_THAT(doc["steps"][1]["message"].get<std::string>(), HasSubstr("too short"));
  EXPECT_THAT(to_text(report), HasSubstr("failed: step too short"));
}

TEST(RunStep, SegmentsNameAndLimitTheSteps) {
  // The fixture names three stretches: the zig-zag orders at 420 and 690 s, the order at
  // 1 230 s and a stretch without an order; the other seventeen orders are outside them.
  TrialLog trial;
  trial.orders = twenty_orders();
  const TempDir dir;
  StepRequest r = trial_request(dir.write("trial.csv", trial.csv(14)));
  r.segments_file = std::filesystem::path(DYNPOS_SOURCE_DIR) / "tests/data/step_segments.csv";
  const StepReport report = run_step(r);
  ASSERT_EQ(report.steps.size(), 3u);
  EXPECT_EQ(report.steps[0].segment, "zigzag 35/35");
  EXPECT_EQ(report.steps[1].segment, "zigzag 35/35");
  EXPECT_EQ(report.steps[2].segment, "turn stb");
  EXPECT_NEAR(report.steps[2].step.t_step, 1230.0, 0.5);
  // The first order of a segment has the segment's start as its window start.
  EXPECT_GE(report.steps[0].step.t_begin, 250.0);
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_THAT(report.notes[0], HasSubstr("drift check"));
  const nlohmann::json doc = to_json(report);
  EXPECT_EQ(doc["steps"][2]["segment"], "turn stb");
  EXPECT_THAT(to_text(report), HasSubstr("zigzag 35/35"));
}

TEST(RunStep, NoStepIsAnEmptyReportWithTheReason) {
  TrialLog trial;
  trial.duration_s = 300.0;
  const TempDir dir;
  const StepReport report = run_step(trial_request(dir.write("flat.csv", trial.csv(15))));
  EXPECT_TRUE(report.steps.empty());
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_THAT(report.notes[0], HasSubstr("constant input"));
}

TEST(RunStep, ErrorsFromInsideTheAnalysisNameTheLog) {
  const TempDir dir;
  const auto log = dir.write("steps.csv", fopdt_csv());
  StepRequest r = request_for(log);
  r.from_s = 100.0;
  r.to_s = 200.0;
  EXPECT_THAT(option_error_of([&] { run_step(r); }).second,
              HasSubstr(log.string() +
                        " (from/to): the window 100 … 200 s starts after the log's last row"));
  // A bad segment file is named with its line and column.
  r = request_for(log);
  r.segments_file = dir.write("segments.csv", "name,start,end\nfirst,10,20\nsecond,30,x\n");
  EXPECT_THAT(option_error_of([&] { run_step(r); }).second,
              HasSubstr(r.segments_file.string() + ":3:3"));
}

// A log without a step is a result, not an error (exit 0): the text says so in words, with
// what to try, instead of a table without rows.
TEST(StepReport, TextSaysWhenNoStepWasFound) {
  const TempDir dir;
  StepRequest r = request_for(dir.write("s.csv", fopdt_csv()));
  r.min_step = 10.0;  // both steps (1 and 0.5) are below it
  const StepReport report = run_step(r);
  ASSERT_TRUE(report.steps.empty());
  const std::string text = to_text(report);
  EXPECT_THAT(text, HasSubstr("no step found: constant input: it varies by 1, less than the "
                              "step threshold 10; lower --min-step, or give the step with "
                              "--from/--to/--step-at\n"));
  EXPECT_THAT(text, ::testing::Not(HasSubstr("t_step")));
}

TEST(StepReport, TextHasAHeaderAndARowPerStep) {
  const TempDir dir;
  StepRequest r = request_for(dir.write("s.csv", fopdt_csv()));
  r.method = StepMethod::kSmith;
  const std::string text = to_text(run_step(r));
  EXPECT_THAT(text, HasSubstr("2 step(s), method smith, output in m (SI)"));
  EXPECT_THAT(text, HasSubstr("t_step"));
  EXPECT_THAT(text, HasSubstr("   10.00 "));
  EXPECT_THAT(text, HasSubstr("   40.00 "));
}

}  // namespace
}  // namespace dynpos::analysis
