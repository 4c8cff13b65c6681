#include "dynpos/hybrid/case_study.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "dynpos/hybrid/derivative_sampler.hpp"
#include "dynpos/hybrid/step_metrics.hpp"
#include "dynpos/sim/random.hpp"
#include "dynpos/sim/sim_time.hpp"

namespace dynpos::hybrid {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

// Steps inside (0, end], on the grid, strictly increasing.
void validate_step_times(const std::vector<double>& times, const CaseTiming& timing,
                         const std::string& who) {
  const sim::TimeGrid grid(timing.dt_s);
  double previous = -1.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::string what = who + ": step " + std::to_string(i + 1);
    require(std::isfinite(times[i]) && times[i] >= 0.0 && times[i] < timing.end_time_s,
            what + " time must be in [0, end_time)");
    require(times[i] > previous, what + " must come after the step before it");
    (void)grid.ticks(times[i], what + " time");
    previous = times[i];
  }
}

// What a case study needs to know about its system, as a compile-time interface:
//   kDofs                      size of the integral-state error
//   kChannels                  trace channels
//   system()                   the HybridSystem
//   initial_state()
//   apply_step(i, x)           the disturbance step i on the true disturbance in x
//   sampled_signal(x, y)       the signal whose derivative the sampler estimates
//   evaluate(x, Eval&)         integral error, position and heading error, V and a trace row
template <int Dofs, int Channels>
struct Eval {
  Eigen::Matrix<double, Dofs, 1> integral_error;
  double position_error = 0.0;
  double heading_error = kNaN;
  double V = 0.0;
  std::array<double, Channels> row{};
};

// One run of a case study: the simulator with the disturbance steps, the derivative sampler
// (sampled jump set only), the metrics on every tick and the jump observer, registered in
// that order (the event order of the file comment), then the metrics of the run.
template <typename Model>
class CaseRun {
 public:
  static constexpr int kDofs = Model::kDofs;
  static constexpr int kChannels = Model::kChannels;
  using Vec = Eigen::Matrix<double, kDofs, 1>;

  CaseRun(const Model& model, const CaseTiming& timing, JumpSet jump_set,
          const std::vector<double>& step_times, const std::vector<Vec>& step_deltas);

  CaseResult run() &&;

 private:
  void add_row(double t, const std::array<double, kChannels>& row);
  void add_step_task(sim::Simulator& simulator);
  void add_sampler_task(sim::Simulator& simulator);
  void add_metrics_task(sim::Simulator& simulator);
  void observe_jumps(sim::Simulator& simulator);
  void set_metrics(const sim::SimResult& run);

  const Model& model_;
  const CaseTiming& timing_;
  const std::vector<Vec>& step_deltas_;
  const sim::TimeGrid grid_;
  CaseResult result_;
  Eval<kDofs, kChannels> eval_;
  std::vector<sim::Tick> step_ticks_;  // disturbance steps, first at their tick
  std::vector<Vec> step_scale_;        // per step, the band scale of each DOF
  std::size_t next_step_ = 0;
  // The derivative sampler of the practical jump set.
  std::optional<DerivativeSampler> sampler_;
  Eigen::VectorXd y_;
  // Per tick: the metrics' samples.
  std::vector<double> tick_time_, ratio_, position_error_, heading_error_;
  std::vector<Vec> integral_error_;
  double v_max_ = 0.0;
  std::optional<double> v_increase_;  // largest V(x⁺) − V(x) over the jumps
};

template <typename Model>
CaseRun<Model>::CaseRun(const Model& model, const CaseTiming& timing, JumpSet jump_set,
                        const std::vector<double>& step_times, const std::vector<Vec>& step_deltas)
    : model_(model), timing_(timing), step_deltas_(step_deltas), grid_(timing.dt_s), y_(kDofs) {
  // Strings built, then moved in (assigning the literals trips a false -Wrestrict in GCC 12).
  result_.case_name = std::string(Model::kName);
  result_.jump_set = jump_set;
  result_.step_times = step_times;
  result_.error_label = std::string(Model::kErrorLabel);
  result_.error_unit = std::string(Model::kErrorUnit);
  for (const Vec& delta : step_deltas) step_scale_.push_back(step_band_scale(delta));
  for (int c = 0; c < kChannels; ++c) {
    core::Channel channel;
    channel.name = Model::kChannelNames[c];
    channel.unit = Model::kChannelUnits[c];
    result_.trace.channels.push_back(std::move(channel));
  }
  for (const double ts : step_times) step_ticks_.push_back(grid_.ticks(ts, "step time"));
}

