#pragma once
/// \file
/// The definition of the "true" time constant and dead time of a simulated actuator.
///
/// The actuators are higher order and nonlinear (rate limits, quadratic thrust maps), so they
/// have no single true FOPDT (3.7) parameter. The truth written for a step test is defined as
/// what Smith's two-point method (3.8)–(3.9) gives on the noise-free simulated response, timed
/// from the command step: t₁ and t₂ are the first times the response has covered 28.3 % and
/// 63.2 % of its change, T = 1.5·(t₂ − t₁), δ = t₂ − T. An identification run on the noisy log
/// should therefore recover these numbers within its noise-induced error.

#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace dynpos::model {

/// A first-order-plus-dead-time description of a step response, (3.7).
struct FopdtTruth {
  double time_constant = 0.0;  ///< T [s], ≥ 0
  double dead_time = 0.0;      ///< δ [s], ≥ 0 for a causal response
};

/// Smith's two-point FOPDT fit (3.8)–(3.9) of a clean step response y(t) sampled at times t
/// (strictly increasing, same length as y) for a step applied at t_step, with final value taken
/// as y.back() and initial value as the last sample at or before t_step. Returns std::nullopt
/// when the response never covers 63.2 % of its change or the change is zero.
std::optional<FopdtTruth> fopdt_two_point(std::span<const double> t, std::span<const double> y,
                                          double t_step);

/// A simulated step response: y at times t_s from the command step at t = 0.
struct StepResponse {
  std::vector<double> t_s;  ///< [s], from 0 at step dt
  std::vector<double> y;    ///< [the response's unit]

  /// y at time t [s] after the step, linear between samples: y[0] before 0, the last after
  /// the end.
  double at(double t) const;
};

/// The response of a one-state actuator ẋ = rate(x, x_c) after a command step from → to at
/// t = 0 seen through a dead time [s]: RK4 at step dt [s] for duration [s] from rest at `from`.
StepResponse scalar_step_response(const std::function<double(double, double)>& rate, double from,
                                  double to, double dead_time, double duration, double dt);

/// The Smith truth of a one-state actuator ẋ = rate(x, x_c) after a command step from → to at
/// t = 0 seen through a dead time [s]: simulated by RK4 at step dt [s] for duration [s] from
/// rest at `from`. Returns a zero FOPDT when the response does not cover 63.2 %.
FopdtTruth scalar_step_truth(const std::function<double(double, double)>& rate, double from,
                             double to, double dead_time, double duration, double dt);

}  // namespace dynpos::model
