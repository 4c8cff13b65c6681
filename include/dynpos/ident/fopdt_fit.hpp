#pragma once
/// \file
/// First-order-plus-dead-time (FOPDT) fits of a step response, (3.7):
///
///     G(s) = K·e^{−δs}/(Ts + 1),   y(t) = y₀ + K·Δu·(1 − e^{−(t−t₀−δ)/T}) for t ≥ t₀ + δ,
///
/// y(t) = y₀ before, with t₀ the step time and Δu the step in the input.
///
/// Methods:
/// - FopdtMethod::kLeastSquares (default): y₀, A = K·Δu, T and δ minimise the sum of squared
///   residuals over the window (Levenberg–Marquardt, started from Smith's estimate and two
///   other guesses; the best is kept). Standard deviations come from σ²(JᵀJ)⁻¹ at the optimum
///   with σ² = SSE/(N − p); they assume white residuals and are too small for coloured noise.
/// - FopdtMethod::kSmith: Smith's two-point method (3.8)–(3.9): t₁ and t₂ where the response
///   has covered 28.3 % and 63.2 % of Δy, T = 1.5·(t₂ − t₁), δ = t₂ − T (times from t₀).
///
/// Levels: y₀ is the mean of the output over the pre-step part of the window, y∞ the mean over
/// its last `tail_fraction`; the static gain is K = Δy/Δu = (y∞ − y₀)/Δu, (3.4)–(3.5). With
/// noise, a crossing time is the mean of the first and the last crossing of the level between
/// the last time the output was 3σ̂ below it and the first time it was 3σ̂ above it.
///
/// Warnings (data, not errors): steady state not reached (a straight line fitted to the tail
/// changes by more than max(2·σ_tail, steady_state_tolerance·|Δy|) over the tail), short window
/// (less than 3T after the dead time: under 95 % of the response seen), poor fit (R² below
/// min_r_squared), few samples, dead time at its bound.
///
/// Status: a fit is kFailed, with the reason in the message, when it is no estimate of the
/// system: T over 10 times the window after the dead time (under 10 % of the response seen: the
/// output does not settle, T and K are extrapolated) or at its lower search limit, δ at its
/// upper search limit, a standard deviation that cannot be computed (least squares), or R²
/// below min_r_squared (default 0.9: the model explains less than 90 % of the output's variance
/// over the window, so the shape is not a first-order step response or the step is lost in
/// the noise: with white noise σ, R² ≈ 1 − σ²/(σ² + var(model))). Such a result keeps its
/// values for diagnosis; model() is nullopt. δ = 0 is a physical limit: a warning only.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dynpos/ident/fit_status.hpp"
#include "dynpos/ident/step_detector.hpp"

namespace dynpos::ident {

/// The FOPDT step response (3.7) with its parameters.
struct FopdtModel {
  double t_step = 0.0;         ///< t₀ [s]
  double y0 = 0.0;             ///< output before the step [output unit]
  double amplitude = 0.0;      ///< A = K·Δu [output unit]
  double time_constant = 1.0;  ///< T [s], > 0
  double dead_time = 0.0;      ///< δ [s], ≥ 0

  /// Response (3.7): y = y₀ + A·(1 − e^{−(t−t₀−δ)/T}) for t ≥ t₀ + δ, else y₀.
  double operator()(double t) const;
};

/// Which FOPDT method fit_fopdt() uses.
enum class FopdtMethod {
  kLeastSquares,  ///< nonlinear least squares with the dead time estimated (default)
  kSmith,         ///< Smith's two-point method (3.8)–(3.9)
};

/// Options for fit_fopdt().
struct FopdtFitOptions {
  FopdtMethod method = FopdtMethod::kLeastSquares;
  /// Least squares: a known dead time [s] ≥ 0 instead of estimating it.
  std::optional<double> fixed_dead_time_s;
  /// Least squares: upper limit of the dead time [s], > 0; default 80 % of the window after the
  /// step.
  std::optional<double> max_dead_time_s;
  /// Seconds [s] > 0 of output before the step used for y₀; default
  /// min(t_step − t_begin, 0.25·(t_end − t_step)), so that in a multi-step log the tail of
  /// the previous response is used rather than its transient.
  std::optional<double> pre_step_s;
  /// Fraction of the window after the step, in (0, 0.5], whose mean is y∞ and which is checked
  /// for steady state.
  double tail_fraction = 0.2;
  /// Steady-state drift tolerance as a fraction of |Δy|, ≥ 0.
  double steady_state_tolerance = 0.02;
  /// R² below this (in [0, 1]) raises WarningCode::kPoorFit and fails the fit.
  double min_r_squared = 0.9;
  /// Fewer valid samples after the step than this (≥ 5) raises WarningCode::kFewSamples.
  std::size_t min_samples = 20;
  /// Least squares iteration limit, ≥ 1.
  int max_iterations = 200;
  /// Channel name used in error messages.
  std::string output_name = "output";

  /// Throws core::InputError naming the bad option.
  void validate() const;
};

/// Result of fit_fopdt(). Estimates are absent when no fit could be made (kFailed), and kept
/// for diagnosis when the fit is degenerate (kFailed, see the file comment).
struct FopdtFitResult {
  FitStatus status = FitStatus::kFailed;
  std::string message;
  FopdtMethod method = FopdtMethod::kLeastSquares;
  double t_step = 0.0;                     ///< t₀ used [s]
  std::optional<Estimate> y0;              ///< [output unit]
  std::optional<Estimate> amplitude;       ///< A = K·Δu [output unit]
  std::optional<Estimate> gain;            ///< K = A/Δu; absent when Δu is unknown
  std::optional<Estimate> time_constant;   ///< T [s]
  std::optional<Estimate> dead_time;       ///< δ [s]
  std::optional<double> gain_from_levels;  ///< K = Δy/Δu from the mean levels, (3.4)
  std::optional<double> delta_y;           ///< Δy = y∞ − y₀ from the mean levels
  std::optional<double> r_squared;         ///< 1 − SSE/SST over the fitted samples
  std::optional<double> rms_residual;      ///< √(SSE/N) [output unit]
  std::optional<double> noise_sigma;       ///< σ̂ of the output noise [output unit]
  std::size_t samples = 0;                 ///< valid samples used
  int iterations = 0;                      ///< least-squares iterations of the best start
  std::vector<FitWarning> warnings;

  /// The fitted model, or nullopt when status is kFailed.
  std::optional<FopdtModel> model() const;
};

/// Fits the FOPDT model (3.7) to the output y(t) over step.t_begin … step.t_end.
/// t [s] strictly increasing; y same length, NaN = missing. Δu = step.delta_u() gives K.
/// Throws core::InputError if the lengths differ, the options are invalid, the window lies
/// outside the log, y has no valid sample in it, there is no valid sample at or before the
/// step or fewer than 5 after it (step too short), or Δu is 0 (constant input).
FopdtFitResult fit_fopdt(std::span<const double> t, std::span<const double> y, const Step& step,
                         const FopdtFitOptions& options = {});

}  // namespace dynpos::ident
