#include "dynpos/sim/simulator.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/sim/log_recorder.hpp"
#include "dynpos/sim/noise.hpp"

#include "allocation_counter.hpp"

using dynpos::test::g_allocations;

namespace dynpos::sim {
namespace {

using ::testing::HasSubstr;

// ẋ = u: an integrator of its held input.
class Integrator final : public HybridSystem {
 public:
  Eigen::Index state_size() const override { return 1; }
  Eigen::Index input_size() const override { return 1; }
  void flow(double, const ConstVectorRef&, const ConstVectorRef& u, VectorRef dxdt) const override {
    dxdt(0) = u(0);
  }
};

// x counts jumps: no flow, always in D, x⁺ = x + 1.
class Counter final : public HybridSystem {
 public:
  Eigen::Index state_size() const override { return 1; }
  void flow(double, const ConstVectorRef&, const ConstVectorRef&, VectorRef dxdt) const override {
    dxdt.setZero();
  }
  bool in_jump_set(double, const ConstVectorRef&, const ConstVectorRef&) const override {
    return true;
  }
  void jump(double, const ConstVectorRef& x, const ConstVectorRef&,
            VectorRef x_plus) const override {
    x_plus(0) = x(0) + 1.0;
  }
};

// The bouncing ball, x = (h, v): C = {h ≥ −slack}, f = (v, −g), D = {h ≤ 0, v < 0},
// g(x) = (h, −e·v), guard γ = h.
class BouncingBall final : public HybridSystem {
 public:
  static constexpr double kGravity = 9.81;
  BouncingBall(double restitution, double flow_set_slack)
      : restitution_(restitution), slack_(flow_set_slack) {}
  Eigen::Index state_size() const override { return 2; }
  void flow(double, const ConstVectorRef& x, const ConstVectorRef&, VectorRef dxdt) const override {
    dxdt(0) = x(1);
    dxdt(1) = -kGravity;
  }
  bool in_flow_set(double, const ConstVectorRef& x, const ConstVectorRef&) const override {
    return x(0) >= -slack_;
  }
  bool in_jump_set(double, const ConstVectorRef& x, const ConstVectorRef&) const override {
    return x(0) <= 0.0 && x(1) < 0.0;
  }
  void jump(double, const ConstVectorRef& x, const ConstVectorRef&,
            VectorRef x_plus) const override {
    x_plus(0) = x(0);
    x_plus(1) = -restitution_ * x(1);
  }
  bool has_guard() const override { return true; }
  double guard(double, const ConstVectorRef& x, const ConstVectorRef&) const override {
    return x(0);
  }

