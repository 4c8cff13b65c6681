#pragma once
/// \file
/// The sampled state derivative that the practical jump sets use instead of the unknown
/// integral error (thesis (5.80) and (5.92)):
///
///     ẏ_k ≈ (y_k − y_{k−1}) / T_s + w_k,
///
/// where y is sampled every T_s and w_k is white noise. The noise is given as a power in the
/// sense of a band-limited white-noise source (a continuous white noise of two-sided power
/// spectral density `noise_power` [unit²/s²·s] seen through a sample-and-hold of period T_s),
/// so each sample of w has the standard deviation σ_w = √(noise_power / T_s)
/// (sim::discrete_std_from_psd). The thesis uses power 0.1 with T_s = 0.03 s for the first-order
/// example (σ_w ≈ 1.83) and power 20 for the DP example (σ_w ≈ 25.8 per DOF).
///
/// The estimate is built from two samples, and a jump between them changes the slope, so the
/// sampler also reports the time of the older sample: a jump set accepts the estimate only when
/// that sample is not older than the last jump.

#include <Eigen/Core>
#include <cstdint>

#include "dynpos/sim/random.hpp"

namespace dynpos::hybrid {

/// What the difference of two samples is divided by.
enum class SampleSpacing {
  kNominal,   ///< the sample period T_s, as (5.80) and (5.92) write it
  kMeasured,  ///< t_k − t_{k−1} of the times given to sample(): for a caller whose sample
              ///< times are products of a finer tick grid, so that their difference is T_s
              ///< only up to rounding (the DP controller of a scenario run)
};

/// Finite-difference derivative of a sampled vector signal with additive white noise.
class DerivativeSampler {
 public:
  /// A sampler for signals of size n (≥ 1) sampled every sample_period_s [s] (> 0), with
  /// derivative noise of power noise_power (≥ 0, see the file comment), drawn from rng, and
  /// the difference divided as `spacing` says. Throws std::invalid_argument on an
  /// out-of-range argument.
  DerivativeSampler(Eigen::Index n, double sample_period_s, double noise_power, sim::Rng rng,
                    SampleSpacing spacing = SampleSpacing::kNominal);

  /// Takes the sample y_k at time t [s] (the caller samples every T_s). Returns true when an
  /// estimate exists, i.e. from the second sample on; the estimate is then in estimate().
  bool sample(double t, const Eigen::Ref<const Eigen::VectorXd>& y);

  /// (y_k − y_{k−1})/T_s + w_k (T_s or t_k − t_{k−1}, see SampleSpacing), size n; zero before
  /// the second sample.
  const Eigen::VectorXd& estimate() const noexcept { return estimate_; }

  /// Time of y_{k−1}, the older sample of the estimate [s]; NaN before the second sample.
  double older_sample_time() const noexcept { return older_time_; }

  /// σ_w = √(noise_power/T_s), the standard deviation of each noise sample.
  double noise_std() const noexcept { return noise_std_; }

  double sample_period() const noexcept { return period_; }

 private:
  double period_;
  SampleSpacing spacing_;
  double noise_std_;
  sim::Rng rng_;
  Eigen::VectorXd previous_;
  Eigen::VectorXd estimate_;
  double previous_time_;
  double older_time_;
  bool has_previous_ = false;
};

}  // namespace dynpos::hybrid
