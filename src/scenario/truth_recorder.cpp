#include "dynpos/scenario/truth_recorder.hpp"

#include <functional>
#include <string>

#include "dynpos/core/angle.hpp"

namespace dynpos::scenario {
namespace {

using Value = std::function<double()>;

// A truth channel; its value does not depend on the context beyond the recorder's sample.
sim::RecordedSignal truth_channel(std::string name, std::string unit, Value value) {
  return {std::move(name), std::move(unit), core::Interp::kLinear,
          [value = std::move(value)](const sim::TaskContext&) { return value(); }};
}

void append(std::vector<sim::RecordedSignal>& to, std::vector<sim::RecordedSignal> more) {
  for (sim::RecordedSignal& s : more) to.push_back(std::move(s));
}

}  // namespace

TruthRecorder::TruthRecorder(core::Log& log, const ControlTask& control)
    : control_(control), recorder_(log, signals()) {}

void TruthRecorder::record(const sim::TaskContext& context, const VesselSample& sample) {
  sample_ = &sample;
  v_b_ = sample.motion.v_b();
  recorder_.record(context);
}

std::vector<sim::RecordedSignal> TruthRecorder::signals() {
  std::vector<sim::RecordedSignal> all = motion_signals();
  append(all, actuator_signals());
  append(all, command_and_weather_signals());
  append(all, observer_signals());
  return all;
}

std::vector<sim::RecordedSignal> TruthRecorder::observer_signals() {
  std::vector<sim::RecordedSignal> out;
  const DpEstimator* estimator = control_.estimator();
  if (estimator == nullptr) return out;  // not a DP run
  const char* const dofs[] = {"surge", "sway", "yaw"};
  const char* const axes[][2] = {{"north", "N"}, {"east", "N"}, {"yaw", "N*m"}};
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("demand.") + dofs[k], axes[k][1], [this, k] {
      return control_.dp_active() ? control_.dp_demand_b()[k] : core::kMissing;
    }));
  }
  out.push_back(truth_channel("lf.north", "m", [this] { return sample_->eta_lf_n.x(); }));
  out.push_back(truth_channel("lf.east", "m", [this] { return sample_->eta_lf_n.y(); }));
  out.push_back(
      truth_channel("lf.heading", "rad", [this] { return core::wrap_2pi(sample_->eta_lf_n.z()); }));
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("env_load.") + axes[k][0], axes[k][1],
                                [this, k] { return sample_->env_load_n[k]; }));
  }
  if (!estimator->estimate()) return out;  // ideal or raw: no observer
  out.push_back(truth_channel("observer.bridged", "1",
                              [estimator] { return estimator->position_bridged() ? 1.0 : 0.0; }));
  const auto estimate = [estimator] { return *estimator->estimate(); };
  out.push_back(truth_channel("observer.north", "m", [=] { return estimate().eta_n.x(); }));
  out.push_back(truth_channel("observer.east", "m", [=] { return estimate().eta_n.y(); }));
  out.push_back(truth_channel("observer.heading", "rad",
                              [=] { return core::wrap_2pi(estimate().eta_n.z()); }));
  const char* const velocity[][2] = {{"u", "m/s"}, {"v", "m/s"}, {"r", "rad/s"}};
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("observer.") + velocity[k][0], velocity[k][1],
                                [=] { return estimate().nu_b[k]; }));
  }
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("observer.bias.") + axes[k][0], axes[k][1],
                                [=] { return estimate().bias_n[k]; }));
  }
  return out;
}

std::vector<sim::RecordedSignal> TruthRecorder::motion_signals() {
  const auto m = [this]() -> const sensors::RigidBodyMotion& { return sample_->motion; };
  return {
      truth_channel("north", "m", [m] { return m().p_n[0]; }),
      truth_channel("east", "m", [m] { return m().p_n[1]; }),
      truth_channel("down", "m", [m] { return m().p_n[2]; }),
      truth_channel("heading", "rad", [m] { return core::wrap_2pi(m().theta.z()); }),
      truth_channel("roll", "rad", [m] { return m().theta.x(); }),
      truth_channel("pitch", "rad", [m] { return m().theta.y(); }),
      truth_channel("u", "m/s", [this] { return v_b_[0]; }),
      truth_channel("v", "m/s", [this] { return v_b_[1]; }),
      truth_channel("w", "m/s", [this] { return v_b_[2]; }),
      truth_channel("p", "rad/s", [m] { return m().omega_nb_b[0]; }),
      truth_channel("q", "rad/s", [m] { return m().omega_nb_b[1]; }),
      truth_channel("r", "rad/s", [m] { return m().omega_nb_b[2]; }),
  };
}

