#include "dynpos/sim/log_recorder.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <stdexcept>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/sim/simulator.hpp"

namespace dynpos::sim {
namespace {

// x = (position, velocity) of a mass pushed by a held force u: ṗ = v, v̇ = u.
class Mass final : public HybridSystem {
 public:
  Eigen::Index state_size() const override { return 2; }
  Eigen::Index input_size() const override { return 1; }
  void flow(double, const ConstVectorRef& x, const ConstVectorRef& u,
            VectorRef dxdt) const override {
    dxdt(0) = x(1);
    dxdt(1) = u(0);
  }
};

TEST(LogRecorder, RecordsStateInputAndDerivedSignalsAtTheLoggerRate) {
  const Mass system;
  SimulatorOptions options;
  options.dt = 0.01;
  options.end_time = 1.0;
  Simulator simulator(system, options);
  simulator.add_periodic_task("force", 0.5, 0.0, [](TaskContext& c) {
    c.mutable_input()(0) = c.time() < 0.25 ? 2.0 : -1.0;
  });
  core::Log log;
  LogRecorder recorder(
      log, {state_signal("p", "m", 0), state_signal("v", "m/s", 1), input_signal("force", "N", 0),
            RecordedSignal{"tick", "1", core::Interp::kNearest,
                           [](const TaskContext& c) { return static_cast<double>(c.tick()); }}});
  recorder.attach(simulator, 0.1);
  const SimResult result = simulator.run(Eigen::Vector2d(0.0, 0.0));
  ASSERT_TRUE(result.ok()) << result.message;

  ASSERT_EQ(log.size(), 11u);  // t = 0, 0.1, …, 1.0
  EXPECT_EQ(log.channel_names(), (std::vector<std::string>{"p", "v", "force", "tick"}));
  EXPECT_EQ(log.channel("v").unit, "m/s");
  EXPECT_EQ(log.channel("force").interp, core::Interp::kHold);
  for (std::size_t i = 0; i < log.size(); ++i) {
    const double t = log.time()[i];
    EXPECT_EQ(t, simulator.grid().time(static_cast<Tick>(10 * i)));
    EXPECT_EQ(log.values("tick")[i], 10.0 * static_cast<double>(i));
    // u = 2 N on [0, 0.5), −1 N after: piecewise-constant acceleration, which RK4 integrates
    // exactly; 1e-12 covers rounding over 100 steps.
    const double u = t < 0.5 ? 2.0 : -1.0;
    const double v = t < 0.5 ? 2.0 * t : 1.0 - (t - 0.5);
    const double p = t < 0.5 ? t * t : 0.25 + 1.0 * (t - 0.5) - 0.5 * (t - 0.5) * (t - 0.5);
    EXPECT_EQ(log.values("force")[i], u) << "t = " << t;
    EXPECT_NEAR(log.values("v")[i], v, 1e-12) << "t = " << t;
    EXPECT_NEAR(log.values("p")[i], p, 1e-12) << "t = " << t;
  }
}

TEST(LogRecorder, RejectsAUsedLogAndASignalWithoutValue) {
  core::Log used;
  used.declare_channel("x", "m");
  EXPECT_THROW(LogRecorder(used, {state_signal("p", "m", 0)}), std::invalid_argument);
  core::Log fresh;
  EXPECT_THROW(LogRecorder(fresh, {RecordedSignal{"y", "m", core::Interp::kLinear, {}}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::sim
