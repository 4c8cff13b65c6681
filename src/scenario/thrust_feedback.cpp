#include "dynpos/scenario/thrust_feedback.hpp"

#include <stdexcept>

#include "dynpos/model/model_unit_forces.hpp"

namespace dynpos::scenario {
namespace {

std::string angle_role(const model::ThrusterUnit& unit) {
  switch (unit.type) {
    case model::UnitType::kAzimuth:
      return "azimuth." + unit.name;
    case model::UnitType::kPropellerRudder:
      return "rudder." + unit.name;
    case model::UnitType::kTunnel:
    case model::UnitType::kPropeller:
      break;
  }
  return {};
}

}  // namespace

ThrustFeedback::ThrustFeedback(const VesselConfig& vessel)
    : rudder_(vessel.rudder), layout_(vessel.layout) {
  for (const model::ThrusterUnit& unit : vessel.thrusters) {
    drives_.emplace_back(unit);
    channels_.push_back({unit.name, "thrust." + unit.name, angle_role(unit)});
  }
  if (drives_.empty()) {
    channels_ = {{"port", "thrust.port", "rudder.port"},
                 {"stb", "thrust.stb", "rudder.stb"},
                 {"tunnel", "thrust.tunnel", ""}};
  }
}

Eigen::Vector3d ThrustFeedback::tau_b(std::span<const double> thrust_N,
                                      std::span<const double> angle_rad) const {
  if (thrust_N.size() != channels_.size() || angle_rad.size() != channels_.size()) {
    throw std::invalid_argument("ThrustFeedback: one thrust and one angle per unit");
  }
  if (drives_.empty()) return model_tau_b(thrust_N, angle_rad);
  Eigen::Vector3d tau = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < drives_.size(); ++k) {
    const model::UnitDrive& d = drives_[k];
    const double angle = channels_[k].angle_role.empty() ? 0.0 : angle_rad[k];
    tau += d.outputs(d.shaft_speed_for(thrust_N[k]), angle).tau_b;
  }
  return tau;
}

Eigen::Vector3d ThrustFeedback::model_tau_b(std::span<const double> thrust_N,
                                            std::span<const double> angle_rad) const {
  // The order of channels_: port, stb, tunnel. At rest in the water only the slipstream flows
  // past the rudders (see the file comment).
  return model::model_unit_forces(
             rudder_, layout_, {thrust_N[0], thrust_N[1], angle_rad[0], angle_rad[1], thrust_N[2]},
             Eigen::Vector3d::Zero())
      .tau_b;
}

}  // namespace dynpos::scenario