// A [[thruster]] layout's units: shaft speed, thrust, power and steering angle of each.
std::vector<sim::RecordedSignal> TruthRecorder::unit_signals() {
  std::vector<sim::RecordedSignal> out;
  const auto& drives = control_.plant().drives();
  for (std::size_t k = 0; k < drives.size(); ++k) {
    const std::string& name = drives[k].unit().name;
    const auto unit = [this, k]() -> const model::UnitOutput& { return sample_->units[k]; };
    out.push_back(truth_channel("rpm." + name, "rps", [unit] { return unit().shaft_speed_rps; }));
    out.push_back(truth_channel("thrust." + name, "N", [unit] { return unit().thrust_N; }));
    out.push_back(truth_channel("power." + name, "W", [unit] { return unit().power_W; }));
    switch (drives[k].unit().type) {
      case model::UnitType::kAzimuth:
        out.push_back(truth_channel("azimuth." + name, "rad",
                                    [unit] { return core::wrap_2pi(unit().angle_rad); }));
        break;
      case model::UnitType::kPropellerRudder:
        out.push_back(truth_channel("rudder." + name, "rad", [unit] { return unit().angle_rad; }));
        break;
      default:
        break;
    }
  }
  return out;
}

// Shaft speeds, thrusts, powers and rudder angles of the actuators.
std::vector<sim::RecordedSignal> TruthRecorder::actuator_signals() {
  if (!control_.plant().drives().empty()) return unit_signals();
  std::vector<sim::RecordedSignal> out;
  const char* const thrusters[] = {"port", "stb", "tunnel"};
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("rpm.") + thrusters[k], "rps",
                                [this, k] { return sample_->shaft_speed_rps[k]; }));
  }
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("thrust.") + thrusters[k], "N",
                                [this, k] { return sample_->thrust_N[k]; }));
  }
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("power.") + thrusters[k], "W",
                                [this, k] { return sample_->power_W[k]; }));
  }
  out.push_back(truth_channel("rudder.port", "rad", [this] { return sample_->rudder_rad[0]; }));
  out.push_back(truth_channel("rudder.stb", "rad", [this] { return sample_->rudder_rad[1]; }));
  return out;
}

// The operator's demand and lever (fractions), weather, DP setpoint and bias, loads.
std::vector<sim::RecordedSignal> TruthRecorder::command_and_weather_signals() {
  std::vector<sim::RecordedSignal> out;
  const char* const dofs[] = {"surge", "sway", "yaw"};
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("command.") + dofs[k], "1",
                                [this, k] { return control_.demand_pct()[k] / 100.0; }));
  }
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("lever.") + dofs[k], "1",
                                [this, k] { return control_.lever_pct()[k] / 100.0; }));
  }
  out.push_back(truth_channel("wind_speed", "m/s", [this] { return sample_->wind_speed_mps; }));
  out.push_back(truth_channel("wind_dir", "rad", [this] { return sample_->wind_from_rad; }));
  out.push_back(truth_channel("current.north", "m/s", [this] { return sample_->current_n.x(); }));
  out.push_back(truth_channel("current.east", "m/s", [this] { return sample_->current_n.y(); }));
  out.push_back(truth_channel("setpoint.north", "m", [this] { return control_.setpoint_n().x(); }));
  out.push_back(truth_channel("setpoint.east", "m", [this] { return control_.setpoint_n().y(); }));
  out.push_back(truth_channel("setpoint.heading", "rad", [this] {
    return control_.dp_active() ? core::wrap_2pi(control_.setpoint_n().z()) : core::kMissing;
  }));
  const char* const axes[][2] = {{"north", "N"}, {"east", "N"}, {"yaw", "N*m"}};
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("bias_estimate.") + axes[k][0], axes[k][1], [this, k] {
      return control_.dp_active() ? control_.bias_hat_n()[k] : core::kMissing;
    }));
  }
  for (int k = 0; k < 3; ++k) {
    out.push_back(truth_channel(std::string("load.") + axes[k][0], axes[k][1],
                                [this, k] { return sample_->load_n[k]; }));
  }
  return out;
}

}  // namespace dynpos::scenario
