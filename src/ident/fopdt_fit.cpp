#include "dynpos/ident/fopdt_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "dynpos/core/error.hpp"
#include "series.hpp"
#include "step_response.hpp"

namespace dynpos::ident {

using detail::fmt;

namespace {

// Beyond this many time constants e^(−x/T) < 4.3·10⁻¹⁸: 1 − e rounds to 1 in double precision,
// so the model is its final value and the exponential need not be computed (most samples of a
// long window of a fast response).
constexpr double kSettledTimeConstants = 40.0;

}  // namespace

double FopdtModel::operator()(double t) const {
  const double x = t - t_step - dead_time;
  if (x <= 0.0) return y0;
  if (time_constant > 0.0 && x > kSettledTimeConstants * time_constant) return y0 + amplitude;
  return y0 + amplitude * (1.0 - std::exp(-x / time_constant));  // (3.7)
}

std::optional<FopdtModel> FopdtFitResult::model() const {
  if (status == FitStatus::kFailed || !y0 || !amplitude || !time_constant || !dead_time) {
    return std::nullopt;
  }
  return FopdtModel{t_step, y0->value, amplitude->value, time_constant->value, dead_time->value};
}

void FopdtFitOptions::validate() const {
  const auto bad = [](const std::string& what, const std::string& hint) {
    throw core::InputError({"", {}, {}, "FOPDT options"}, what, hint);
  };
  if (fixed_dead_time_s && !(*fixed_dead_time_s >= 0.0 && std::isfinite(*fixed_dead_time_s))) {
    bad("fixed dead time " + fmt(*fixed_dead_time_s) + " s", "give a finite dead time ≥ 0 s");
  }
  if (max_dead_time_s && !(*max_dead_time_s > 0.0 && std::isfinite(*max_dead_time_s))) {
    bad("maximum dead time " + fmt(*max_dead_time_s) + " s", "give a finite limit > 0 s");
  }
  detail::validate_window_options(pre_step_s, tail_fraction, steady_state_tolerance, min_r_squared,
                                  min_samples, "FOPDT options");
  if (max_iterations < 1) bad("iteration limit " + std::to_string(max_iterations), "give ≥ 1");
}

namespace {

// Parameters in the order y₀, A, T, δ.
using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat4 = Eigen::Matrix<double, 4, 4>;

struct Bounds {
  double t_min = 0.0;
  double t_max = 0.0;
  double delta_max = 0.0;
  bool delta_free = true;
};

// The settled samples (tail) of a window in O(1) per evaluation: there the model is the constant
// c = y₀ + A, so Σ(y − c) and Σ(y − c)² follow from prefix sums of y − ȳ and (y − ȳ)², ȳ the
// window's final level (which keeps the sums at the size of the noise, not of the level).
struct TailSums {
  double y_ref = 0.0;
  std::vector<double> s1, s2;  // s1[i] = Σ_{k<i} (y_k − y_ref), s2 likewise of the squares

