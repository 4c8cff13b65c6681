#include "dynpos/scenario/hull_drive.hpp"

#include <cmath>
#include <span>

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
  DriveStages one;
  add_point(s, i, i, 0.0, one);
  return point_tau_b(one, 0, nu_r);
}

void HullDrive::add_point(const DriveSeries& s, std::size_t i, std::size_t j, double w,
                          DriveStages& out) const {
  auto mix = [&](const std::vector<double>& v) { return v[i] + w * (v[j] - v[i]); };
  auto mix_angle = [&](const std::vector<double>& v) {
    return v[i] + w * core::wrap_pi(v[j] - v[i]);
  };
  const double psi = mix_angle(s.heading_rad);
  out.heading_rad.push_back(psi);
  out.cos_heading.push_back(std::cos(psi));
  out.sin_heading.push_back(std::sin(psi));
  if (!s.wind_speed_mps.empty()) {
    out.wind_speed_mps.push_back(mix(s.wind_speed_mps));
    out.wind_from_rad.push_back(mix_angle(s.wind_from_rad));
  }
  out.units = s.thrust_N.size();
  for (std::size_t k = 0; k < s.thrust_N.size(); ++k) {
    const double thrust = mix(s.thrust_N[k]);
    // The model's units: the logged thrust is the one at rest, so the shaft speed it stands for
    // gives the thrust at the advance speed (2.25) and the tunnel's speed loss, as in the plant.
    out.input.push_back(!model_units_ ? thrust
                        : k < 2       ? propeller_.shaft_speed_for_thrust(thrust)
                                      : tunnel_.shaft_speed_for_thrust(thrust));
    out.angle.push_back(mix_angle(s.angle_rad[k]));
  }
}

DriveStages HullDrive::stages(const DriveSeries& s) const {
  DriveStages out;
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < n; ++i) {
    add_point(s, i, i, 0.0, out);
    if (i + 1 < n) add_point(s, i, i + 1, 0.5, out);
  }
  return out;
}

Eigen::Vector3d HullDrive::point_tau_b(const DriveStages& st, std::size_t p,
                                       const Eigen::Vector3d& nu_r) const {
  const std::span<const double> input(st.input.data() + p * st.units, st.units);
  const std::span<const double> angle(st.angle.data() + p * st.units, st.units);
  if (!model_units_) return feedback_.tau_b(input, angle);
  // Channels port, stb, tunnel (ThrustFeedback).
  const double u_r = nu_r.x();
  const double port = propeller_.thrust(input[0], u_r);
  const double stb = propeller_.thrust(input[1], u_r);
  const double tunnel = tunnel_.thrust(input[2], u_r);
  return model::model_unit_forces(rudder_, layout_, {port, stb, angle[0], angle[1], tunnel}, nu_r)
      .tau_b;
}

Eigen::Vector3d HullDrive::nu_dot(const DriveStages& st, std::size_t p, const Eigen::Vector3d& nu,
                                  const Eigen::Vector2d& current_n) const {
  const double c = st.cos_heading[p], sn = st.sin_heading[p];
  const Eigen::Vector3d nu_r(nu.x() - (c * current_n.x() + sn * current_n.y()),
                             nu.y() - (-sn * current_n.x() + c * current_n.y()), nu.z());
  Eigen::Vector3d tau = point_tau_b(st, p, nu_r);
  if (!st.wind_speed_mps.empty()) {
    const Eigen::Vector2d velocity_n(c * nu.x() - sn * nu.y(), sn * nu.x() + c * nu.y());
    tau += model::relative_wind_force_b(wind_, st.wind_speed_mps[p], st.wind_from_rad[p],
                                        st.heading_rad[p], velocity_n);
  }
  return hull_.nu_dot(nu, nu_r, tau);
}

std::vector<Eigen::Vector3d> HullDrive::simulate(const DriveSeries& s, const Eigen::Vector3d& nu0,
                                                 const Eigen::Vector2d& current_n,
                                                 const Eigen::Vector2d& current_rate_n) const {
  return simulate(s, stages(s), nu0, current_n, current_rate_n);
}

std::vector<Eigen::Vector3d> HullDrive::simulate(const DriveSeries& s, const DriveStages& st,
                                                 const Eigen::Vector3d& nu0,
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
    const Eigen::Vector3d k1 = nu_dot(st, 2 * i, nu, current);
    const Eigen::Vector3d k2 = nu_dot(st, 2 * i + 1, nu + 0.5 * h * k1, current);
    const Eigen::Vector3d k3 = nu_dot(st, 2 * i + 1, nu + 0.5 * h * k2, current);
    const Eigen::Vector3d k4 = nu_dot(st, 2 * i + 2, nu + h * k3, current);
    nu += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    out[i + 1] = nu;
  }
  return out;
}

}  // namespace dynpos::scenario