template <typename Model>
CaseResult CaseRun<Model>::run() && {
  const sim::HybridSystem& system = model_.system();
  sim::SimulatorOptions sim_options;
  sim_options.dt = timing_.dt_s;
  sim_options.end_time = timing_.end_time_s;
  sim_options.dwell_time = timing_.dwell_time_s;
  sim_options.locate_events = false;
  sim::Simulator simulator(system, sim_options);
  Eigen::VectorXd u0 = Eigen::VectorXd::Zero(system.input_size());
  u0(Model::kOlderSampleTime) = kNaN;  // no derivative estimate yet
  simulator.set_initial_input(u0);

  add_step_task(simulator);
  if (result_.jump_set == JumpSet::kSampled) add_sampler_task(simulator);
  add_metrics_task(simulator);
  observe_jumps(simulator);

  const sim::SimResult run = simulator.run(model_.initial_state());
  result_.status = run.status;
  result_.message = run.message;
  result_.jump_times = run.jump_times;
  set_metrics(run);
  return std::move(result_);
}

template <typename Model>
void CaseRun<Model>::add_row(double t, const std::array<double, kChannels>& row) {
  Trace& trace = result_.trace;
  trace.t.push_back(t);
  for (int c = 0; c < kChannels; ++c) trace.channels[c].values.push_back(row[c]);
}

template <typename Model>
void CaseRun<Model>::add_step_task(sim::Simulator& simulator) {
  simulator.add_every_tick_task("disturbance steps", [this](sim::TaskContext& ctx) {
    bool stepped = false;
    while (next_step_ < step_ticks_.size() && step_ticks_[next_step_] == ctx.tick()) {
      if (!stepped) {
        // The state just before the step, so that a plot shows the step as a vertical edge.
        model_.evaluate(ctx.state(), eval_);
        add_row(ctx.time(), eval_.row);
      }
      model_.apply_step(next_step_, ctx.mutable_state());
      ++next_step_;
      stepped = true;
    }
  });
}

template <typename Model>
void CaseRun<Model>::add_sampler_task(sim::Simulator& simulator) {
  sampler_.emplace(kDofs, timing_.sample_period_s, timing_.noise_power,
                   sim::Rng(timing_.seed, Model::kNoiseStream));
  simulator.add_periodic_task(
      "derivative sampler", timing_.sample_period_s, 0.0, [this](sim::TaskContext& ctx) {
        model_.sampled_signal(ctx.state(), y_);
        if (sampler_->sample(ctx.time(), y_)) {
          ctx.mutable_input().segment(Model::kDerivative, kDofs) = sampler_->estimate();
          ctx.mutable_input()(Model::kOlderSampleTime) = sampler_->older_sample_time();
        }
      });
}

// Metrics on every tick, trace rows every log period.
template <typename Model>
void CaseRun<Model>::add_metrics_task(sim::Simulator& simulator) {
  const sim::Tick end_tick = grid_.ticks(timing_.end_time_s, "end_time");
  const sim::Tick log_every = grid_.ticks_for_period(timing_.log_period_s, "log_period");
  const std::size_t n_ticks = static_cast<std::size_t>(end_tick) + 1;
  tick_time_.reserve(n_ticks);
  position_error_.reserve(n_ticks);
  heading_error_.reserve(n_ticks);
  ratio_.reserve(n_ticks);
  integral_error_.reserve(n_ticks);
  simulator.add_every_tick_task("metrics", [this, log_every](sim::TaskContext& ctx) {
    model_.evaluate(ctx.state(), eval_);
    const double t = ctx.time();
    tick_time_.push_back(t);
    position_error_.push_back(eval_.position_error);
    heading_error_.push_back(eval_.heading_error);
    integral_error_.push_back(eval_.integral_error);
    // The band of the step whose window this tick is in (none before the first step).
    const auto it = std::upper_bound(step_ticks_.begin(), step_ticks_.end(), ctx.tick());
    if (it == step_ticks_.begin()) {
      ratio_.push_back(0.0);
    } else {
      const Vec& scale = step_scale_[static_cast<std::size_t>(it - step_ticks_.begin()) - 1];
      ratio_.push_back(band_ratio(eval_.integral_error, scale, timing_.settle_band));
    }
    v_max_ = std::max(v_max_, eval_.V);
    const bool step_tick = it != step_ticks_.begin() && *(it - 1) == ctx.tick();
    if (ctx.tick() % log_every == 0 || step_tick) add_row(t, eval_.row);
  });
}