 private:
  double restitution_;
  double slack_;
};

// The n-th (1-based) bounce time of a ball dropped from rest at h0: t₁ = √(2h₀/g), and flight n
// lasts 2eⁿ·t₁, so tₙ = t₁·(1 + 2e·(1 − e^{n−1})/(1 − e)).
double bounce_time(int n, double h0, double e) {
  const double t1 = std::sqrt(2.0 * h0 / BouncingBall::kGravity);
  return t1 * (1.0 + 2.0 * e * (1.0 - std::pow(e, n - 1)) / (1.0 - e));
}

TEST(SimulatorOptions, ValidateNamesTheBadOption) {
  struct Case {
    const char* field;
    void (*edit)(SimulatorOptions&);
  };
  const Case cases[] = {
      {"dt", [](SimulatorOptions& o) { o.dt = 0.0; }},
      {"dt", [](SimulatorOptions& o) { o.dt = std::numeric_limits<double>::quiet_NaN(); }},
      {"end_time", [](SimulatorOptions& o) { o.end_time = -1.0; }},
      {"end_time", [](SimulatorOptions& o) { o.end_time = 1.005; }},  // not a multiple of dt
      {"dwell_time", [](SimulatorOptions& o) { o.dwell_time = -0.1; }},
      {"max_jumps_per_instant", [](SimulatorOptions& o) { o.max_jumps_per_instant = 0; }},
      {"event_time_tolerance", [](SimulatorOptions& o) { o.event_time_tolerance = 0.0; }},
      {"max_events_per_step", [](SimulatorOptions& o) { o.max_events_per_step = 0; }},
  };
  EXPECT_NO_THROW(SimulatorOptions{}.validate());
  for (const Case& c : cases) {
    SimulatorOptions options;
    c.edit(options);
    EXPECT_THAT([&] { options.validate(); },
                ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr(c.field)))
        << c.field;
    const Integrator system;
    EXPECT_THROW(Simulator(system, options), std::invalid_argument) << c.field;
  }
}

TEST(Simulator, RejectsWrongSizesAndOffGridTasks) {
  const Integrator system;
  Simulator simulator(system, SimulatorOptions{});
  EXPECT_THROW((void)simulator.run(Eigen::VectorXd::Zero(2)), std::invalid_argument);
  EXPECT_THROW(simulator.set_initial_input(Eigen::VectorXd::Zero(3)), std::invalid_argument);
  EXPECT_THAT([&] { simulator.add_periodic_task("gnss", 0.015, 0.0, [](TaskContext&) {}); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("gnss")));
  EXPECT_THROW(simulator.add_periodic_task("late", 0.1, 0.005, [](TaskContext&) {}),
               std::invalid_argument);
}

TEST(Simulator, SampleAndHoldControllerAt10HzOn100HzIntegrator) {
  // ẋ = u with u = −k·x(t_j) held over each 0.1 s controller period. The held input is constant
  // over a period, where RK4 is exact, so x(t_{j+1}) = (1 − 0.1·k)·x(t_j) and x is linear in
  // between; only rounding (~1e-16 per step) separates simulation and closed form.
  SimulatorOptions options;
  options.dt = 0.01;
  options.end_time = 3.0;
  const double gain = 2.0;
  const Integrator system;
  Simulator simulator(system, options);
  simulator.add_periodic_task("controller", 0.1, 0.0, [&](TaskContext& context) {
    context.mutable_input()(0) = -gain * context.state()(0);
  });
  std::vector<double> x_seen;
  std::vector<double> u_seen;
  simulator.add_every_tick_task("probe", [&](TaskContext& context) {
    x_seen.push_back(context.state()(0));
    u_seen.push_back(context.input()(0));
  });
  const SimResult result = simulator.run(Eigen::VectorXd::Constant(1, 1.0));
  ASSERT_TRUE(result.ok()) << result.message;
  ASSERT_EQ(x_seen.size(), 301u);
  for (std::size_t k = 0; k < x_seen.size(); ++k) {
    const std::size_t j = k / 10;
    const double x_j = std::pow(1.0 - 0.1 * gain, static_cast<double>(j));
    const double expected = x_j * (1.0 - gain * 0.01 * static_cast<double>(k % 10));
    EXPECT_NEAR(x_seen[k], expected, 1e-13) << "tick " << k;
    if (k % 10 != 0) {
      EXPECT_EQ(u_seen[k], u_seen[k - 1]) << "input must be held between controller ticks, k " << k;
    } else {
      EXPECT_EQ(u_seen[k], -gain * x_seen[k]) << "controller output at tick " << k;
    }
  }
}

TEST(Simulator, TasksFireInTheOrderAddedAndSeeEarlierWrites) {
  const Integrator system;
  SimulatorOptions options;
  options.end_time = 0.03;
  Simulator simulator(system, options);
  std::vector<std::string> calls;
  simulator.add_every_tick_task(
      "a", [&](TaskContext& c) { calls.push_back("a" + std::to_string(c.tick())); });
  simulator.add_periodic_task("b", 0.02, 0.0, [&](TaskContext& c) {
    calls.push_back("b" + std::to_string(c.tick()));
    c.mutable_input()(0) = 5.0 + static_cast<double>(c.tick());
  });
  simulator.add_every_tick_task("c", [&](TaskContext& c) {
    calls.push_back("c" + std::to_string(c.tick()) + "u" +
                    std::to_string(static_cast<int>(c.input()(0))));
  });
  ASSERT_TRUE(simulator.run(Eigen::VectorXd::Zero(1)).ok());
  const std::vector<std::string> expected = {"a0", "b0", "c0u5", "a1", "c1u5",
                                             "a2", "b2", "c2u7", "a3", "c3u7"};
  EXPECT_EQ(calls, expected);
}

TEST(Simulator, TasksSeeTheStateBeforeTheJumpsOfTheirTick) {
  // Counter with dwell 0.1 s: jumps at t = 0, 0.1, …; a task at tick 10 sees 1 (one jump done,
  // the one of t = 0.1 not yet) and one at tick 11 sees 2.
  const Counter system;
  SimulatorOptions options;
  options.dt = 0.01;
  options.end_time = 0.2;
  options.dwell_time = 0.1;
  Simulator simulator(system, options);
  std::vector<double> seen;
  simulator.add_every_tick_task("probe", [&](TaskContext& c) { seen.push_back(c.state()(0)); });
  const SimResult result = simulator.run(Eigen::VectorXd::Zero(1));
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(seen.size(), 21u);
  EXPECT_EQ(seen[0], 0.0);
  EXPECT_EQ(seen[9], 1.0);
  EXPECT_EQ(seen[10], 1.0);
  EXPECT_EQ(seen[11], 2.0);
  EXPECT_EQ(seen[20], 2.0);
  EXPECT_EQ(result.final_state(0), 3.0);
}

TEST(Simulator, TaskMayUpdateTheStateExplicitly) {
  // ẋ = 1 with a 1 Hz task resetting x to 0: at t = 2.5 s, x = 0.5 (RK4 exact for constant rate;
  // 1e-12 covers the rounding of 50 additions of 0.01).
  const Integrator system;
  SimulatorOptions options;
  options.end_time = 2.5;
  Simulator simulator(system, options);
  simulator.set_initial_input(Eigen::VectorXd::Ones(1));
  simulator.add_periodic_task("reset", 1.0, 0.0,
                              [](TaskContext& c) { c.mutable_state()(0) = 0.0; });
  const SimResult result = simulator.run(Eigen::VectorXd::Constant(1, 42.0));
  ASSERT_TRUE(result.ok());
  EXPECT_NEAR(result.final_state(0), 0.5, 1e-12);
  EXPECT_EQ(result.steps, 250);
  EXPECT_EQ(result.final_time, 2.5);
}

TEST(Simulator, PeriodicTasksFireAtExactTicksOverAMillionSteps) {
  const Integrator system;
  SimulatorOptions options;
  options.dt = 0.01;
  options.end_time = 10000.0;  // 10⁶ steps
  Simulator simulator(system, options);
  std::vector<Tick> ticks;
  std::vector<double> times;
  ticks.reserve(100001);
  times.reserve(100001);
  simulator.add_periodic_task("sensor", 0.1, 0.03, [&](TaskContext& c) {
    ticks.push_back(c.tick());
    times.push_back(c.time());
  });
  const SimResult result = simulator.run(Eigen::VectorXd::Zero(1));
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result.steps, 1'000'000);
  EXPECT_EQ(result.final_time, 10000.0);
  // Fires at k = 3, 13, …, 999993: (999993 − 3)/10 + 1 = 100000 times.
  ASSERT_EQ(ticks.size(), 100000u);
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    ASSERT_EQ(ticks[i], 3 + 10 * static_cast<Tick>(i));
    // Bit-exact: the time is one multiplication k·dt, never a running sum.
    ASSERT_EQ(times[i], static_cast<double>(ticks[i]) * 0.01) << "firing " << i;
  }
}

