#include "dynpos/model/fopdt_truth.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "dynpos/model/delay_line.hpp"
#include "dynpos/sim/rk4.hpp"

namespace dynpos::model {

namespace {

// First time at which the response has covered fraction p of the change y0 → y1, with linear
// interpolation between samples; negative when never reached.
double crossing_time(std::span<const double> t, std::span<const double> y, std::size_t start,
                     double y0, double y1, double p) {
  const double level = y0 + p * (y1 - y0);
  const double dir = y1 > y0 ? 1.0 : -1.0;
  for (std::size_t k = start + 1; k < y.size(); ++k) {
    if (dir * (y[k] - level) >= 0.0) {
      const double a = y[k - 1];
      const double b = y[k];
      const double w = (b != a) ? (level - a) / (b - a) : 1.0;
      return t[k - 1] + std::clamp(w, 0.0, 1.0) * (t[k] - t[k - 1]);
    }
  }
  return -1.0;
}

}  // namespace

std::optional<FopdtTruth> fopdt_two_point(std::span<const double> t, std::span<const double> y,
                                          double t_step) {
  if (t.size() != y.size() || t.size() < 3) return std::nullopt;
  std::size_t start = 0;
  while (start + 1 < t.size() && t[start + 1] <= t_step) ++start;
  const double y0 = y[start];
  const double y1 = y.back();
  if (!(std::abs(y1 - y0) > 0.0)) return std::nullopt;
  // (3.8)–(3.9): t₁ at 1 − e^{−1/3} ≈ 28.3 %, t₂ at 1 − e^{−1} ≈ 63.2 % of the change.
  const double t1 = crossing_time(t, y, start, y0, y1, 1.0 - std::exp(-1.0 / 3.0));
  const double t2 = crossing_time(t, y, start, y0, y1, 1.0 - std::exp(-1.0));
  if (t1 < 0.0 || t2 < 0.0) return std::nullopt;
  FopdtTruth fit;
  fit.time_constant = 1.5 * (t2 - t1);
  fit.dead_time = (t2 - t_step) - fit.time_constant;
  return fit;
}

double StepResponse::at(double t) const {
  if (t_s.empty()) return 0.0;
  if (!(t > t_s.front())) return y.front();
  if (t >= t_s.back()) return y.back();
  const auto hi =
      static_cast<std::size_t>(std::upper_bound(t_s.begin(), t_s.end(), t) - t_s.begin());
  const std::size_t lo = hi - 1;
  const double w = (t - t_s[lo]) / (t_s[hi] - t_s[lo]);
  return y[lo] + w * (y[hi] - y[lo]);
}

StepResponse scalar_step_response(const std::function<double(double, double)>& rate, double from,
                                  double to, double dead_time, double duration, double dt) {
  const auto steps = static_cast<std::size_t>(std::ceil(duration / dt));
  DelayLine line(dead_time, dt, from);
  sim::Rk4<1> rk4;
  Eigen::Matrix<double, 1, 1> x(from);
  StepResponse r{std::vector<double>(steps + 1), std::vector<double>(steps + 1)};
  for (std::size_t k = 0; k <= steps; ++k) {
    const double tk = static_cast<double>(k) * dt;
    r.t_s[k] = tk;
    r.y[k] = x[0];
    const double cmd = line.push(to);
    rk4.step([&](double, const Eigen::Matrix<double, 1, 1>& xs,
                 Eigen::Matrix<double, 1, 1>& dxs) { dxs[0] = rate(xs[0], cmd); },
             tk, dt, x, x);
  }
  return r;
}

FopdtTruth scalar_step_truth(const std::function<double(double, double)>& rate, double from,
                             double to, double dead_time, double duration, double dt) {
  const StepResponse r = scalar_step_response(rate, from, to, dead_time, duration, dt);
  return fopdt_two_point(r.t_s, r.y, 0.0).value_or(FopdtTruth{});
}

}  // namespace dynpos::model