// Jumps: V before and after, and both states in the trace.
template <typename Model>
void CaseRun<Model>::observe_jumps(sim::Simulator& simulator) {
  simulator.set_jump_observer(
      [this](double t, const Eigen::VectorXd& x_minus, const Eigen::VectorXd& x_plus) {
        model_.evaluate(x_minus, eval_);
        const double v_minus = eval_.V;
        add_row(t, eval_.row);
        model_.evaluate(x_plus, eval_);
        add_row(t, eval_.row);
        const double dv = eval_.V - v_minus;
        v_increase_ = v_increase_ ? std::max(*v_increase_, dv) : dv;
      });
}

template <typename Model>
void CaseRun<Model>::set_metrics(const sim::SimResult& run) {
  CaseMetrics& m = result_.metrics;
  m.jumps = static_cast<int>(run.jump_times.size());
  m.v_increase_at_jumps = v_increase_;
  m.v_max = v_max_;
  m.iae = integral_abs_error(tick_time_, position_error_);
  m.peak_error = peak_abs(position_error_);
  m.heading_iae = Model::kHasHeading ? integral_abs_error(tick_time_, heading_error_) : kNaN;
  m.heading_peak = Model::kHasHeading ? peak_abs(heading_error_) : kNaN;
  const std::vector<double>& step_times = result_.step_times;
  for (std::size_t i = 0; i < step_times.size(); ++i) {
    const double t_end =
        i + 1 < step_times.size() ? step_times[i + 1] : std::numeric_limits<double>::infinity();
    m.settle_s.push_back(settling_time(tick_time_, ratio_, step_times[i], t_end));
    // The last tick of the window.
    const auto last = std::lower_bound(tick_time_.begin(), tick_time_.end(), t_end);
    if (last == tick_time_.begin()) {
      m.residual.push_back(kNaN);
    } else {
      const Vec& e = integral_error_[static_cast<std::size_t>(last - tick_time_.begin()) - 1];
      m.residual.push_back(step_residual(e, step_deltas_[i], step_scale_[i]));
    }
  }
}

template <typename Model>
CaseResult run_case(const Model& model, const CaseTiming& timing, JumpSet jump_set,
                    const std::vector<double>& step_times,
                    const std::vector<Eigen::Matrix<double, Model::kDofs, 1>>& step_deltas) {
  return CaseRun<Model>(model, timing, jump_set, step_times, step_deltas).run();
}

// The first-order system as a case-study model.
class FirstOrderModel {
 public:
  static constexpr int kDofs = 1;
  static constexpr int kChannels = 5;
  static constexpr const char* kName = "first-order";
  static constexpr const char* kErrorLabel = "position error x1";
  static constexpr const char* kErrorUnit = "";
  static constexpr const char* kNoiseStream = "hybrid.first-order.derivative";
  static constexpr bool kHasHeading = false;
  static constexpr Eigen::Index kDerivative = FirstOrderSystem::kX1DotHat;
  static constexpr Eigen::Index kOlderSampleTime = FirstOrderSystem::kOlderSampleTime;
  static constexpr std::array<const char*, kChannels> kChannelNames = {"x1", "x2", "V", "d",
                                                                       "d_hat"};
  static constexpr std::array<const char*, kChannels> kChannelUnits = {"", "", "", "", ""};

  explicit FirstOrderModel(const FirstOrderCaseOptions& options)
      : options_(options), system_(options.params) {}

  const sim::HybridSystem& system() const { return system_; }
  Eigen::VectorXd initial_state() const { return system_.initial_state(); }
  void apply_step(std::size_t i, Eigen::VectorXd& x) const {
    x(FirstOrderSystem::kD) += options_.steps[i].delta;
  }
  void sampled_signal(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    y(0) = system_.errors(x)(0);  // x₁, sampled for ẋ₁ (5.80)
  }
  void evaluate(const Eigen::VectorXd& x, Eval<kDofs, kChannels>& out) const {
    const Eigen::Vector2d e = system_.errors(x);
    out.integral_error(0) = e(1);
    out.position_error = e(0);
    out.V = system_.lyapunov(e);
    out.row = {e(0), e(1), out.V, x(FirstOrderSystem::kD), x(FirstOrderSystem::kDHat)};
  }

 private:
  const FirstOrderCaseOptions& options_;
  FirstOrderSystem system_;
};

// The DP system as a case-study model.
class DpModel {
 public:
  static constexpr int kDofs = 3;
  static constexpr int kChannels = 10;
  static constexpr const char* kName = "dp";
  static constexpr const char* kErrorLabel = "horizontal position error |x1 (surge, sway)|";
  static constexpr const char* kErrorUnit = "m";
  static constexpr const char* kNoiseStream = "hybrid.dp.derivative";
  static constexpr bool kHasHeading = true;
  static constexpr Eigen::Index kDerivative = DpHybridSystem::kX2DotHat;
  static constexpr Eigen::Index kOlderSampleTime = DpHybridSystem::kOlderSampleTime;
  static constexpr std::array<const char*, kChannels> kChannelNames = {
      "x1.surge", "x1.sway",  "x1.yaw",  "x2.surge", "x2.sway",
      "x2.yaw",   "x3.north", "x3.east", "x3.yaw",   "V"};
  static constexpr std::array<const char*, kChannels> kChannelUnits = {
      "m", "m", "rad", "m/s", "m/s", "rad/s", "N", "N", "N·m", ""};