TEST(Simulator, BouncingBallJumpTimesMatchTheGeometricSeriesWithEventLocation) {
  // Free flight is a quadratic in t, which RK4 integrates exactly, so the only errors are the
  // event location (each located time is at most event_time_tolerance = 1e-10 s late) and
  // rounding. A late bounce shifts later ones by a few times that, so after 7 bounces the error
  // is below ~1e-9 s; 1e-8 s leaves margin and is 10⁶ times smaller than dt.
  const double h0 = 10.0;
  const double e = 0.8;
  // The located point lies up to 1e-10 s past the crossing, where h ≈ −|v|·1e-10 ≈ −1.4e-9 m;
  // a 1e-6 m slack in C absorbs that and is far below any physical length here.
  const BouncingBall ball(e, 1e-6);
  SimulatorOptions options;
  options.dt = 0.01;
  options.end_time = 10.0;  // t_7 ≈ 9.86 s, t_8 ≈ 10.45 s
  Simulator simulator(ball, options);
  const SimResult result = simulator.run(Eigen::Vector2d(h0, 0.0));
  ASSERT_TRUE(result.ok()) << result.message;
  ASSERT_EQ(result.jump_times.size(), 7u);
  for (int n = 1; n <= 7; ++n) {
    EXPECT_NEAR(result.jump_times[n - 1], bounce_time(n, h0, e), 1e-8) << "bounce " << n;
  }
  // Between bounces the height follows the parabola after bounce 7 (same error budget, times
  // the speed ≤ 14 m/s).
  const double t7 = bounce_time(7, h0, e);
  const double v7 = std::pow(e, 7) * BouncingBall::kGravity * std::sqrt(2.0 * h0 / 9.81);
  const double dt7 = 10.0 - t7;
  EXPECT_NEAR(result.final_state(0), v7 * dt7 - 0.5 * BouncingBall::kGravity * dt7 * dt7, 1e-6);
}

