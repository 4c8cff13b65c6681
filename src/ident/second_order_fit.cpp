#include "dynpos/ident/second_order_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "dynpos/core/error.hpp"
#include "series.hpp"
#include "step_response.hpp"

namespace dynpos::ident {

using detail::fmt;

double second_order_unit_step(double tau, double t1, double t2) {
  if (tau <= 0.0) return 0.0;
  if (t2 <= 0.0) return 1.0 - std::exp(-tau / t1);  // first order
  // g = 1 − (f(T₁) − f(T₂))/(T₁ − T₂) with f(x) = x·e^{−τ/x}. For nearly equal time
  // constants the divided difference cancels; use f'(m) = e^{−τ/m}(1 + τ/m) at the midpoint,
  // whose error is O((T₁ − T₂)²), below 1e-12 for the switch-over used here.
  if (t1 - t2 < 1e-6 * t1) {
    const double m = 0.5 * (t1 + t2);
    return 1.0 - std::exp(-tau / m) * (1.0 + tau / m);
  }
  return 1.0 - (t1 * std::exp(-tau / t1) - t2 * std::exp(-tau / t2)) / (t1 - t2);
}

double SecondOrderModel::operator()(double t) const {
  return y0 + amplitude *
                  second_order_unit_step(t - t_step - dead_time, time_constant_1, time_constant_2);
}

std::optional<SecondOrderModel> SecondOrderFitResult::model() const {
  if (status == FitStatus::kFailed || !y0 || !amplitude || !time_constant_1 || !time_constant_2 ||
      !dead_time) {
    return std::nullopt;
  }
  return SecondOrderModel{t_step, *y0, *amplitude, *time_constant_1, *time_constant_2, *dead_time};
}

void SecondOrderFitOptions::validate() const {
  const auto bad = [](const std::string& what, const std::string& hint) {
    throw core::InputError({"", {}, {}, "second-order options"}, what, hint);
  };
  if (dead_time_s && !(*dead_time_s >= 0.0 && std::isfinite(*dead_time_s))) {
    bad("dead time " + fmt(*dead_time_s) + " s", "give a finite dead time ≥ 0 s");
  }
  if (!(onset_fraction > 0.0 && onset_fraction < 0.2)) {
    bad("onset fraction " + fmt(onset_fraction), "give a fraction in (0, 0.2)");
  }
  detail::validate_window_options(pre_step_s, tail_fraction, steady_state_tolerance, min_r_squared,
                                  min_samples, "second-order options");
}

namespace {

// Time τ_f(ρ) where g(τ; 1, ρ) = f, by bisection (g increases monotonically for ρ ∈ [0, 1]).
double unit_time(double fraction, double rho) {
  if (fraction <= 0.0) return 0.0;
  double lo = 0.0;
  double hi = 1.0;
  while (second_order_unit_step(hi, 1.0, rho) < fraction) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (second_order_unit_step(mid, 1.0, rho) < fraction ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Shape ratio (τ_c − τ_b)/(τ_b − τ_a) of three fractions; free of dead time and time scale.
double shape_ratio(const std::array<double, 3>& f, double rho) {
  const double ta = unit_time(f[0], rho);
  const double tb = unit_time(f[1], rho);
  const double tc = unit_time(f[2], rho);
  return (tc - tb) / (tb - ta);
}

struct ThreePoint {
  double rho = 0.0;
  double t1 = 0.0;
  double dead_time = 0.0;
  bool clamped = false;
};

// Solves ρ = T₂/T₁, T₁ and θ from the measured times t[k] (from the step) of fractions f[k].
ThreePoint solve_three_point(const std::array<double, 3>& f, const std::array<double, 3>& t) {
  const double measured = (t[2] - t[1]) / (t[1] - t[0]);
  const double r0 = shape_ratio(f, 0.0);
  const double r1 = shape_ratio(f, 1.0);
  ThreePoint out;
  const bool increasing = r1 > r0;
  const double lo_val = std::min(r0, r1);
  const double hi_val = std::max(r0, r1);
  if (measured <= lo_val || measured >= hi_val) {
    out.rho = (measured <= lo_val) == increasing ? 0.0 : 1.0;
    out.clamped = !(measured == lo_val || measured == hi_val);
  } else {
    double lo = 0.0;
    double hi = 1.0;
    for (int i = 0; i < 100 && hi - lo > 1e-13; ++i) {
      const double mid = 0.5 * (lo + hi);
      const bool below = shape_ratio(f, mid) < measured;
      (below == increasing ? lo : hi) = mid;
    }
    out.rho = 0.5 * (lo + hi);
  }
  const double ta = unit_time(f[0], out.rho);
  const double tb = unit_time(f[1], out.rho);
  const double tc = unit_time(f[2], out.rho);
  out.t1 = (t[2] - t[0]) / (tc - ta);
  out.dead_time = t[1] - out.t1 * tb;
  return out;
}

}  // namespace

SecondOrderFitResult fit_second_order(std::span<const double> t, std::span<const double> y,
                                      const Step& step, const SecondOrderFitOptions& options) {
  options.validate();
  const detail::StepResponse r = detail::prepare_step_response(
      t, y, step,
      {options.pre_step_s, options.tail_fraction, options.steady_state_tolerance,
       options.min_samples, options.output_name});
  SecondOrderFitResult result;
  result.method = options.method;
  result.t_step = step.t_step;
  result.samples = r.y.size();
  result.warnings = r.warnings;
  if (r.delta_y == 0.0) {
    result.message = "no response: the output level is the same before and after the step";
    return result;
  }

  std::array<double, 3> fractions{};
  const bool smith = options.method == SecondOrderMethod::kSmith;
  if (smith) {
    fractions = {options.dead_time_s ? 0.0 : options.onset_fraction, 0.2, 0.6};
  } else {
    fractions = {0.14, 0.55, 0.91};
  }
  std::array<double, 3> times{};
  for (int k = 0; k < 3; ++k) {
    if (k == 0 && smith && options.dead_time_s) {
      times[0] = *options.dead_time_s;
      continue;
    }
    const std::optional<double> tk = detail::crossing_time(r, fractions[k]);
    if (!tk) {
      result.message = "the response never covers " + fmt(100.0 * fractions[k]) + " % of Δy";
      return result;
    }
    times[k] = *tk;
  }
  if (!(times[0] < times[1] && times[1] < times[2])) {
    result.message = "the characteristic times are not increasing (" + fmt(times[0]) + ", " +
                     fmt(times[1]) + ", " + fmt(times[2]) + " s): dead time or noise too large";
    return result;
  }
  const ThreePoint sol = solve_three_point(fractions, times);
  if (sol.clamped) {
    const char* why =
        sol.rho == 0.0
            ? "response shape faster than first order: taken as first order (T₂ = 0)"
            : "response more S-shaped than two equal time constants (underdamped or higher "
              "order): taken as T₁ = T₂";
    result.warnings.push_back({WarningCode::kShapeOutOfRange, why});
  }
  const double t1 = sol.t1;
  const double t2 = sol.rho * t1;
  const double dead = (smith && options.dead_time_s) ? *options.dead_time_s : sol.dead_time;
  result.y0 = r.y0;
  result.amplitude = r.delta_y;
  if (const auto du = step.delta_u()) result.gain = r.delta_y / *du;  // (3.4)
  result.time_constant_1 = t1;
  result.time_constant_2 = t2;
  result.dead_time = dead;
  result.natural_period = std::sqrt(t1 * t2);
  if (t2 > 0.0) result.damping_ratio = (t1 + t2) / (2.0 * std::sqrt(t1 * t2));
  const SecondOrderModel model{step.t_step, r.y0, r.delta_y, t1, t2, dead};
  const detail::FitQuality q = detail::fit_quality(r, model);
  result.r_squared = q.r_squared;
  result.rms_residual = q.rms;
  if (dead < 0.0) {
    result.warnings.push_back(
        {WarningCode::kDeadTimeAtBound,
         "negative dead time " + fmt(dead) + " s: the response starts before the step time"});
  }
  // 95 % of a two-time-constant response takes about 3(T₁ + T₂).
  const double seen = r.tau_end - std::max(dead, 0.0);
  if (seen < 3.0 * (t1 + t2)) {
    result.warnings.push_back(
        {WarningCode::kShortWindow,
         "step too short for the time constants: " + fmt(seen) +
             " s after the dead time, less than 3(T₁ + T₂) = " + fmt(3.0 * (t1 + t2)) + " s"});
  }
  if (q.r_squared < options.min_r_squared) {
    result.warnings.push_back(
        {WarningCode::kPoorFit,
         "poor fit: R² = " + fmt(q.r_squared) + " is below " + fmt(options.min_r_squared)});
  }
  result.status = q.r_squared < options.min_r_squared ? FitStatus::kFailed : FitStatus::kOk;
  result.message = smith ? "Smith second-order fit" : "Rangaiah–Krishnaswamy three-point fit";
  if (result.status == FitStatus::kFailed) result.message = "poor fit: " + result.message;
  return result;
}

}  // namespace dynpos::ident
