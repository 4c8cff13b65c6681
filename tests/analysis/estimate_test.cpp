// The estimate and consequence requests, the bias summary, the time series' columns and the
// consequence summary on constructed data (their runs on simulated logs: tests/validation and
// tests/cli).

#include "dynpos/analysis/estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "dynpos/analysis/consequence.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using testing::option_key_of;

TEST(EstimateRequest, NamesTheBadOption) {
  const auto key = [](auto change) {
    EstimateRequest q;
    change(q);
    return option_key_of([&] { q.validate(); });
  };
  EXPECT_EQ(key([](EstimateRequest&) {}), "no error");
  EXPECT_EQ(key([](EstimateRequest& q) { q.observer = "raw"; }), "observer");
  EXPECT_EQ(key([](EstimateRequest& q) { q.observer = "kalman"; }), "observer");
  EXPECT_EQ(key([](EstimateRequest& q) { q.tp_s = 1.0; }), "tp");
  EXPECT_EQ(key([](EstimateRequest& q) { q.tp_s = std::nan(""); }), "tp");
  EXPECT_EQ(key([](EstimateRequest& q) { q.rate_hz = 0.0; }), "rate");
  EXPECT_EQ(key([](EstimateRequest& q) { q.max_hold_s = -1.0; }), "max_hold");
  EXPECT_EQ(key([](EstimateRequest& q) { q.settle_s = -1.0; }), "settle");
  EXPECT_EQ(key([](EstimateRequest& q) { q.vessel = "/no/such/vessel.toml"; }), "vessel");
  EXPECT_EQ(key([](EstimateRequest& q) {
              q.arm_m = Eigen::Vector3d(1.0, std::numeric_limits<double>::infinity(), 0.0);
            }),
            "arm");
  ConsequenceRequest c;
  c.step_s = 0.0;
  EXPECT_EQ(option_key_of([&] { c.validate(); }), "step");
  c.step_s = 10.0;
  c.mean_window_s = -60.0;
  EXPECT_EQ(option_key_of([&] { c.validate(); }), "window");
}

TEST(EstimateRequest, TheRunHoldsThePassiveObserversMeasurementOnly) {
  EstimateRequest q;
  EXPECT_EQ(q.run_options().kind, control::ObserverKind::kEkf);
  EXPECT_FALSE(q.run_options().holds_measurements());
  q.observer = "passive";
  EXPECT_TRUE(q.run_options().holds_measurements());
}

control::ObserverTrack track_of(const std::vector<Eigen::Vector3d>& bias) {
  control::ObserverTrack t;
  for (std::size_t k = 0; k < bias.size(); ++k) {
    t.t_s.push_back(static_cast<double>(k + 1));
    control::ObserverEstimate e;
    e.bias_n = bias[k];
    e.eta_n = {1.0, 2.0, -0.5};  // a heading below zero: written in [0, 360)
    e.nu_b = {0.1, 0.2, 0.01};
    t.estimate.push_back(e);
    t.position_age_s.push_back(0.1 * static_cast<double>(k + 1));
  }
  return t;
}

TEST(SummariseBias, MeanAndStdFromTheSettledSamples) {
  const control::ObserverTrack t =
      track_of({{100.0, 0.0, 0.0}, {1e3, 2e3, 3e3}, {3e3, 2e3, 1e3}, {2e3, 2e3, 2e3}});
  const auto s = summarise_bias(t, 2.0);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->samples, 3u);
  EXPECT_EQ(s->from_s, 2.0);
  EXPECT_EQ(s->to_s, 4.0);
  EXPECT_NEAR(s->mean_n.x(), 2e3, 1e-9);
  EXPECT_NEAR(s->std_n.x(), std::sqrt(2e6 / 3.0), 1e-6);
  EXPECT_NEAR(s->std_n.y(), 0.0, 1e-6);
  EXPECT_FALSE(summarise_bias(t, 4.5).has_value());
}

TEST(EstimateLog, TheColumnsInTheirUnits) {
  const core::Log log = estimate_log(track_of({{1e3, -2e3, 3e4}, {0.0, 0.0, 0.0}}));
  ASSERT_EQ(log.channels().size(), 10u);
  EXPECT_EQ(log.channel("lf.heading").unit, "deg");
  EXPECT_NEAR(log.values("lf.heading")[0], 360.0 - 0.5 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(log.values("lf.r")[0], 0.01 * 180.0 / std::numbers::pi, 1e-12);
  EXPECT_EQ(log.channel("bias.yaw").unit, "kN*m");
  EXPECT_NEAR(log.values("bias.east")[0], -2.0, 1e-12);
  EXPECT_NEAR(log.values("bias.yaw")[0], 30.0, 1e-12);
  EXPECT_EQ(log.channel("position.age").unit, "s");
  EXPECT_EQ(log.values("position.age")[1], 0.2);
}

// Three points of two cases: the summary's smallest margin, fractions and per-case minima.
TEST(SummariseConsequence, TheWorstPointAndTheFractions) {
  ConsequenceReport r;
  r.cases = {"a", "b"};
  const auto point = [](double t, double a, double b, double intact) {
    ConsequencePoint p;
    p.t_s = t;
    p.factors = {a, b};
    p.worst = a <= b ? 0 : 1;
    p.intact = intact;
    return p;
  };
  r.points = {point(10, 2.0, 1.1, 5.0), point(20, 0.8, 3.0, 4.0), point(30, 1.5, 0.9, 6.0)};
  const ConsequenceSummary s = summarise(r);
  EXPECT_EQ(s.smallest, 1u);  // margin −0.2
  EXPECT_DOUBLE_EQ(r.points[s.smallest].margin(), 0.8 - 1.0);
  EXPECT_DOUBLE_EQ(s.fraction_negative, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.fraction_below_reserve, 1.0);  // 1.1, 0.8, 0.9 all < 1.25
  EXPECT_EQ(s.case_min[0], 1u);
  EXPECT_EQ(s.case_min[1], 2u);
  EXPECT_DOUBLE_EQ(s.case_fraction_below_one[0], 1.0 / 3.0);
  EXPECT_EQ(s.intact_min, 1u);
}

}  // namespace
}  // namespace dynpos::analysis