TEST(Simulator, BouncingBallWithoutEventLocationJumpsAtTicks) {
  const double h0 = 10.0;
  const BouncingBall ball(0.8, std::numeric_limits<double>::infinity());
  SimulatorOptions options;
  options.dt = 0.01;
  options.end_time = 5.0;
  options.locate_events = false;
  Simulator simulator(ball, options);
  const SimResult result = simulator.run(Eigen::Vector2d(h0, 0.0));
  ASSERT_TRUE(result.ok()) << result.message;
  ASSERT_GE(result.jump_times.size(), 2u);
  // The first jump is at the first tick with h ≤ 0: ⌈t₁/dt⌉·dt, t₁ = 1.4278 s → 1.43 s.
  EXPECT_EQ(result.jump_times[0], simulator.grid().time(143));
  for (double t : result.jump_times) {
    EXPECT_EQ(t, simulator.grid().time(std::llround(t / 0.01))) << "jump off the tick grid";
  }
  // Quantised to the grid: each bounce is late by less than a step, and lateness adds up
  // over bounces (a late bounce starts lower and faster), so 2·dt for the second.
  EXPECT_LT(result.jump_times[0] - bounce_time(1, h0, 0.8), 0.01);
  EXPECT_LT(std::abs(result.jump_times[1] - bounce_time(2, h0, 0.8)), 0.02);
}

TEST(Simulator, BouncingBallPastItsZenoTimeStopsWithAStatus) {
  // The bounces accumulate at t_∞ = t₁·(1 + e)/(1 − e) ≈ 12.85 s. The run must neither hang nor
  // pass t_∞: once flights are shorter than a step the sub-step events are missed and the ball
  // ends up under the floor (or the Zeno cap trips), and either is reported as a status.
  const double h0 = 10.0;
  const double e = 0.8;
  const double t_inf = std::sqrt(2.0 * h0 / BouncingBall::kGravity) * (1.0 + e) / (1.0 - e);
  const BouncingBall ball(e, 1e-6);
  SimulatorOptions options;
  options.dt = 0.01;
  options.end_time = 20.0;
  Simulator simulator(ball, options);
  const SimResult result = simulator.run(Eigen::Vector2d(h0, 0.0));
  EXPECT_FALSE(result.ok());
  EXPECT_TRUE(result.status == SimStatus::kLeftFlowSet || result.status == SimStatus::kZeno)
      << to_string(result.status);
  EXPECT_LE(result.final_time, t_inf + options.dt);
  // Bounces are resolved until flights get shorter than ~dt: bounce 25 is at 12.80 s.
  EXPECT_GE(result.final_time, t_inf - 0.1);
  EXPECT_GT(result.jump_times.size(), 20u);
}

