#include "dynpos/scenario/hull_drive.hpp"

#include <cmath>

#include "dynpos/core/angle.hpp"
#include "dynpos/model/environment.hpp"
#include "dynpos/model/model_unit_forces.hpp"

namespace dynpos::scenario {

HullDrive::HullDrive(const VesselConfig& vessel)
    : hull_(vessel.hull),
      propeller_(vessel.propeller),
      rudder_(vessel.rudder),
      tunnel_(vessel.tunnel),
      layout_(vessel.layout),
      wind_(vessel.wind),
      feedback_(vessel),
      model_units_(vessel.thrusters.empty()) {}

Eigen::Vector3d HullDrive::actuator_tau_b(const DriveSeries& s, std::size_t i,
                                          const Eigen::Vector3d& nu_r) const {
  return mixed_tau_b(s, i, i, 0.0, nu_r);
}

Eigen::Vector3d HullDrive::mixed_tau_b(const DriveSeries& s, std::size_t i, std::size_t j, double w,
                                       const Eigen::Vector3d& nu_r) const {
  auto mix = [&](const std::vector<double>& v) { return v[i] + w * (v[j] - v[i]); };
  auto mix_angle = [&](const std::vector<double>& v) {
    return v[i] + w * core::wrap_pi(v[j] - v[i]);
  };
  if (!model_units_) {
    std::vector<double> thrust(s.thrust_N.size()), angle(s.thrust_N.size());
    for (std::size_t k = 0; k < thrust.size(); ++k) {
      thrust[k] = mix(s.thrust_N[k]);
      angle[k] = mix_angle(s.angle_rad[k]);
    }
    return feedback_.tau_b(thrust, angle);
  }
  // Channels port, stb, tunnel (ThrustFeedback): the logged thrust is the one at rest, so the
  // shaft speed it stands for gives the thrust at the advance speed (2.25) and the tunnel's
  // speed loss, as in the plant.
  const double u_r = nu_r.x();
  const double port = propeller_.thrust(propeller_.shaft_speed_for_thrust(mix(s.thrust_N[0])), u_r);
  const double stb = propeller_.thrust(propeller_.shaft_speed_for_thrust(mix(s.thrust_N[1])), u_r);
  const double tunnel = tunnel_.thrust(tunnel_.shaft_speed_for_thrust(mix(s.thrust_N[2])), u_r);
  return model::model_unit_forces(
             rudder_, layout_,
             {port, stb, mix_angle(s.angle_rad[0]), mix_angle(s.angle_rad[1]), tunnel}, nu_r)
      .tau_b;
}

Eigen::Vector3d HullDrive::nu_dot(const DriveSeries& s, std::size_t i, std::size_t j, double w,
                                  const Eigen::Vector3d& nu,
                                  const Eigen::Vector2d& current_n) const {
  const double psi = s.heading_rad[i] + w * core::wrap_pi(s.heading_rad[j] - s.heading_rad[i]);
  const double c = std::cos(psi), sn = std::sin(psi);
  const Eigen::Vector3d nu_r(nu.x() - (c * current_n.x() + sn * current_n.y()),
                             nu.y() - (-sn * current_n.x() + c * current_n.y()), nu.z());
  Eigen::Vector3d tau = mixed_tau_b(s, i, j, w, nu_r);
  if (!s.wind_speed_mps.empty()) {
    const Eigen::Vector2d velocity_n(c * nu.x() - sn * nu.y(), sn * nu.x() + c * nu.y());
    const double speed = s.wind_speed_mps[i] + w * (s.wind_speed_mps[j] - s.wind_speed_mps[i]);
    const double from =
        s.wind_from_rad[i] + w * core::wrap_pi(s.wind_from_rad[j] - s.wind_from_rad[i]);
    tau += model::relative_wind_force_b(wind_, speed, from, psi, velocity_n);
  }
  model::Hull::State x = model::Hull::State::Zero();
  x[model::Hull::kYaw] = psi;
  x.segment<3>(model::Hull::kSurge) = nu;
  return hull_.derivatives(x, tau, current_n).segment<3>(model::Hull::kSurge);
}

std::vector<Eigen::Vector3d> HullDrive::simulate(const DriveSeries& s, const Eigen::Vector3d& nu0,
                                                 const Eigen::Vector2d& current_n,
                                                 const Eigen::Vector2d& current_rate_n) const {
  std::vector<Eigen::Vector3d> out(s.size());
  if (s.size() == 0) return out;
  Eigen::Vector3d nu = nu0;
  out[0] = nu;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const double h = s.time_s[i + 1] - s.time_s[i];
    const Eigen::Vector2d current =
        current_n + current_rate_n * (0.5 * (s.time_s[i] + s.time_s[i + 1]) - s.time_s[0]);
    const Eigen::Vector3d k1 = nu_dot(s, i, i + 1, 0.0, nu, current);
    const Eigen::Vector3d k2 = nu_dot(s, i, i + 1, 0.5, nu + 0.5 * h * k1, current);
    const Eigen::Vector3d k3 = nu_dot(s, i, i + 1, 0.5, nu + 0.5 * h * k2, current);
    const Eigen::Vector3d k4 = nu_dot(s, i + 1, i + 1, 0.0, nu + h * k3, current);
    nu += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    out[i + 1] = nu;
  }
  return out;
}

}  // namespace dynpos::scenario