  explicit TailSums(const detail::StepResponse& r) : y_ref(r.y_final) {
    s1.resize(r.y.size() + 1);
    s2.resize(r.y.size() + 1);
    for (std::size_t i = 0; i < r.y.size(); ++i) {
      const double d = r.y[i] - y_ref;
      s1[i + 1] = s1[i] + d;
      s2[i + 1] = s2[i] + d * d;
    }
  }
  // Index of the first settled sample for the parameters p: τ − δ > 40·T.
  static std::size_t first_settled(const detail::StepResponse& r, const Vec4& p) {
    const double tau_settled = p(3) + kSettledTimeConstants * p(2);
    return static_cast<std::size_t>(std::upper_bound(r.tau.begin(), r.tau.end(), tau_settled) -
                                    r.tau.begin());
  }
  // Σ res and Σ res² of the samples from `first` on, against the constant c.
  std::pair<double, double> residuals(std::size_t first, double c) const {
    const std::size_t n = s1.size() - 1;
    const double m = static_cast<double>(n - first);
    const double a = s1[n] - s1[first];
    const double b = s2[n] - s2[first];
    const double d = c - y_ref;
    return {a - m * d, std::max(b - 2.0 * d * a + m * d * d, 0.0)};
  }
};

double sse_of(const detail::StepResponse& r, const TailSums& tail, const Vec4& p) {
  double sse = 0.0;
  const std::size_t settled = TailSums::first_settled(r, p);
  for (std::size_t i = 0; i < settled; ++i) {
    const double x = r.tau[i] - p(3);
    const double m = x <= 0.0 ? p(0) : p(0) + p(1) * (1.0 - std::exp(-x / p(2)));
    sse += (r.y[i] - m) * (r.y[i] - m);
  }
  return sse + tail.residuals(settled, p(0) + p(1)).second;
}

// Normal equations JᵀJ and Jᵀr of the residuals r = y − m(τ; p), with the model (3.7).
void normal_equations(const detail::StepResponse& r, const TailSums& tail, const Vec4& p, Mat4& jtj,
                      Vec4& jtr, double& sse) {
  // J = [1, 1 − e, −A·x·e/T², −A·e/T] per sample (∂m/∂(y0, A, T, δ) of (3.7)). The ten distinct
  // products of JᵀJ are summed in scalars: this loop is the cost of a fit, and a day-long log
  // has hundreds of steps.
  const double inv_t = 1.0 / p(2);
  double s1 = 0, s2 = 0, s3 = 0, s11 = 0, s21 = 0, s31 = 0, s22 = 0, s32 = 0, s33 = 0;
  double r0 = 0, r1 = 0, r2 = 0, r3 = 0, sq = 0;
  const std::size_t n = r.y.size();
  const std::size_t settled = TailSums::first_settled(r, p);
  for (std::size_t i = 0; i < settled; ++i) {
    const double x = r.tau[i] - p(3);
    double m = p(0), j1 = 0.0, j2 = 0.0, j3 = 0.0;
    if (x > 0.0) {
      const double e = std::exp(-x * inv_t);
      m = p(0) + p(1) * (1.0 - e);
      j1 = 1.0 - e;
      j3 = -p(1) * e * inv_t;
      j2 = j3 * x * inv_t;
    }
    const double res = r.y[i] - m;
    sq += res * res;
    s1 += j1;
    s2 += j2;
    s3 += j3;
    s11 += j1 * j1;
    s21 += j2 * j1;
    s31 += j3 * j1;
    s22 += j2 * j2;
    s32 += j3 * j2;
    s33 += j3 * j3;
    r0 += res;
    r1 += j1 * res;
    r2 += j2 * res;
    r3 += j3 * res;
  }
  // The settled tail: j = [1, 1, 0, 0] and the residuals of the constant y₀ + A.
  const double m_tail = static_cast<double>(n - settled);
  const auto [res_tail, sq_tail] = tail.residuals(settled, p(0) + p(1));
  s1 += m_tail;
  s11 += m_tail;
  r0 += res_tail;
  r1 += res_tail;
  sq += sq_tail;
  jtj << static_cast<double>(n), s1, s2, s3,  //
      s1, s11, s21, s31,                      //
      s2, s21, s22, s32,                      //
      s3, s31, s32, s33;
  jtr << r0, r1, r2, r3;
  sse = sq;
}

Vec4 clamp_params(Vec4 p, const Bounds& b) {
  p(2) = std::clamp(p(2), b.t_min, b.t_max);
  p(3) = std::clamp(p(3), 0.0, b.delta_max);
  return p;
}

struct LmRun {
  Vec4 p;
  double sse = 0.0;
  int iterations = 0;
  bool converged = false;
};

// Levenberg–Marquardt with Marquardt's diagonal scaling, box limits on T and δ by projection.
LmRun levenberg_marquardt(const detail::StepResponse& r, const TailSums& tail, Vec4 p,
                          const Bounds& b, int max_iterations) {
  LmRun run;
  p = clamp_params(p, b);
  Mat4 jtj;
  Vec4 jtr;
  double sse = 0.0;
  normal_equations(r, tail, p, jtj, jtr, sse);
  double lambda = 1e-3;
  const double scale_y = std::max(std::abs(r.delta_y), 1e-300);
  const Vec4 scale(scale_y, scale_y, r.tau_end, r.tau_end);
  for (int it = 0; it < max_iterations; ++it) {
    run.iterations = it + 1;
    if (!b.delta_free) {  // δ held: its row and column drop out
      jtj.row(3).setZero();
      jtj.col(3).setZero();
      jtr(3) = 0.0;
    }
    bool accepted = false;
    while (!accepted) {
      Mat4 a = jtj;
      for (int k = 0; k < 4; ++k) a(k, k) += lambda * std::max(jtj(k, k), 1e-12 * scale(k));
      if (!b.delta_free) a(3, 3) = 1.0;
      const Vec4 step = a.ldlt().solve(jtr);
      const Vec4 trial = clamp_params(p + step, b);
      const double trial_sse = sse_of(r, tail, trial);
      if (std::isfinite(trial_sse) && trial_sse <= sse) {
        const double reduction = sse - trial_sse;
        const double moved = ((trial - p).array() / scale.array()).abs().maxCoeff();
        p = trial;
        lambda = std::max(lambda / 3.0, 1e-12);
        accepted = true;
        normal_equations(r, tail, p, jtj, jtr, sse);
        if (moved < 1e-10 || reduction <= 1e-14 * (sse + 1e-300)) {
          run.converged = true;
        }
      } else {
        lambda *= 4.0;
        if (lambda > 1e12) {  // no downhill step left: at a minimum within round-off
          run.converged = true;
          break;
        }
      }
    }
    if (run.converged) break;
  }
  run.p = p;
  run.sse = sse;
  return run;
}

void add_common_warnings(const FopdtFitOptions& options, const detail::StepResponse& r,
                         double time_constant, double dead_time, double r_squared,
                         std::vector<FitWarning>& warnings) {
  const double seen = r.tau_end - dead_time;
  if (seen < 3.0 * time_constant) {
    warnings.push_back({WarningCode::kShortWindow,
                        "step too short for the time constant: " + fmt(seen) +
                            " s after the dead time, less than 3T = " + fmt(3.0 * time_constant) +
                            " s (under 95 % of the response seen)"});
  }
  if (r_squared < options.min_r_squared) {
    warnings.push_back({WarningCode::kPoorFit, "poor fit: R² = " + fmt(r_squared) + " is below " +
                                                   fmt(options.min_r_squared)});
  }
}

// Smith's two-point method (3.8)–(3.9) from the 28.3 % and 63.2 % crossing times.
void smith_fit(const detail::StepResponse& r, const Step& step, const FopdtFitOptions& options,
               std::optional<double> t28, std::optional<double> t63, FopdtFitResult& result) {
  if (!t28 || !t63 || !(*t63 > *t28)) {
    result.status = FitStatus::kFailed;
    result.message = "the response does not cross 28.3 % and 63.2 % of Δy in order";
    return;
  }
  const std::optional<double> du = step.delta_u();
  const double tc = 1.5 * (*t63 - *t28);  // (3.8)
  const double dead = *t63 - tc;          // (3.9)
  result.y0 = Estimate{r.y0, {}};
  result.amplitude = Estimate{r.delta_y, {}};
  if (du) result.gain = Estimate{r.delta_y / *du, {}};
  result.time_constant = Estimate{tc, {}};
  result.dead_time = Estimate{dead, {}};
  const FopdtModel model{step.t_step, r.y0, r.delta_y, tc, dead};
  const detail::FitQuality q = detail::fit_quality(r, model);
  result.r_squared = q.r_squared;
  result.rms_residual = q.rms;
  if (dead < 0.0) {
    result.warnings.push_back(
        {WarningCode::kDeadTimeAtBound,
         "negative dead time " + fmt(dead) + " s: the response starts before the step time"});
  }
  add_common_warnings(options, r, tc, std::max(dead, 0.0), q.r_squared, result.warnings);
  if (q.r_squared < options.min_r_squared) {
    result.status = FitStatus::kFailed;
    result.message = "poor fit: Smith two-point fit with R² = " + fmt(q.r_squared) + " below " +
                     fmt(options.min_r_squared);
    return;
  }
  result.status = FitStatus::kOk;
  result.message = "Smith two-point fit";
}

// Limits of the least squares: the sampling period sets the smallest resolvable time
// constant, the window the largest; δ is held at a fixed dead time if one is given.
Bounds lsq_bounds(const detail::StepResponse& r, const FopdtFitOptions& options) {
  Bounds bounds;
  bounds.t_min = std::max(1e-9 * r.tau_end, 1e-12);
  bounds.t_max = 100.0 * r.tau_end;
  bounds.delta_free = !options.fixed_dead_time_s.has_value();
  bounds.delta_max = options.fixed_dead_time_s ? *options.fixed_dead_time_s
                                               : options.max_dead_time_s.value_or(0.8 * r.tau_end);
  return bounds;
}

// Starting points (T, δ) of the least squares, from Smith's times where the data give them.
std::vector<std::array<double, 2>> lsq_starts(const detail::StepResponse& r,
                                              std::optional<double> t28,
                                              std::optional<double> t63) {
  std::vector<std::array<double, 2>> starts;
  if (t28 && t63 && *t63 > *t28) {
    const double tc = 1.5 * (*t63 - *t28);
    starts.push_back({tc, *t63 - tc});
    starts.push_back({*t63, 0.0});
    starts.push_back({0.5 * tc, *t63 - 0.5 * tc});
  } else if (t63) {
    starts.push_back({std::max(*t63, 0.05 * r.tau_end), 0.0});
  } else {
    starts.push_back({0.2 * r.tau_end, 0.0});
  }
  return starts;
}

// Standard deviations of the free parameters from the covariance σ²(JᵀJ)⁻¹ at p,
// σ² = SSE/(N − p); NaN where it is not defined (δ when held, a singular JᵀJ, no dof).
Vec4 parameter_sigmas(const detail::StepResponse& r, const TailSums& tail, const Vec4& p,
                      const Bounds& bounds) {
  Mat4 jtj;
  Vec4 jtr;
  double sse = 0.0;
  normal_equations(r, tail, p, jtj, jtr, sse);
  const int n_par = bounds.delta_free ? 4 : 3;
  const double dof = static_cast<double>(r.y.size()) - n_par;
  const double s2 = dof > 0.0 ? sse / dof : std::numeric_limits<double>::quiet_NaN();
  Vec4 sigma = Vec4::Constant(std::numeric_limits<double>::quiet_NaN());
  const Eigen::MatrixXd info = jtj.topLeftCorner(n_par, n_par);
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(info);
  if (lu.isInvertible()) {
    const Eigen::MatrixXd cov = s2 * lu.inverse();
    for (int k = 0; k < n_par; ++k) sigma(k) = std::sqrt(std::max(cov(k, k), 0.0));
  }
  return sigma;
}

// Why a least-squares optimum is no estimate, "" when it is one: T beyond 10 times the window
// after the dead time (under 10 % of the response seen: T and K are extrapolated; this takes in
// T at its search limit, 100 × the window) or at its lower limit, δ at its upper search limit
// (the data do not bound them), a standard deviation that cannot be computed (JᵀJ singular:
// the window does not separate the parameters), or a poor R². δ = 0 is a physical limit, not a
// search limit: a warning only.
std::string degenerate_reasons(const FopdtFitOptions& options, const Bounds& bounds, double tau_end,
                               const Vec4& p, const Vec4& sigma, double r_squared) {
  std::string why;
  const auto add = [&why](const std::string& reason) { why += (why.empty() ? "" : "; ") + reason; };
  const double seen = tau_end - p(3);
  if (p(2) > 10.0 * seen) {
    add("time constant " + fmt(p(2)) + " s is over 10 times the " + fmt(seen) +
        " s seen after the dead time: the output does not settle in the window");
  } else if (p(2) <= bounds.t_min * (1.0 + 1e-3)) {
    add("time constant " + fmt(p(2)) + " s at its lower search limit");
  }
  if (bounds.delta_free && p(3) >= bounds.delta_max * (1.0 - 1e-6)) {
    add("dead time " + fmt(p(3)) + " s at its search limit " + fmt(bounds.delta_max) + " s");
  }
  const int n_par = bounds.delta_free ? 4 : 3;
  if (!sigma.head(n_par).allFinite()) {
    add("the standard deviations cannot be computed (the window does not separate the "
        "parameters)");
  }
  if (r_squared < options.min_r_squared) {
    add("R² = " + fmt(r_squared) + " is below " + fmt(options.min_r_squared));
  }
  return why;
}

// The estimates, fit quality, warnings and status of the best least-squares run.
void set_lsq_result(const detail::StepResponse& r, const TailSums& tail, const Step& step,
                    const FopdtFitOptions& options, const Bounds& bounds, const LmRun& best,
                    FopdtFitResult& result) {
  const Vec4 sigma = parameter_sigmas(r, tail, best.p, bounds);
  const auto opt_sigma = [](double s) -> std::optional<double> {
    if (std::isfinite(s)) return s;
    return std::nullopt;
  };
  result.y0 = Estimate{best.p(0), opt_sigma(sigma(0))};
  result.amplitude = Estimate{best.p(1), opt_sigma(sigma(1))};
  result.time_constant = Estimate{best.p(2), opt_sigma(sigma(2))};
  result.dead_time = Estimate{best.p(3), bounds.delta_free ? opt_sigma(sigma(3)) : std::nullopt};
  if (const std::optional<double> du = step.delta_u()) {
    result.gain = Estimate{best.p(1) / *du,
                           result.amplitude->sigma
                               ? std::optional<double>(*result.amplitude->sigma / std::abs(*du))
                               : std::nullopt};
  }
  const FopdtModel model{step.t_step, best.p(0), best.p(1), best.p(2), best.p(3)};
  const detail::FitQuality q = detail::fit_quality(r, model);
  result.r_squared = q.r_squared;
  result.rms_residual = q.rms;
  result.iterations = best.iterations;
  if (bounds.delta_free) {
    const double tol = 1e-9 * r.tau_end;
    if (best.p(3) <= tol || best.p(3) >= bounds.delta_max - tol) {
      result.warnings.push_back({WarningCode::kDeadTimeAtBound, "dead time " + fmt(best.p(3)) +
                                                                    " s is at its limit [0, " +
                                                                    fmt(bounds.delta_max) + "] s"});
    }
  }
  add_common_warnings(options, r, best.p(2), best.p(3), q.r_squared, result.warnings);
  const std::string degenerate =
      degenerate_reasons(options, bounds, r.tau_end, best.p, sigma, q.r_squared);
  if (!degenerate.empty()) {
    result.status = FitStatus::kFailed;
    result.message = "degenerate fit: " + degenerate;
  } else if (best.converged) {
    result.status = FitStatus::kOk;
    result.message =
        "least-squares fit converged in " + std::to_string(best.iterations) + " iterations";
  } else {
    result.status = FitStatus::kNotConverged;
    result.message = "least squares did not converge in " + std::to_string(options.max_iterations) +
                     " iterations";
  }
}

}  // namespace

FopdtFitResult fit_fopdt(std::span<const double> t, std::span<const double> y, const Step& step,
                         const FopdtFitOptions& options) {
  options.validate();
  const detail::StepResponse r = detail::prepare_step_response(
      t, y, step,
      {options.pre_step_s, options.tail_fraction, options.steady_state_tolerance,
       options.min_samples, options.output_name});

  FopdtFitResult result;
  result.method = options.method;
  result.t_step = step.t_step;
  result.samples = r.y.size();
  result.noise_sigma = r.noise_sigma;
  result.delta_y = r.delta_y;
  result.warnings = r.warnings;
  const std::optional<double> du = step.delta_u();
  if (du) result.gain_from_levels = r.delta_y / *du;  // (3.4)

  if (r.delta_y == 0.0) {
    result.status = FitStatus::kFailed;
    result.message = "no response: the output level is the same before and after the step";
    return result;
  }

  // Smith's two-point method (3.8)–(3.9) on the data; also the least-squares start.
  const std::optional<double> t28 = detail::crossing_time(r, 1.0 - std::exp(-1.0 / 3.0));
  const std::optional<double> t63 = detail::crossing_time(r, 1.0 - std::exp(-1.0));
  if (options.method == FopdtMethod::kSmith) {
    smith_fit(r, step, options, t28, t63, result);
    return result;
  }

  const Bounds bounds = lsq_bounds(r, options);
  const TailSums tail(r);
  LmRun best;
  best.sse = std::numeric_limits<double>::infinity();
  // The starts guard against a local minimum in δ. A converged fit whose residual is already
  // at the noise level (rms ≤ 1.5·σ̂, or 1e-4·|Δy| on clean data) leaves nothing for another
  // start to find, so the remaining starts are skipped.
  const double good_rms = std::max(1.5 * r.noise_sigma, 1e-4 * std::abs(r.delta_y));
  for (const auto& s : lsq_starts(r, t28, t63)) {
    Vec4 p0(r.y0, r.delta_y, std::max(s[0], bounds.t_min),
            bounds.delta_free ? std::max(s[1], 0.0) : bounds.delta_max);
    const LmRun run = levenberg_marquardt(r, tail, p0, bounds, options.max_iterations);
    if (run.sse < best.sse) best = run;
    if (best.converged && std::sqrt(best.sse / static_cast<double>(r.y.size())) <= good_rms) break;
  }
  if (!std::isfinite(best.sse)) {
    result.status = FitStatus::kFailed;
    result.message = "least squares failed: the residuals are not finite";
    return result;
  }
  set_lsq_result(r, tail, step, options, bounds, best, result);
  return result;
}

}  // namespace dynpos::ident
