#include "dynpos/analysis/step.hpp"

#include <fmt/core.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../io/io_test_util.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::analysis {
namespace {

using io::testing::TempDir;
using ::testing::HasSubstr;

// The analytic FOPDT (3.7) with K = 2, T = 3 s, δ = 1 s, sampled at 10 Hz over 70 s: the input
// steps 0 → 1 at 10 s and 1 → 0.5 at 40 s, the output is the sum of both step responses.
constexpr double kGain = 2.0, kTimeConstant = 3.0, kDeadTime = 1.0;

std::string fopdt_csv() {
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
    csv += fmt::format("{:.1f},{},{:.12g},{:.12g},{:.12g}\n", t, u, y, 0.6 * y, 0.8 * y);
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
  EXPECT_EQ(report.method, "lsq");
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

TEST(RunStep, SecondOrderMethodsReportTheirOwnDetails) {
  const TempDir dir;
  StepRequest r = request_for(dir.write("steps.csv", fopdt_csv()));
  r.method = "rk";
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

TEST(RunStep, TotalSpeedIsDerivedFromUAndV) {
  const TempDir dir;
  StepRequest r;
  r.source.log = dir.write("steps.csv", fopdt_csv());
  r.source.columns = {"input=cmd"};
  r.derive = "total-speed";
  const StepReport report = run_step(r);
  EXPECT_EQ(report.output_unit, "m/s");
  ASSERT_EQ(report.steps.size(), 2u);
  ASSERT_TRUE(report.steps[0].time_constant_s);
  EXPECT_NEAR(*report.steps[0].time_constant_s, kTimeConstant, 0.03);
}

TEST(StepRequest, ValidateNamesTheBadKey) {
  StepRequest r;
  r.method = "fast";
  auto [key, what] = option_error_of([&] { r.validate(); });
  EXPECT_EQ(key, "method");
  EXPECT_THAT(what, HasSubstr("unknown method 'fast'"));
  r.method = "smith";
  r.derive = "speed";
  std::tie(key, what) = option_error_of([&] { r.validate(); });
  EXPECT_EQ(key, "derive");
  EXPECT_THAT(what, HasSubstr("unknown derived output 'speed'"));
  r.derive = "total-speed";
  EXPECT_NO_THROW(r.validate());
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
  for (const char* key : {"log", "method", "output_unit", "input_unit", "timing", "steps"}) {
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

TEST(StepReport, TextHasAHeaderAndARowPerStep) {
  const TempDir dir;
  StepRequest r = request_for(dir.write("s.csv", fopdt_csv()));
  r.method = "smith";
  const std::string text = to_text(run_step(r));
  EXPECT_THAT(text, HasSubstr("2 step(s), method smith, output in m (SI)"));
  EXPECT_THAT(text, HasSubstr("t_step"));
  EXPECT_THAT(text, HasSubstr("   10.00 "));
  EXPECT_THAT(text, HasSubstr("   40.00 "));
}

}  // namespace
}  // namespace dynpos::analysis