TEST(Simulator, LeavingTheFlowSetIsReportedAsStatus) {
  // Without event location the ball is 5 cm under the floor at the bounce tick; with C = {h ≥
  // −1e-6} the state after the jump is outside C and outside D.
  const BouncingBall ball(0.8, 1e-6);
  SimulatorOptions options;
  options.locate_events = false;
  Simulator simulator(ball, options);
  const SimResult result = simulator.run(Eigen::Vector2d(10.0, 0.0));
  EXPECT_EQ(result.status, SimStatus::kLeftFlowSet);
  EXPECT_THAT(result.message, HasSubstr("outside both the flow set C and the jump set D"));
  EXPECT_EQ(result.final_time, simulator.grid().time(143));
  EXPECT_EQ(result.jump_times.size(), 1u);
  EXPECT_EQ(result.steps, 143);
  EXPECT_STREQ(to_string(result.status), "left flow set");
}

TEST(Simulator, DwellTimeSpacesTheJumps) {
  const Counter system;
  struct Case {
    double dwell;
    std::size_t jumps;
    Tick spacing;  // in ticks
  };
  // Over [0, 1] s at dt = 0.01: dwell 0.1 → jumps every 10 ticks (11 jumps); dwell 0.015 is not
  // a multiple of dt, so the next allowed tick is 2 later (51 jumps); dwell 0.01 → every tick.
  const Case cases[] = {{0.1, 11, 10}, {0.015, 51, 2}, {0.01, 101, 1}};
  for (const Case& c : cases) {
    SimulatorOptions options;
    options.dt = 0.01;
    options.end_time = 1.0;
    options.dwell_time = c.dwell;
    Simulator simulator(system, options);
    const SimResult result = simulator.run(Eigen::VectorXd::Zero(1));
    ASSERT_TRUE(result.ok()) << result.message;
    ASSERT_EQ(result.jump_times.size(), c.jumps) << "dwell " << c.dwell;
    for (std::size_t i = 0; i < result.jump_times.size(); ++i) {
      EXPECT_EQ(result.jump_times[i], simulator.grid().time(static_cast<Tick>(i) * c.spacing));
    }
    EXPECT_EQ(result.final_state(0), static_cast<double>(c.jumps));
  }
}

TEST(Simulator, ZenoCapIsReportedAsStatus) {
  const Counter system;
  SimulatorOptions options;
  options.dwell_time = 0.0;
  options.max_jumps_per_instant = 5;
  Simulator simulator(system, options);
  const SimResult result = simulator.run(Eigen::VectorXd::Zero(1));
  EXPECT_EQ(result.status, SimStatus::kZeno);
  EXPECT_FALSE(result.ok());
  EXPECT_THAT(result.message, HasSubstr("Zeno"));
  EXPECT_EQ(result.jump_times.size(), 5u);
  EXPECT_EQ(result.final_time, 0.0);
  EXPECT_EQ(result.final_state(0), 5.0);
  EXPECT_EQ(result.steps, 0);
}

TEST(Simulator, NonFiniteStateIsReportedAsStatus) {
  const Integrator system;
  Simulator simulator(system, SimulatorOptions{});
  simulator.add_periodic_task("bad", 1.0, 2.0, [](TaskContext& c) {
    c.mutable_input()(0) = std::numeric_limits<double>::infinity();
  });
  const SimResult result = simulator.run(Eigen::VectorXd::Zero(1));
  EXPECT_EQ(result.status, SimStatus::kNonFinite);
  EXPECT_EQ(result.steps, 200);
}

