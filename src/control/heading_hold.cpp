#include "dynpos/control/heading_hold.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynpos/core/angle.hpp"

namespace dynpos::control {

void HeadingHoldParams::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(inertia_kgm2)) throw std::invalid_argument("HeadingHoldParams.inertia_kgm2 > 0");
  if (!(std::isfinite(yaw_damping_Nms) && yaw_damping_Nms >= 0.0)) {
    throw std::invalid_argument("HeadingHoldParams.yaw_damping_Nms >= 0");
  }
  if (!positive(omega_rad_s)) throw std::invalid_argument("HeadingHoldParams.omega_rad_s > 0");
  if (!positive(zeta)) throw std::invalid_argument("HeadingHoldParams.zeta > 0");
  if (!positive(max_yaw_Nm)) throw std::invalid_argument("HeadingHoldParams.max_yaw_Nm > 0");
  if (!positive(rate_hz)) throw std::invalid_argument("HeadingHoldParams.rate_hz > 0");
  if (!std::isfinite(heading_rad)) throw std::invalid_argument("HeadingHoldParams.heading_rad");
}

HeadingHold::HeadingHold(const HeadingHoldParams& params) : params_(params) {
  params_.validate();
  const double w = params_.omega_rad_s;
  kp_ = params_.inertia_kgm2 * w * w;
  kd_ = std::max(0.0, 2.0 * params_.zeta * w * params_.inertia_kgm2 - params_.yaw_damping_Nms);
  ki_ = kp_ * w / 10.0;  // integral time 10/ω
}

double HeadingHold::update(double operator_fraction, double heading_rad, double yaw_rate_rad_s) {
  const double psi_err = core::angle_diff(heading_rad, params_.heading_rad);
  const double yaw_Nm = -kp_ * psi_err - kd_ * yaw_rate_rad_s - integral_Nm_;
  const double fraction = operator_fraction + yaw_Nm / params_.max_yaw_Nm;
  const double clamped = std::clamp(fraction, -1.0, 1.0);
  if (fraction == clamped) integral_Nm_ += ki_ * psi_err / params_.rate_hz;
  return clamped;
}

}  // namespace dynpos::control