  explicit DpModel(const DpCaseOptions& options) : options_(options), system_(options.params) {}

  const sim::HybridSystem& system() const { return system_; }
  Eigen::VectorXd initial_state() const { return system_.initial_state(); }
  void apply_step(std::size_t i, Eigen::VectorXd& x) const {
    x.segment<3>(DpHybridSystem::kBias) += options_.steps[i].delta_n;
  }
  void sampled_signal(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    y = system_.errors(x).x2;  // x₂, sampled for ẋ₂ (5.92)
  }
  void evaluate(const Eigen::VectorXd& x, Eval<kDofs, kChannels>& out) const {
    const DpErrors e = system_.errors(x);
    out.integral_error = e.x3;
    out.position_error = e.x1.head<2>().norm();
    out.heading_error = e.x1.z();
    out.V = system_.lyapunov(e);
    out.row = {e.x1(0), e.x1(1), e.x1(2), e.x2(0), e.x2(1),
               e.x2(2), e.x3(0), e.x3(1), e.x3(2), out.V};
  }

 private:
  const DpCaseOptions& options_;
  DpHybridSystem system_;
};

}  // namespace

void CaseTiming::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(positive(dt_s), "CaseTiming: dt must be finite and > 0");
  require(positive(end_time_s), "CaseTiming: end_time must be finite and > 0");
  require(std::isfinite(dwell_time_s) && dwell_time_s >= 0.0,
          "CaseTiming: dwell_time must be finite and >= 0");
  require(positive(sample_period_s), "CaseTiming: sample_period must be finite and > 0");
  require(std::isfinite(noise_power) && noise_power >= 0.0,
          "CaseTiming: noise_power must be finite and >= 0");
  require(positive(log_period_s), "CaseTiming: log_period must be finite and > 0");
  require(std::isfinite(settle_band) && settle_band > 0.0 && settle_band < 1.0,
          "CaseTiming: settle_band must be in (0, 1)");
  const sim::TimeGrid grid(dt_s);
  (void)grid.ticks(end_time_s, "CaseTiming: end_time");
  (void)grid.ticks(dwell_time_s, "CaseTiming: dwell_time");
  (void)grid.ticks_for_period(sample_period_s, "CaseTiming: sample_period");
  (void)grid.ticks_for_period(log_period_s, "CaseTiming: log_period");
}

void FirstOrderCaseOptions::validate() const {
  params.validate();
  timing.validate();
  std::vector<double> times;
  for (const DisturbanceStep& s : steps) {
    require(std::isfinite(s.delta) && s.delta != 0.0,
            "FirstOrderCaseOptions: a step's delta must be finite and non-zero");
    times.push_back(s.time_s);
  }
  validate_step_times(times, timing, "FirstOrderCaseOptions");
}

void DpCaseOptions::validate() const {
  params.validate();
  timing.validate();
  std::vector<double> times;
  for (const BiasStep& s : steps) {
    require(s.delta_n.allFinite() && !s.delta_n.isZero(0.0),
            "DpCaseOptions: a step's delta_n must be finite and non-zero");
    times.push_back(s.time_s);
  }
  validate_step_times(times, timing, "DpCaseOptions");
}

CaseResult run_first_order_case(const FirstOrderCaseOptions& options) {
  options.validate();
  const FirstOrderModel model(options);
  std::vector<double> times;
  std::vector<Eigen::Matrix<double, 1, 1>> deltas;
  for (const DisturbanceStep& s : options.steps) {
    times.push_back(s.time_s);
    deltas.push_back(Eigen::Matrix<double, 1, 1>(s.delta));
  }
  return run_case(model, options.timing, options.params.jump_set, times, deltas);
}

CaseResult run_dp_case(const DpCaseOptions& options) {
  options.validate();
  const DpModel model(options);
  std::vector<double> times;
  std::vector<Eigen::Vector3d> deltas;
  for (const BiasStep& s : options.steps) {
    times.push_back(s.time_s);
    deltas.push_back(s.delta_n);
  }
  return run_case(model, options.timing, options.params.jump_set, times, deltas);
}

}  // namespace dynpos::hybrid