// ẋ = (−x + u₀)/T: a first-order lag driven by a held disturbance.
class Lag final : public HybridSystem {
 public:
  Eigen::Index state_size() const override { return 1; }
  Eigen::Index input_size() const override { return 1; }
  void flow(double, const ConstVectorRef& x, const ConstVectorRef& u,
            VectorRef dxdt) const override {
    dxdt(0) = (-x(0) + u(0)) / 5.0;
  }
};

// A small virtual trial: a Gauss–Markov disturbance sampled at 10 Hz drives the lag, a 20 Hz
// sensor measures x with white noise, a 20 Hz logger records truth, input and measurement.
core::Log run_noisy_trial(std::uint64_t seed) {
  const Lag system;
  SimulatorOptions options;
  options.dt = 0.01;
  options.end_time = 20.0;
  Simulator simulator(system, options);
  GaussMarkov disturbance =
      GaussMarkov::with_stationary_std(2.0, 1.0, 0.1, Rng(seed, "disturbance"));
  WhiteNoise sensor_noise(0.05, Rng(seed, "sensor"));
  double measured = 0.0;
  simulator.add_periodic_task("disturbance", 0.1, 0.0,
                              [&](TaskContext& c) { c.mutable_input()(0) = disturbance.step(); });
  simulator.add_periodic_task("sensor", 0.05, 0.0, [&](TaskContext& c) {
    measured = c.state()(0) + sensor_noise.sample();
  });
  core::Log log;
  LogRecorder recorder(log, {state_signal("x", "m", 0), input_signal("u", "m", 0),
                             RecordedSignal{"y", "m", core::Interp::kLinear,
                                            [&](const TaskContext&) { return measured; }}});
  recorder.attach(simulator, 0.05);
  const SimResult result = simulator.run(Eigen::VectorXd::Zero(1));
  EXPECT_TRUE(result.ok());
  return log;
}

bool bit_identical(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(Simulator, SameSeedGivesBitIdenticalLogsAndAnotherSeedDiffers) {
  const core::Log first = run_noisy_trial(42);
  const core::Log second = run_noisy_trial(42);
  const core::Log other = run_noisy_trial(43);
  ASSERT_EQ(first.size(), 401u);  // 20 s at 20 Hz, both ends included
  EXPECT_TRUE(bit_identical(first.time(), second.time()));
  for (const char* name : {"x", "u", "y"}) {
    EXPECT_TRUE(bit_identical(first.values(name), second.values(name))) << name;
    EXPECT_FALSE(bit_identical(first.values(name), other.values(name))) << name;
  }
  EXPECT_EQ(first.channel("u").interp, core::Interp::kHold);
}

TEST(Simulator, StepCostDoesNotAllocate) {
  // A run allocates its workspace once; a ten times longer run must not allocate more.
  const Lag system;
  const auto allocations_for = [&](double end_time) {
    SimulatorOptions options;
    options.end_time = end_time;
    Simulator simulator(system, options);
    double sink = 0.0;
    simulator.add_periodic_task("controller", 0.1, 0.0,
                                [](TaskContext& c) { c.mutable_input()(0) = 1.0; });
    simulator.add_every_tick_task("probe", [&](TaskContext& c) { sink += c.state()(0); });
    const long before = g_allocations.load();
    const SimResult result = simulator.run(Eigen::VectorXd::Zero(1));
    const long count = g_allocations.load() - before;
    EXPECT_TRUE(result.ok());
    EXPECT_GT(sink, 0.0);
    return count;
  };
  EXPECT_EQ(allocations_for(10.0), allocations_for(100.0));
}

}  // namespace
}  // namespace dynpos::sim
