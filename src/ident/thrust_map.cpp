#include "dynpos/ident/thrust_map.hpp"

#include <cmath>

#include "dynpos/core/error.hpp"
#include "series.hpp"

namespace dynpos::ident {

using detail::fmt;

double ThrustMap::thrust(double n_rps) const {
  if (std::isnan(n_rps)) return n_rps;
  return (n_rps >= 0.0 ? c_forward : c_reverse) * n_rps * n_rps;  // (3.17)
}

std::vector<double> ThrustMap::thrust(std::span<const double> n_rps) const {
  std::vector<double> out(n_rps.size());
  for (std::size_t i = 0; i < n_rps.size(); ++i) out[i] = thrust(n_rps[i]);
  return out;
}

double ThrustMap::mean_coefficient() const {
  return 0.5 * (c_forward + std::abs(c_reverse));  // (3.18)
}

std::vector<double> thrust_from_abs_speed(double c_mean, std::span<const double> n_abs_rps) {
  std::vector<double> out(n_abs_rps.size());
  for (std::size_t i = 0; i < n_abs_rps.size(); ++i) {
    out[i] = c_mean * n_abs_rps[i] * n_abs_rps[i];  // (3.17) with c̄ of (3.18)
  }
  return out;
}

void ThrustMapFitOptions::validate() const {
  if (!(min_abs_shaft_speed_rps >= 0.0 && std::isfinite(min_abs_shaft_speed_rps))) {
    throw core::InputError({"", {}, {}, "thrust-map options"},
                           "minimum shaft speed " + fmt(min_abs_shaft_speed_rps) + " rps",
                           "give a finite speed ≥ 0 rps");
  }
}

std::optional<ThrustMap> ThrustMapFitResult::map() const {
  if (status == FitStatus::kFailed) return std::nullopt;
  return ThrustMap{c_forward ? c_forward->value : 0.0, c_reverse ? c_reverse->value : 0.0};
}

ThrustMapFitResult fit_thrust_map(std::span<const double> n_rps, std::span<const double> thrust_N,
                                  const ThrustMapFitOptions& options) {
  options.validate();
  detail::check_same_length(n_rps.size(), thrust_N.size(), options.thrust_name);

  // Per sign: Σ T·n², Σ n⁴, Σ T², count. Through the origin, c = ΣTn²/Σn⁴ and
  // SSE = ΣT² − c·ΣTn².
  struct Sums {
    double tn2 = 0.0;
    double n4 = 0.0;
    double t2 = 0.0;
    std::size_t count = 0;
  };
  Sums pos;
  Sums neg;
  double sum_t = 0.0;
  double sum_t2 = 0.0;
  for (std::size_t i = 0; i < n_rps.size(); ++i) {
    const double n = n_rps[i];
    const double f = thrust_N[i];
    if (std::isnan(n) || std::isnan(f) || std::abs(n) < options.min_abs_shaft_speed_rps) continue;
    Sums& s = n >= 0.0 ? pos : neg;
    const double n2 = n * n;
    s.tn2 += f * n2;
    s.n4 += n2 * n2;
    s.t2 += f * f;
    ++s.count;
    sum_t += f;
    sum_t2 += f * f;
  }
  ThrustMapFitResult result;
  result.samples_forward = pos.count;
  result.samples_reverse = neg.count;
  if (pos.count == 0 && neg.count == 0) {
    result.message = "no sample pair with |n| ≥ " + fmt(options.min_abs_shaft_speed_rps) +
                     " rps and both " + options.shaft_speed_name + " and " + options.thrust_name +
                     " logged";
    return result;
  }
  double sse_total = 0.0;
  const auto estimate = [&sse_total](const Sums& s) {
    const double c = s.tn2 / s.n4;
    const double sse = std::max(s.t2 - c * s.tn2, 0.0);
    sse_total += sse;
    Estimate e{c, {}};
    if (s.count > 1) e.sigma = std::sqrt(sse / static_cast<double>(s.count - 1) / s.n4);
    return e;
  };
  if (pos.count > 0) {
    result.c_forward = estimate(pos);
  } else {
    result.warnings.push_back(
        {WarningCode::kNoSamplesForSign, "no samples with positive shaft speed: c₊ not estimated"});
  }
  if (neg.count > 0) {
    result.c_reverse = estimate(neg);
  } else {
    result.warnings.push_back(
        {WarningCode::kNoSamplesForSign, "no samples with negative shaft speed: c₋ not estimated"});
  }
  const double n = static_cast<double>(pos.count + neg.count);
  const double sst = sum_t2 - sum_t * sum_t / n;
  if (sst > 0.0) result.r_squared = 1.0 - sse_total / sst;
  result.rms_residual = std::sqrt(sse_total / n);
  result.status = FitStatus::kOk;
  result.message = "thrust map from " + std::to_string(pos.count) + " forward and " +
                   std::to_string(neg.count) + " reverse samples";
  return result;
}

}  // namespace dynpos::ident
