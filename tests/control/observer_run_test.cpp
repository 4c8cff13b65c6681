#include "dynpos/control/observer_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include "observer_truth.hpp"

namespace dynpos::control {
namespace {

using testing::simulate_truth;
using testing::TruthOptions;
using testing::TruthSample;
using testing::vessel_model;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The truth as a log: every sample's heading and thrust, the position every `gnss_every`
// samples (the others missing).
ObserverInputs log_of(const std::vector<TruthSample>& truth, std::size_t gnss_every = 1) {
  ObserverInputs in;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const TruthSample& s = truth[k];
    const bool fix = k % gnss_every == 0;
    in.t_s.push_back(s.t_s);
    in.north_m.push_back(fix ? s.y_n.x() : kNaN);
    in.east_m.push_back(fix ? s.y_n.y() : kNaN);
    in.heading_rad.push_back(s.y_n.z());
    in.tau_b.push_back(s.tau_b);
  }
  return in;
}

// The mean of b̂ − b over the track's samples with t in [from, to), relative to |b_NE| (N, E)
// and |b_r| [-].
Eigen::Vector3d mean_bias_error(const ObserverTrack& track, const TruthOptions& opt, double from_s,
                                double to_s) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (std::size_t k = 0; k < track.t_s.size(); ++k) {
    if (track.t_s[k] < from_s || track.t_s[k] >= to_s) continue;
    sum += track.estimate[k].bias_n - opt.bias_n;
    ++n;
  }
  const Eigen::Vector3d scale(opt.bias_n.head<2>().norm(), opt.bias_n.head<2>().norm(),
                              std::abs(opt.bias_n.z()));
  return (sum / n).cwiseAbs().cwiseQuotient(scale);
}

TEST(ObserverRun, AtTheInputsRateIsTheObserverSteppedOnEachSample) {
  const ObserverModel model = vessel_model();
  TruthOptions opt;
  opt.duration_s = 60.0;
  const auto truth = simulate_truth(model, opt);
  const ObserverTrack track = run_observer(model, log_of(truth), {});  // EKF at 10 Hz
  EkfObserver ekf(model, EkfObserverTuning{}, truth[0].y_n);
  ASSERT_EQ(track.t_s.size(), truth.size() - 1);
  for (std::size_t k = 0; k + 1 < truth.size(); ++k) {
    ekf.step(truth[k].y_n, truth[k].tau_b, 0.1);
    EXPECT_NEAR(track.t_s[k], truth[k + 1].t_s, 1e-9);
    ASSERT_LT((track.estimate[k].bias_n - ekf.estimate().bias_n).norm(), 1e-9) << k;
  }
  EXPECT_EQ(track.position_steps, truth.size() - 1);
  EXPECT_EQ(track.coasting_steps, 0u);
}

// GNSS at 1 Hz under an observer at 10 Hz: the EKF corrects once per fix, the passive observer
// runs on the held fix; both estimate the bias as they do on a fix every step.
TEST(ObserverRun, EstimatesTheBiasFromOneFixASecond) {
  const ObserverModel model = vessel_model();
  TruthOptions opt;
  opt.duration_s = 900.0;
  const auto truth = simulate_truth(model, opt);
  for (const ObserverKind kind : {ObserverKind::kEkf, ObserverKind::kPassive}) {
    ObserverRunOptions o;
    o.kind = kind;
    const ObserverTrack track = run_observer(model, log_of(truth, 10), o);
    const Eigen::Vector3d error = mean_bias_error(track, opt, 300.0, 900.0);
    std::printf("%s, GNSS at 1 Hz: mean b̂ error over 300–900 s %.2f %.2f %.2f %%\n",
                std::string(observer_name(kind)).c_str(), 100 * error.x(), 100 * error.y(),
                100 * error.z());
    // The observers' own settling short of a bias that does not decay (−b/T, T = 1000 s):
    // 2–3 % (ekf_observer_test, passive_observer_test).
    EXPECT_LT(error.maxCoeff(), 0.05) << observer_name(kind);
    if (kind == ObserverKind::kEkf) {
      EXPECT_EQ(track.position_steps, 900u);  // one per fix (the last fix ends the log)
    } else {
      EXPECT_EQ(track.coasting_steps, 0u);  // held for 1 s < max_hold_s
    }
  }
}

