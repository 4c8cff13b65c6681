#pragma once
/// \file
/// The quadratic thrust map of a fixed-pitch propeller, (3.17): T = c·n², with a different
/// coefficient for each sign of the shaft speed n [rps] (c = ρK_T D⁴, (2.25)):
///
///     T = c₊·n² for n ≥ 0,  T = c₋·n² for n < 0  (c₊ > 0, c₋ < 0; T = |c±|·n|n|).
///
/// fit_thrust_map() back-calculates c₊ and c₋ by least squares from a log with both thrust
/// and shaft speed (section 3.4.1, table 3.2: 8.13 and −5.8 kN/rps²); thrust() applies a map
/// to a log with shaft speed only. When only |n| is logged the direction is unknown and the
/// mean magnitude c̄ = (c₊ + |c₋|)/2 is used, (3.18), giving |T| ≈ c̄·n².
///
/// Units: n in rps, T in N, c in N/rps² (= N·s²); the thesis's kN/rps² are 1000 N/rps².

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dynpos/ident/fit_status.hpp"

namespace dynpos::ident {

/// A thrust map (3.17).
struct ThrustMap {
  double c_forward = 0.0;  ///< c₊ [N/rps²], for n ≥ 0
  double c_reverse = 0.0;  ///< c₋ [N/rps²], for n < 0 (negative for a normal propeller)

  /// T = c₊·n² for n ≥ 0, c₋·n² for n < 0 [N]; NaN stays NaN.
  double thrust(double n_rps) const;
  /// thrust() of every sample.
  std::vector<double> thrust(std::span<const double> n_rps) const;
  /// Mean magnitude c̄ = (c₊ + |c₋|)/2 [N/rps²], (3.18).
  double mean_coefficient() const;
};

/// Thrust magnitude from |n| only with the mean coefficient (3.18): |T| = c̄·n² [N].
std::vector<double> thrust_from_abs_speed(double c_mean, std::span<const double> n_abs_rps);

/// Options for fit_thrust_map().
struct ThrustMapFitOptions {
  /// Samples with |n| below this [rps] ≥ 0 are left out: near zero the thrust is noise and
  /// the sign of n uncertain.
  double min_abs_shaft_speed_rps = 0.05;
  /// Channel names used in error messages.
  std::string shaft_speed_name = "shaft speed";
  std::string thrust_name = "thrust";

  /// Throws core::InputError naming the bad option.
  void validate() const;
};

/// Result of fit_thrust_map(). A coefficient is absent when no sample has that sign.
struct ThrustMapFitResult {
  FitStatus status = FitStatus::kFailed;
  std::string message;
  std::optional<Estimate> c_forward;  ///< c₊ [N/rps²] with 1σ
  std::optional<Estimate> c_reverse;  ///< c₋ [N/rps²] with 1σ
  std::size_t samples_forward = 0;
  std::size_t samples_reverse = 0;
  std::optional<double> r_squared;     ///< of T against the map, both signs together
  std::optional<double> rms_residual;  ///< [N]
  std::vector<FitWarning> warnings;

  /// The map; a missing coefficient is taken as 0 — check c_forward/c_reverse before use.
  /// nullopt when status is kFailed.
  std::optional<ThrustMap> map() const;
};

/// Back-calculates c₊ and c₋ of (3.17): for each sign, c = Σ Tᵢnᵢ²/Σ nᵢ⁴ (least squares through
/// the origin), σ_c = s/√(Σ nᵢ⁴) with s² the residual variance of that sign.
/// Pairs with a NaN are skipped. Throws core::InputError if the lengths differ or the options
/// are invalid; status kFailed when no sample has |n| ≥ min_abs_shaft_speed_rps.
ThrustMapFitResult fit_thrust_map(std::span<const double> n_rps, std::span<const double> thrust_N,
                                  const ThrustMapFitOptions& options = {});

}  // namespace dynpos::ident
