#include "dynpos/control/inertial_position.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace dynpos::control {
namespace {

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

// The velocity's σ at the first fix [m/s]. Source: reasoned — a vessel taken over by DP at up to
// about 1 kn; the filter settles on its fixes within seconds.
constexpr double kInitialVelocityStd = 0.5;

}  // namespace

void InertialPositionTuning::validate() const {
  if (!positive(accel_std_mps2) || !positive(position_std_m) || !positive(max_position_std_m)) {
    throw std::invalid_argument(
        "inertial position: the acceleration and fix noise and the largest position sigma must "
        "be finite and > 0");
  }
  if (!(accel_bias_std_mps2 >= 0.0) || !std::isfinite(accel_bias_std_mps2) ||
      !positive(accel_bias_time_constant_s)) {
    throw std::invalid_argument(
        "inertial position: the accelerometer bias sigma must be finite and >= 0, its time "
        "constant finite and > 0");
  }
}

InertialPosition::InertialPosition(const InertialPositionTuning& tuning) : tuning_(tuning) {
  tuning_.validate();
}

double InertialPosition::position_std_m() const { return std::sqrt(P_(0, 0)); }

Eigen::Vector2d InertialPosition::step(const Eigen::Vector2d& fix_n, const Eigen::Vector2d& accel_n,
                                       double dt_s) {
  if (!positive(dt_s)) {
    throw std::invalid_argument("inertial position: the step dt must be finite and > 0");
  }
  const bool fix = fix_n.allFinite();
  bridging_ = false;
  if (started_ && accel_n.allFinite()) {
    const double phi = std::exp(-dt_s / tuning_.accel_bias_time_constant_s);
    Eigen::Matrix3d F;
    F << 1.0, dt_s, -0.5 * dt_s * dt_s, 0.0, 1.0, -dt_s, 0.0, 0.0, phi;
    const Eigen::Vector3d B(0.5 * dt_s * dt_s, dt_s, 0.0);
    x_ = F * x_ + B * accel_n.transpose();
    const double bias_var = tuning_.accel_bias_std_mps2 * tuning_.accel_bias_std_mps2;
    P_ = F * P_ * F.transpose() +
         tuning_.accel_std_mps2 * tuning_.accel_std_mps2 * B * B.transpose();
    P_(2, 2) += bias_var * (1.0 - phi * phi);
  } else {
    valid_ = false;  // no acceleration over the step: only a fix restarts the state
  }
  if (fix) {
    if (!started_ || !valid_) {
      // The bias learnt so far is kept (it is the sensor's); position and velocity restart.
      x_.row(0) = fix_n.transpose();
      x_.row(1).setZero();
      const double bias_var =
          started_ ? P_(2, 2) : tuning_.accel_bias_std_mps2 * tuning_.accel_bias_std_mps2;
      P_.setZero();
      P_.diagonal() << tuning_.position_std_m * tuning_.position_std_m,
          kInitialVelocityStd * kInitialVelocityStd, bias_var;
      started_ = valid_ = true;
      return fix_n;
    }
    const double S = P_(0, 0) + tuning_.position_std_m * tuning_.position_std_m;
    const Eigen::Vector3d K = P_.col(0) / S;
    x_ += K * (fix_n.transpose() - x_.row(0));
    P_ -= K * P_.row(0);
    P_ = 0.5 * (P_ + P_.transpose()).eval();
    return fix_n;
  }
  if (valid_ && position_std_m() <= tuning_.max_position_std_m) {
    bridging_ = true;
    return x_.row(0).transpose();
  }
  valid_ = false;  // the bridge is over: the next fix restarts it (the bias learnt is kept)
  return Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
}

}  // namespace dynpos::control
