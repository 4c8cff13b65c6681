#pragma once
/// \file
/// A position reference bridged through a GNSS loss by dead reckoning on the measured
/// acceleration: what a DP system with an inertial sensor does instead of coasting its observer
/// on the model alone. Without fixes an observer's model holds the load of seconds ago while the
/// slowly varying wave drift and the gusts go on changing; under DP in H_s 2.5 m that moved the
/// virtual Gunnerus up to 2.6 m from its estimate in 30 s, and holding even the true mean load
/// of the last wave period would have moved it up to 1.5 m (docs/theory.md, "Dead
/// reckoning"). The MRU measures the acceleration itself.
///
/// Per horizontal axis (N, E) a Kalman filter of the total position p and velocity v (LF plus
/// WF motion) of the control origin and the accelerometer's bias β, driven by the measured
/// acceleration a (BODY turned into NED by the measured heading), corrected by each fix:
///
///     p ← p + v dt + (a − β) dt²/2,   v ← v + (a − β) dt,   β ← φ β,   φ = e^(−dt/T_β)
///     P ← F P Fᵀ + B Bᵀ σ_a² + diag(0, 0, σ_β² (1 − φ²))          (B = [dt²/2; dt; 0])
///     K = P Hᵀ/(H P Hᵀ + σ_p²),  H = [1 0 0]
///
/// with σ_a the accelerometer's white noise per sample, β a Gauss–Markov bias of stationary σ_β
/// and time constant T_β (a levelling error of 0.01° is 1.7e-3 m/s² of gravity), learnt from the
/// fixes and held through the loss, and σ_p the fix's noise. Between fixes the
/// filter runs on the acceleration alone: its position is the reference the observer takes in
/// place of the missing fix, with the WF motion in it as in a fix, so the observer's wave model
/// goes on separating it. The error grows as σ_a √(dt t³/3) (0.3 m in 30 s for 0.01 m/s² at
/// 10 Hz) plus the velocity's at the loss times t; the bridge ends (the position is missing
/// again and the observer coasts on its model) once the filter's own position σ exceeds
/// max_position_std_m; the next fix restarts it, with the bias learnt so far.

#include <Eigen/Core>

namespace dynpos::control {

/// The noise of the bridge (see the file comment).
struct InertialPositionTuning {
  /// σ_a: white noise of each acceleration sample [m/s²]. Source: an MRU 5 class accelerometer
  /// (0.01 m/s², the virtual Gunnerus's MRUs).
  double accel_std_mps2 = 0.01;
  /// σ_β: stationary σ of the accelerometer's bias [m/s²], ≥ 0 (0: none). Source: reasoned — a
  /// levelling error of about 0.01° (1.7e-3 m/s²).
  double accel_bias_std_mps2 = 2e-3;
  /// T_β: the bias's time constant [s]. Source: reasoned — drifts over minutes, as the MRUs'
  /// Gauss–Markov biases (sensors/mru.hpp).
  double accel_bias_time_constant_s = 600.0;
  /// σ_p: white noise of a fix [m]. Source: RTK (1–2 cm, gnss_receiver.hpp).
  double position_std_m = 0.02;
  /// The bridge ends once the position's σ exceeds this [m]. Source: reasoned — a third of a 3 m
  /// DP footprint; with the defaults at 10 Hz it is reached after 46 s (65 s without a bias;
  /// the virtual Gunnerus's MRU averaged to 10 Hz, 3.2e-3 m/s², with 1 cm fixes: 142 s).
  double max_position_std_m = 1.0;
  /// Throws std::invalid_argument unless every value is finite and > 0 (σ_β ≥ 0).
  void validate() const;
};

class InertialPosition {
 public:
  /// Throws std::invalid_argument on a bad tuning.
  explicit InertialPosition(const InertialPositionTuning& tuning = {});

  /// One step of dt [s] (> 0): predicts on the acceleration over it (N, E) NED [m/s²], then
  /// corrects on the fix at its end (N, E) [m] (either NaN: missing). Returns the fix when there
  /// is one; without, the dead-reckoned position while the bridge holds (see the file comment);
  /// NaN otherwise (no fix yet, a missing acceleration since the last fix, or the bridge over).
  Eigen::Vector2d step(const Eigen::Vector2d& fix_n, const Eigen::Vector2d& accel_n, double dt_s);

  /// Whether the last step's position was dead-reckoned.
  bool bridging() const noexcept { return bridging_; }
  /// The filter's position σ [m] after the last step.
  double position_std_m() const;

 private:
  InertialPositionTuning tuning_;
  bool started_ = false;  // a fix has been taken
  bool valid_ = false;    // the state has followed the acceleration since the last fix
  bool bridging_ = false;
  Eigen::Matrix<double, 3, 2> x_ = Eigen::Matrix<double, 3, 2>::Zero();  // cols N, E; rows p, v, β
  Eigen::Matrix3d P_ = Eigen::Matrix3d::Zero();  // of (p, v, β), the same on both axes
};

}  // namespace dynpos::control
