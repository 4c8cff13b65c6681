#pragma once
/// \file
/// The practical jump rule of hybrid integral action (5.64)–(5.67) inside a discrete DP
/// controller that runs at a fixed control rate on a real (or virtual) vessel: at each control
/// step it samples x₂, estimates ẋ₂ by the finite difference of two samples
/// (derivative_sampler.hpp, (5.92)), evaluates the jump set of integral_jump.hpp at
/// x̂₃ = R(ψ)(Mẋ₂ + x₁ + K_d x₂) and, when the state is in it, returns the jump Δb̂ = ΛR(ψ)x₂
/// (5.47) for the controller to add to its bias estimate.
///
/// The rule takes an estimate only when both of its samples are from after the last jump (a
/// jump changes ẋ₂; see first_order_system.hpp), and jumps at most once per dwell time
/// (sim/dwell_time.hpp, τ_D = IntegralJumpParams::dwell_s, compared exactly: the jumps happen
/// at control steps, not at located events). The controller's states come from an ideal
/// observer, so the derivative is noise-free; it is divided by the time between the two
/// samples (SampleSpacing::kMeasured).

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "dynpos/control/dp_controller.hpp"
#include "dynpos/hybrid/derivative_sampler.hpp"
#include "dynpos/hybrid/integral_jump.hpp"
#include "dynpos/sim/dwell_time.hpp"

namespace dynpos::hybrid {

/// The sampled jump rule of a discrete DP controller (see the file comment).
class SampledIntegralJump {
 public:
  /// The rule `params` for a controller with model M and gains K_d, K_i of `controller`,
  /// stepped every sample_period_s [s] (> 0). Throws std::invalid_argument if params.validate()
  /// does or the period is not positive.
  SampledIntegralJump(const IntegralJumpParams& params,
                      const control::DpControllerParams& controller, double sample_period_s);

  /// One control step at time t [s] with the controller's errors x₁ (BODY) [m, m, rad] and x₂
  /// (BODY) [m/s, m/s, rad/s] at heading ψ [rad]: the jump Δb̂ (NED) [N, N, N·m] when the
  /// practical jump set (5.65)–(5.67) holds and the dwell time allows it, else nothing.
  std::optional<Eigen::Vector3d> step(double t, const Eigen::Vector3d& x1_b,
                                      const Eigen::Vector3d& x2_b, double psi_rad);

  /// The times of the jumps taken [s], in order.
  const std::vector<double>& jump_times() const noexcept { return jump_times_; }

  const IntegralJumpParams& params() const noexcept { return params_; }

 private:
  IntegralJumpParams params_;
  Eigen::Matrix3d M_;
  Eigen::Matrix3d Kd_;
  Eigen::Matrix3d Ki_;
  DerivativeSampler x2_dot_;
  sim::DwellTime dwell_;
  std::vector<double> jump_times_;
};

}  // namespace dynpos::hybrid
