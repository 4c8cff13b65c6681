#include "fall_onset.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "series.hpp"

namespace dynpos::ident::detail {
namespace {

constexpr std::size_t kGrid = 32;  // time constants and rate limits tried

// n log-spaced values from lo to hi.
std::array<double, kGrid> log_grid(double lo, double hi) {
  std::array<double, kGrid> g{};
  for (std::size_t k = 0; k < kGrid; ++k) {
    g[k] = lo * std::pow(hi / lo, static_cast<double>(k) / static_cast<double>(kGrid - 1));
  }
  return g;
}

// s/L a time dt ≥ 0 after the onset: the rate limit ρ = r/L [1/s] until s = r·T, then first
// order with the time constant T [s].
double decayed(double dt, double time_constant_s, double rho) {
  const double t_lin = std::max(0.0, 1.0 / rho - time_constant_s);
  if (dt <= t_lin) return 1.0 - rho * dt;
  return std::min(1.0, rho * time_constant_s) * std::exp(-(dt - t_lin) / time_constant_s);
}

// The best fit for one onset: its residual sum of squares, T and L; nullopt without a sample at
// or before the onset.
struct OnsetFit {
  double sse = 0.0;
  double time_constant_s = 0.0;
  double level = 0.0;
};

std::optional<OnsetFit> fit_at(std::span<const double> t, std::span<const double> s, double t_f,
                               const std::array<double, kGrid>& taus,
                               const std::array<double, kGrid>& rhos) {
  const auto n_pre =
      static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), t_f) - t.begin());
  if (n_pre == 0) return std::nullopt;
  std::vector<double> dt_pre(n_pre);
  for (std::size_t i = 0; i < n_pre; ++i) dt_pre[i] = t[i] - t_f;
  const LineFit line = fit_line(dt_pre, s.first(n_pre));  // a = the level at the onset
  OnsetFit best;
  best.level = line.a;
  if (!(line.a > 0.0)) return std::nullopt;
  double sse_pre = 0.0;
  for (std::size_t i = 0; i < n_pre; ++i) {
    sse_pre += std::pow(s[i] - (line.a + line.b * dt_pre[i]), 2);
  }
  const auto sse_of = [&](double tau, double rho, double bound) {
    double sse = sse_pre;
    for (std::size_t i = n_pre; i < t.size() && sse < bound; ++i) {
      sse += std::pow(s[i] - line.a * decayed(t[i] - t_f, tau, rho), 2);
    }
    return sse;
  };
  best.sse = std::numeric_limits<double>::infinity();
  double best_rho = rhos.front();
  for (const double tau : taus) {
    for (const double rho : rhos) {
      const double sse = sse_of(tau, rho, best.sse);
      if (sse < best.sse) {
        best = {sse, tau, line.a};
        best_rho = rho;
      }
    }
  }
  // Refined between the grid's points: steps of a factor, halved when none improves.
  double step = std::log(taus[1] / taus[0]);
  for (int k = 0; k < 200 && step > 1e-3; ++k) {
    bool moved = false;
    for (const auto& [f_tau, f_rho] : {std::pair{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}}) {
      // Within the grid's range (fall_onset.hpp).
      const double tau =
          std::clamp(best.time_constant_s * std::exp(f_tau * step), taus.front(), taus.back());
      const double rho = std::clamp(best_rho * std::exp(f_rho * step), rhos.front(), rhos.back());
      const double sse = sse_of(tau, rho, best.sse);
      if (sse < best.sse) {
        best = {sse, tau, line.a};
        best_rho = rho;
        moved = true;
      }
    }
    if (!moved) step *= 0.5;
  }
  return best;
}

}  // namespace

std::optional<FallOnset> fit_fall_onset(const std::vector<double>& t, const std::vector<double>& s,
                                        const FallSearch& q) {
  std::vector<double> ts, ss;  // the valid samples of the windows
  std::size_t n_before = 0, n_after = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < q.from_s - q.level_s || t[i] > q.to_s + q.fall_s || std::isnan(s[i])) continue;
    ts.push_back(t[i]);
    ss.push_back(s[i]);
    n_before += t[i] < q.from_s ? 1 : 0;
    n_after += t[i] >= q.to_s ? 1 : 0;
  }
  if (n_before == 0 || n_after < 2 || !(q.to_s >= q.from_s) || !(q.step_s > 0.0)) {
    return std::nullopt;
  }
  static const std::array<double, kGrid> taus = log_grid(0.05, 5.0);
  static const std::array<double, kGrid> rhos = log_grid(0.05, 50.0);
  std::vector<std::pair<double, OnsetFit>> fits;
  const auto steps = static_cast<std::size_t>(std::floor((q.to_s - q.from_s) / q.step_s + 1e-9));
  for (std::size_t k = 0; k <= steps; ++k) {
    const double t_f = q.from_s + static_cast<double>(k) * q.step_s;
    if (const auto f = fit_at(ts, ss, t_f, taus, rhos)) fits.emplace_back(t_f, *f);
  }
  if (fits.empty()) return std::nullopt;
  const auto best = std::min_element(fits.begin(), fits.end(), [](const auto& a, const auto& b) {
    return a.second.sse < b.second.sse;
  });
  const double sigma = std::max(q.noise_sigma, 1e-6 * best->second.level);
  const double within = best->second.sse + 4.0 * sigma * sigma;
  FallOnset o;
  o.earliest_s = std::numeric_limits<double>::infinity();
  o.latest_s = -o.earliest_s;
  for (const auto& [t_f, f] : fits) {
    if (f.sse > within) continue;
    o.earliest_s = std::min(o.earliest_s, t_f);
    o.latest_s = std::max(o.latest_s, t_f);
  }
  // An onset as good as the best at the search's start may lie before it, and onsets that fit
  // as well over more than 1.5 sample intervals (a slow fall the line before it takes for a
  // swing) place none: not timed here.
  std::vector<double> gaps(ts.size() > 1 ? ts.size() - 1 : 0);
  for (std::size_t i = 0; i < gaps.size(); ++i) gaps[i] = ts[i + 1] - ts[i];
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2),
                   gaps.end());
  const double spacing_s = gaps.empty() ? 0.0 : gaps[gaps.size() / 2];
  if (o.earliest_s < q.from_s + 0.5 * q.step_s || o.latest_s - o.earliest_s > 1.5 * spacing_s) {
    return std::nullopt;
  }
  o.t_s = 0.5 * (o.earliest_s + o.latest_s);
  o.time_constant_s = best->second.time_constant_s;
  o.level = best->second.level;
  return o;
}

}  // namespace dynpos::ident::detail
