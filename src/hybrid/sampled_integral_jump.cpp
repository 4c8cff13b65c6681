#include "dynpos/hybrid/sampled_integral_jump.hpp"

namespace dynpos::hybrid {

SampledIntegralJump::SampledIntegralJump(const IntegralJumpParams& params,
                                         const control::DpControllerParams& controller,
                                         double sample_period_s)
    : params_((params.validate(), params)),
      M_(controller.M),
      Kd_(controller.Kd),
      Ki_(controller.Ki),
      // Noise-free (power 0): the engine is never drawn from.
      x2_dot_(3, sample_period_s, 0.0, sim::Rng(0), SampleSpacing::kMeasured),
      dwell_(params.dwell_s) {}

std::optional<Eigen::Vector3d> SampledIntegralJump::step(double t, const Eigen::Vector3d& x1_b,
                                                         const Eigen::Vector3d& x2_b,
                                                         double psi_rad) {
  if (!x2_dot_.sample(t, x2_b)) return std::nullopt;
  // Both samples after the last jump, and the dwell time since it.
  const std::optional<double>& last_jump = dwell_.last_jump_time();
  if (last_jump && !(x2_dot_.older_sample_time() >= *last_jump)) return std::nullopt;
  if (!dwell_.allows(t)) return std::nullopt;
  const Eigen::Vector3d x2_dot_b = x2_dot_.estimate();
  const Eigen::Vector3d x3_hat_n = estimate_integral_error(M_, Kd_, x1_b, x2_b, x2_dot_b, psi_rad);
  if (!in_integral_jump_set(params_, Ki_, x1_b, x2_b, x3_hat_n, psi_rad)) return std::nullopt;
  dwell_.record_jump(t);
  jump_times_.push_back(t);
  return integral_jump(params_, x2_b, psi_rad);  // (5.47)
}

}  // namespace dynpos::hybrid
