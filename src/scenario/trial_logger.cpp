#include "dynpos/scenario/trial_logger.hpp"

#include <algorithm>

#include <fmt/core.h>

#include <span>
#include <stdexcept>
#include <utility>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/error.hpp"
#include "sensor_logger.hpp"

namespace dynpos::scenario {
namespace {

// The command channels, after the sensors (logger units).
constexpr std::pair<const char*, const char*> kCommandChannels[] = {
    {"command.surge", "%"},         {"command.sway", "%"},         {"command.yaw", "%"},
    {"lever.surge", "%"},           {"lever.sway", "%"},           {"lever.yaw", "%"},
    {"command.rpm.port", "rpm"},    {"command.rpm.stb", "rpm"},    {"command.rpm.tunnel", "rpm"},
    {"command.thrust.port", "kN"},  {"command.thrust.stb", "kN"},  {"command.thrust.tunnel", "kN"},
    {"command.rudder.port", "deg"}, {"command.rudder.stb", "deg"}, {"setpoint.north", "m"},
    {"setpoint.east", "m"},         {"setpoint.heading", "deg"},
};

// A sensor rate or latency that does not fit the log's tick grid is bad input (the vessel file
// together with the scenario's log rate).
std::unique_ptr<detail::SensorLogger> sensor_logger(const ScenarioSpec& spec,
                                                    const VesselConfig& vessel,
                                                    const VesselPlant& plant, std::uint64_t seed) {
  try {
    if (!plant.drives().empty()) {
      return std::make_unique<detail::SensorLogger>(vessel, plant.drives(), spec.log_rate_hz, seed);
    }
    return std::make_unique<detail::SensorLogger>(vessel, plant.propeller(), plant.tunnel(),
                                                  spec.log_rate_hz, seed);
  } catch (const std::invalid_argument& e) {
    throw core::InputError(
        {vessel.source.empty() ? spec.source : vessel.source, {}, {}, {}}, e.what(),
        fmt::format("the log rate is {} Hz: give the sensor a rate that divides it and a "
                    "latency of whole log periods, or change the log rate (--log-rate)",
                    spec.log_rate_hz));
  }
}

// A layout's command channels: the demand and lever, each unit's orders, the setpoint.
std::vector<std::pair<std::string, std::string>> unit_command_channels(
    const std::vector<model::UnitDrive>& drives) {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t k = 0; k < 6; ++k) out.emplace_back(kCommandChannels[k].first, "%");
  for (const model::UnitDrive& d : drives) {
    const std::string& name = d.unit().name;
    out.emplace_back("command.rpm." + name, "rpm");
    out.emplace_back("command.thrust." + name, "kN");
    if (d.unit().type == model::UnitType::kAzimuth)
      out.emplace_back("command.azimuth." + name, "deg");
    if (d.unit().type == model::UnitType::kPropellerRudder) {
      out.emplace_back("command.rudder." + name, "deg");
    }
  }
  for (const char* c : {"setpoint.north", "setpoint.east"}) out.emplace_back(c, "m");
  out.emplace_back("setpoint.heading", "deg");
  return out;
}

}  // namespace

TrialLogger::TrialLogger(core::Log& log, const ScenarioSpec& spec, const VesselConfig& vessel,
                         const VesselPlant& plant, std::uint64_t seed, const ControlTask& control)
    : log_(log),
      control_(control),
      gnss_dropouts_(spec.gnss_dropouts),
      sensors_(sensor_logger(spec, vessel, plant, seed)) {
  sensors_->declare(log_);
  std::size_t commands = std::size(kCommandChannels);
  if (!plant.drives().empty()) {
    const auto channels = unit_command_channels(plant.drives());
    for (const auto& [name, unit] : channels) log_.declare_channel(name, unit);
    commands = channels.size();
  } else {
    for (const auto& [name, unit] : kCommandChannels) log_.declare_channel(name, unit);
  }
  row_.resize(sensors_->channel_count() + commands);
}

TrialLogger::~TrialLogger() = default;

void TrialLogger::record(double t, const VesselSample& sample) {
  const std::span<double> measured(row_);
  sensors_->record(tick_++, sample, measured.first(sensors_->channel_count()),
                   any_covers(gnss_dropouts_, t));
  std::size_t i = sensors_->channel_count();
  const Eigen::Vector3d& demand_pct = control_.demand_pct();
  const Eigen::Vector3d& lever_pct = control_.lever_pct();
  const ActuatorCommands& cmd = control_.commands();
  for (int k = 0; k < 3; ++k) row_[i++] = demand_pct[k];
  for (int k = 0; k < 3; ++k) row_[i++] = lever_pct[k];
  if (!cmd.units.empty()) {
    const auto& drives = control_.plant().drives();
    for (std::size_t k = 0; k < cmd.units.size(); ++k) {
      row_[i++] = cmd.units[k].n_rps * 60.0;
      row_[i++] = cmd.units[k].thrust_N * 1e-3;
      if (drives[k].unit().type == model::UnitType::kAzimuth) {
        row_[i++] = core::rad_to_deg(core::wrap_2pi(cmd.units[k].angle_rad));
      } else if (drives[k].unit().type == model::UnitType::kPropellerRudder) {
        row_[i++] = core::rad_to_deg(cmd.units[k].angle_rad);
      }
    }
    record_setpoint(i);
    log_.append_row(t, row_);
    return;
  }
  row_[i++] = cmd.n_port_rps * 60.0;
  row_[i++] = cmd.n_stb_rps * 60.0;
  row_[i++] = cmd.n_tunnel_rps * 60.0;
  for (int j : {model::ThrustConfiguration::kThrustPort, model::ThrustConfiguration::kThrustStb,
                model::ThrustConfiguration::kTunnel}) {
    row_[i++] = control_.forces_N()[j] * 1e-3;
  }
  row_[i++] = core::rad_to_deg(cmd.rudder_port_rad);
  row_[i++] = core::rad_to_deg(cmd.rudder_stb_rad);
  record_setpoint(i);
  log_.append_row(t, row_);
}

void TrialLogger::record_setpoint(std::size_t i) {
  const Eigen::Vector3d& setpoint = control_.setpoint_n();
  row_[i++] = setpoint.x();
  row_[i++] = setpoint.y();
  row_[i++] =
      control_.dp_active() ? core::rad_to_deg(core::wrap_2pi(setpoint.z())) : core::kMissing;
}

}  // namespace dynpos::scenario
