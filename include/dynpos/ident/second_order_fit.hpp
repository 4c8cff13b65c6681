#pragma once
/// \file
/// Second-order-plus-dead-time (SOPDT) fits of a step response from characteristic points.
///
/// The model is (3.6) with a dead time, for an overdamped process:
///
///     G(s) = K·e^{−θs} / ((T₁s + 1)(T₂s + 1)),  T₁ ≥ T₂ ≥ 0,
///     y(t) = y₀ + K·Δu·g(t − t₀ − θ),  g(τ) = 1 − (T₁e^{−τ/T₁} − T₂e^{−τ/T₂})/(T₁ − T₂),
///
/// (g(τ) = 1 − (1 + τ/T)e^{−τ/T} when T₁ = T₂ = T), equivalently ω-form τₙ = √(T₁T₂),
/// ζ = (T₁ + T₂)/(2√(T₁T₂)) ≥ 1. Section 3.2.1 names two methods and notes their low
/// precision; both are implemented here:
///
/// - Smith's method (Smith 1972, in Seborg et al. 2004): the times t₂₀ and t₆₀ where the
///   response has covered 20 % and 60 % of Δy, counted from the end of the dead time.
///   (t₂₀ − θ)/(t₆₀ − θ) depends only on the ratio ρ = T₂/T₁ and gives it; then
///   T₁ = (t₆₀ − θ)/τ₆₀(ρ) with τ₆₀ the 60 % time of g for T₁ = 1. Smith reads θ off the plot
///   first; here θ is `dead_time_s` when given, otherwise the point where the response has
///   covered `onset_fraction` of Δy is used as a third point and θ, ρ, T₁ are solved from the
///   three (as below).
/// - Rangaiah and Krishnaswamy (1994): three points, 14 %, 55 % and 91 %.
///   (t₉₁ − t₅₅)/(t₅₅ − t₁₄) is free of θ and of the time scale and gives ρ; then
///   T₁ = (t₉₁ − t₁₄)/(τ₉₁(ρ) − τ₁₄(ρ)) and θ = t₅₅ − T₁·τ₅₅(ρ).
///
/// Both papers publish charts or regression formulas for these relations; here the exact
/// relations are solved numerically (bisection on ρ ∈ [0, 1], and on τ for each fraction), so
/// there is no table error. A measured ratio outside the overdamped range (faster than first
/// order, or more S-shaped than two equal time constants) is clamped to ρ = 0 or ρ = 1 with
/// WarningCode::kShapeOutOfRange. Levels and crossing times are read as in fopdt_fit.hpp.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dynpos/ident/fit_status.hpp"
#include "dynpos/ident/step_detector.hpp"

namespace dynpos::ident {

/// The SOPDT step response with its parameters.
struct SecondOrderModel {
  double t_step = 0.0;           ///< t₀ [s]
  double y0 = 0.0;               ///< output before the step [output unit]
  double amplitude = 0.0;        ///< A = K·Δu [output unit]
  double time_constant_1 = 1.0;  ///< T₁ [s], > 0, the larger
  double time_constant_2 = 0.0;  ///< T₂ [s], in [0, T₁]
  double dead_time = 0.0;        ///< θ [s]

  /// Response y = y₀ + A·g(t − t₀ − θ) (see the file comment), y₀ before t₀ + θ.
  double operator()(double t) const;
};

/// Normalised step response g(τ) of 1/((T₁s + 1)(T₂s + 1)), T₁ ≥ T₂ ≥ 0, T₁ > 0; 0 for τ ≤ 0.
double second_order_unit_step(double tau, double t1, double t2);

/// Which characteristic-point method fit_second_order() uses.
enum class SecondOrderMethod {
  kSmith,                 ///< 20 % and 60 % times (plus θ or an onset point)
  kRangaiahKrishnaswamy,  ///< 14 %, 55 % and 91 % times
};

/// Options for fit_second_order().
struct SecondOrderFitOptions {
  SecondOrderMethod method = SecondOrderMethod::kRangaiahKrishnaswamy;
  /// Smith: known dead time θ [s] ≥ 0 from the step time.
  std::optional<double> dead_time_s;
  /// Smith without dead_time_s: the fraction of Δy, in (0, 0.2), used as the third point.
  double onset_fraction = 0.05;
  /// As in FopdtFitOptions.
  std::optional<double> pre_step_s;
  double tail_fraction = 0.2;
  double steady_state_tolerance = 0.02;
  double min_r_squared = 0.9;
  std::size_t min_samples = 20;
  std::string output_name = "output";

  /// Throws core::InputError naming the bad option.
  void validate() const;
};

/// Result of fit_second_order(). Estimates are absent when status is kFailed.
struct SecondOrderFitResult {
  FitStatus status = FitStatus::kFailed;
  std::string message;
  SecondOrderMethod method = SecondOrderMethod::kRangaiahKrishnaswamy;
  double t_step = 0.0;                    ///< t₀ used [s]
  std::optional<double> y0;               ///< [output unit]
  std::optional<double> amplitude;        ///< A = Δy [output unit]
  std::optional<double> gain;             ///< K = Δy/Δu, (3.4); absent when Δu is unknown
  std::optional<double> time_constant_1;  ///< T₁ [s]
  std::optional<double> time_constant_2;  ///< T₂ [s]
  std::optional<double> dead_time;        ///< θ [s]
  std::optional<double> natural_period;   ///< τₙ = √(T₁T₂) [s]
  std::optional<double> damping_ratio;  ///< ζ = (T₁ + T₂)/(2√(T₁T₂)); absent when T₂ = 0
  std::optional<double> r_squared;      ///< of the model against the window
  std::optional<double> rms_residual;  ///< [output unit]
  std::size_t samples = 0;
  std::vector<FitWarning> warnings;

  /// The fitted model, or nullopt when status is kFailed.
  std::optional<SecondOrderModel> model() const;
};

/// Fits the SOPDT model to y(t) over step.t_begin … step.t_end by the chosen method.
/// Throws core::InputError in the cases listed for fit_fopdt().
SecondOrderFitResult fit_second_order(std::span<const double> t, std::span<const double> y,
                                      const Step& step, const SecondOrderFitOptions& options = {});

}  // namespace dynpos::ident