TEST(ObserverRun, CoastsThroughAGnssDropoutAndHoldsTheThrust) {
  const ObserverModel model = vessel_model();
  TruthOptions opt;
  opt.duration_s = 200.0;
  const auto truth = simulate_truth(model, opt);
  ObserverInputs in = log_of(truth);
  for (std::size_t k = 1000; k < 1300; ++k) in.north_m[k] = in.east_m[k] = kNaN;  // 100–130 s
  for (std::size_t k = 500; k < 600; ++k) in.tau_b[k].x() = kNaN;  // 50–60 s: no complete τ
  ObserverRunOptions o;
  o.kind = ObserverKind::kPassive;  // held measurement: the dropout's first 5 s are bridged
  o.max_hold_s = 5.05;              // clear of the 0.1 s grid
  const ObserverTrack track = run_observer(model, in, o);
  EXPECT_EQ(track.coasting_steps, 250u);     // 105–130 s
  EXPECT_EQ(track.stale_thrust_steps, 50u);  // 55–60 s, on the τ of 49.9 s
  // Each estimate's position age: a step while the 10 Hz fixes come; through the dropout the
  // time since the fix of 99.9 s, 30.1 s at the estimate of 130 s (the step from 129.9 s).
  ASSERT_EQ(track.position_age_s.size(), track.t_s.size());
  for (std::size_t k = 0; k < track.t_s.size(); ++k) {
    const double t = track.t_s[k];
    const double expected = t > 100.0 + 1e-6 && t < 130.0 + 1e-6 ? t - 99.9 : 0.1;
    ASSERT_NEAR(track.position_age_s[k], expected, 1e-9) << "t " << t;
  }
  for (const ObserverEstimate& e : track.estimate) ASSERT_TRUE(e.eta_n.allFinite());
}

// A τ row made of a unit's sample held from earlier is as old as that sample: with every row
// of 50–60 s built from the sample of 49.9 s, the steps from 55 s on are stale, as when the
// rows are missing.
TEST(ObserverRun, ThrustIsAsOldAsTheOldestSampleOfItsRow) {
  const ObserverModel model = vessel_model();
  TruthOptions opt;
  opt.duration_s = 80.0;
  ObserverInputs in = log_of(simulate_truth(model, opt));
  in.tau_sampled_s = in.t_s;
  for (std::size_t k = 500; k < 600; ++k) {
    in.tau_b[k] = in.tau_b[499];
    in.tau_sampled_s[k] = in.t_s[499];
  }
  ObserverRunOptions o;
  o.kind = ObserverKind::kPassive;
  o.max_hold_s = 5.05;
  EXPECT_EQ(run_observer(model, in, o).stale_thrust_steps, 50u);
  in.tau_sampled_s.clear();  // the rows' own times: never stale
  EXPECT_EQ(run_observer(model, in, o).stale_thrust_steps, 0u);
}

TEST(ObserverRun, StartsAtTheFirstTimeWithEveryInput) {
  const ObserverModel model = vessel_model();
  TruthOptions opt;
  opt.duration_s = 20.0;
  ObserverInputs in = log_of(simulate_truth(model, opt));
  for (std::size_t k = 0; k < 25; ++k) in.heading_rad[k] = kNaN;
  const ObserverTrack track = run_observer(model, in, {});
  EXPECT_NEAR(track.start_s, 2.5, 1e-12);
  EXPECT_NEAR(track.t_s.front(), 2.6, 1e-12);
  EXPECT_NEAR(track.estimate.front().eta_n.z(), in.heading_rad[25], 0.01);
}

TEST(ObserverRun, RejectsBadInputsAndOptions) {
  const ObserverModel model = vessel_model();
  TruthOptions opt;
  opt.duration_s = 10.0;
  const ObserverInputs good = log_of(simulate_truth(model, opt));
  ObserverInputs shorter = good;
  shorter.east_m.pop_back();
  EXPECT_THROW(run_observer(model, shorter, {}), std::invalid_argument);
  ObserverInputs backwards = good;
  backwards.t_s[5] = backwards.t_s[4];
  EXPECT_THROW(run_observer(model, backwards, {}), std::invalid_argument);
  ObserverInputs no_heading = good;
  for (double& h : no_heading.heading_rad) h = kNaN;
  EXPECT_THROW(run_observer(model, no_heading, {}), std::invalid_argument);
  ObserverRunOptions o;
  o.kind = ObserverKind::kRaw;
  EXPECT_THROW(run_observer(model, good, o), std::invalid_argument);
  o = {};
  o.rate_hz = 0.0;
  EXPECT_THROW(run_observer(model, good, o), std::invalid_argument);
  o = {};
  o.max_hold_s = kNaN;
  EXPECT_THROW(run_observer(model, good, o), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::control
