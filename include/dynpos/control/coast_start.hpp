#pragma once
/// \file
/// Where an observer starts to coast when a measurement is lost. Under DP in waves an
/// observer's LF velocity ν̂ and bias b̂ carry wave motion and the load's fast part at an instant
/// (on the virtual Gunnerus in H_s 2.5 m up to 0.5 m/s and 10 kN); coasting on them would hold
/// what is there at the instant the measurement goes. So until a DOF's measurement is lost its
/// ν̂ and b̂ are low-passed over a wave period (first order, time constant 2π/ω₀), and when it
/// is lost they start from those means: u, v, b_N and b_E when the position is lost (a GNSS
/// dropout), r and b_ψ when the heading is (a gyro fault).
///
/// A measurement is lost once its last sample is `lost_after_s` old or more: 0 where one
/// comes every step (the DP loop, an observer on held samples), the longest gap between samples
/// where a filter takes each sample once (an EKF on a log's 1 Hz fixes): there the steps between
/// fixes are not a loss.

#include <Eigen/Core>

namespace dynpos::control {

class CoastStart {
 public:
  /// The wave peak frequency ω₀ per DOF (N, E, ψ) [rad/s] sets the time constants; lost_after_s
  /// [s] ≥ 0 (see the file comment).
  explicit CoastStart(const Eigen::Vector3d& wave_peak_frequency_rad_s, double lost_after_s = 0.0);

  /// Before a step on the measurement y (N, E, ψ; NaN: missing): where the position or the
  /// heading is lost now, ν̂ (BODY) and b̂ (NED) of its DOFs become their means.
  void start_if_lost(const Eigen::Vector3d& y_n, Eigen::Ref<Eigen::Vector3d> nu_b,
                     Eigen::Ref<Eigen::Vector3d> bias_n);

  /// After a step of dt [s]: the means of the DOFs not lost follow ν̂ and b̂.
  void track(const Eigen::Vector3d& nu_b, const Eigen::Vector3d& bias_n, double dt_s);

 private:
  // The position's (0) and the heading's (1) state.
  struct Channel {
    double missing_s = 0.0;  // the age of its last sample
    bool lost = false;
  };
  Eigen::Vector3d wave_peak_frequency_rad_s_;
  double lost_after_s_;
  Eigen::Vector3d nu_mean_b_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d bias_mean_n_ = Eigen::Vector3d::Zero();
  Channel channel_[2];
};

}  // namespace dynpos::control
