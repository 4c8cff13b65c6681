#pragma once
/// \file
/// Circular statistics of angles: the mean and spread of headings that wrap at 0°/360°.
///
/// A plain mean of 359° and 1° is 180°; the circular mean is 0°. Each angle θᵢ is a unit vector
/// (cos θᵢ, sin θᵢ); with weights wᵢ (all 1 when none are given) and W = Σwᵢ,
///   C̄ = Σwᵢ·cos θᵢ / W,  S̄ = Σwᵢ·sin θᵢ / W,  R̄ = √(C̄² + S̄²) ∈ [0, 1],
///   mean θ̄ = atan2(S̄, C̄),  circular standard deviation σ = √(−2·ln R̄)  (Mardia, 1972).
/// For a small spread σ ≈ the ordinary (population, 1/W) standard deviation of the angles about
/// θ̄ (for a wrapped normal distribution R̄ = e^{−σ²/2}, so it is exact there); σ → ∞ as R̄ → 0.
///
/// Missing samples (NaN angle, or NaN weight) are skipped and not counted. When R̄ is below
/// kMinResultantLength (for example angles spread evenly round the circle) the mean direction
/// is undefined and `mean_rad` is empty; when no sample (or only zero weight) remains,
/// `mean_rad` and `std_rad` are both empty. Neither is ever reported as 0 in place of "undefined".

#include <cstddef>
#include <optional>
#include <span>

namespace dynpos::core {

/// R̄ below which the mean direction is reported as undefined. Rounding in the sums of unit
/// vectors that cancel exactly leaves R̄ of order 1e-16; 1e-9 is far above that and far below
/// any spread that still has a direction worth reporting.
inline constexpr double kMinResultantLength = 1e-9;

/// The circular mean and spread of a set of angles.
struct CircularStats {
  /// θ̄ [rad] in (−π, π]; empty if W = 0 (no samples) or R̄ < kMinResultantLength.
  std::optional<double> mean_rad;
  /// σ = √(−2 ln R̄) [rad], ≥ 0, +∞ if R̄ = 0; empty if W = 0 (no samples).
  std::optional<double> std_rad;
  double resultant_length = 0.0;  ///< R̄ ∈ [0, 1]; 0 when W = 0
  double weight_sum = 0.0;        ///< W = Σwᵢ over the used samples (= count when unweighted)
  std::size_t count = 0;          ///< samples used (angle and weight not NaN)
};

/// Circular mean and standard deviation of angles [rad], skipping NaN (Mardia):
/// θ̄ = atan2(Σ sin θᵢ, Σ cos θᵢ), σ = √(−2 ln R̄), R̄ = |Σ e^{iθᵢ}| / N.
CircularStats circular_stats(std::span<const double> angles_rad);

/// Weighted circular mean and standard deviation of angles [rad], skipping samples whose angle
/// or weight is NaN: θ̄ = atan2(Σwᵢ sin θᵢ, Σwᵢ cos θᵢ), σ = √(−2 ln R̄), R̄ = |Σwᵢ e^{iθᵢ}| / Σwᵢ.
/// A total weight of 0 is treated like no samples (mean and std empty, count still reported).
/// Throws std::invalid_argument if the sizes differ or a weight is negative or infinite.
CircularStats circular_stats(std::span<const double> angles_rad, std::span<const double> weights);

/// Shorthand for circular_stats(angles_rad).mean_rad.
std::optional<double> circular_mean(std::span<const double> angles_rad);

}  // namespace dynpos::core
