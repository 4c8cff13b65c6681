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
// The samples before the search from which the shaft's following of its order is fitted [s].
constexpr double kTrackingWindow_s = 60.0;

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

// The unit's shaft following its order: the order's shaft speed (held between its samples)
// after a dead time, through a first-order lag, from the order's first valid sample on.
class OrderResponse {
 public:
  OrderResponse(const std::vector<double>& t, std::span<const double> order, double from_s,
                double to_s) {
    for (std::size_t i = 0; i < order.size() && i < t.size(); ++i) {
      if (t[i] >= from_s && t[i] <= to_s && std::isfinite(order[i])) {
        t_.push_back(t[i]);
        u_.push_back(order[i]);
      }
    }
  }
  bool usable() const noexcept { return t_.size() >= 2; }

  // The response at the sorted `times`.
  std::vector<double> at(double time_constant_s, double dead_time_s,
                         std::span<const double> times) const {
    std::vector<double> y(times.size());
    double state = u_.front(), t_state = t_.front();
    std::size_t j = 0;  // the next order sample
    for (std::size_t k = 0; k < times.size(); ++k) {
      const double tk = times[k] - dead_time_s;
      while (j < t_.size() && t_[j] <= tk) {
        state = advance(state, j, t_[j] - t_state, time_constant_s);
        t_state = t_[j++];
      }
      y[k] = j == 0 ? u_.front() : advance(state, j, tk - t_state, time_constant_s);
    }
    return y;
  }

 private:
  // The state dt after a sample, the input held at the order sample before j.
  double advance(double state, std::size_t j, double dt, double tau) const {
    const double u = u_[j == 0 ? 0 : j - 1];
    return u + (state - u) * std::exp(-std::max(dt, 0.0) / tau);
  }
  std::vector<double> t_, u_;
};

// How the shaft follows the order: dead time and time constant, fitted with a gain.
struct Tracking {
  double dead_time_s = 0.0;
  double time_constant_s = 1.0;
  double gain = 1.0;  ///< feedback / the order's response
};

// The samples before an onset: their residual sum of squares under a model, and the model's
// level at the onset.
struct Before {
  double sse = 0.0;
  double level = 0.0;
};

// s ≈ c·y (least squares), y the order's response at t and then at t_f: its sse and c·y(t_f);
// c in `gain` when not null.
Before gain_fit(std::span<const double> s, const std::vector<double>& y, double* gain = nullptr) {
  double sy = 0.0, yy = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    sy += s[i] * y[i];
    yy += y[i] * y[i];
  }
  if (!(yy > 0.0)) return {std::numeric_limits<double>::infinity(), 0.0};
  const double c = sy / yy;
  if (gain != nullptr) *gain = c;
  Before b{0.0, c * y.back()};
  for (std::size_t i = 0; i < s.size(); ++i) b.sse += std::pow(s[i] - c * y[i], 2);
  return b;
}

// The dead time (0–3 s by 0.1 s) and time constant (0.05–5 s, log grid) with which the samples
// (t, s) follow the order best; nullopt with fewer than 4 samples.
std::optional<Tracking> fit_tracking(std::span<const double> t, std::span<const double> s,
                                     const OrderResponse& order,
                                     const std::array<double, kGrid>& taus) {
  if (t.size() < 4) return std::nullopt;
  std::vector<double> times(t.begin(), t.end());
  times.push_back(t.back());
  Tracking best;
  double best_sse = std::numeric_limits<double>::infinity();
  for (int d = 0; d <= 30; ++d) {
    for (const double tau : taus) {
      double gain = 0.0;
      const double sse = gain_fit(s, order.at(tau, 0.1 * d, times), &gain).sse;
      if (sse < best_sse) {
        best_sse = sse;
        best = {0.1 * d, tau, gain};
      }
    }
  }
  return best;
}

// Before the onset t_f: the level line through the samples (the DP's own swing) or, when it fits
// them better, the order followed as `tracking` says.
Before before_onset(std::span<const double> t, std::span<const double> s, double t_f,
                    const OrderResponse* order, const Tracking& tracking) {
  std::vector<double> dt(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) dt[i] = t[i] - t_f;
  const LineFit line = fit_line(dt, s);
  Before b{0.0, line.a};
  for (std::size_t i = 0; i < t.size(); ++i) b.sse += std::pow(s[i] - (line.a + line.b * dt[i]), 2);
  if (order == nullptr) return b;
  std::vector<double> times(t.begin(), t.end());
  times.push_back(t_f);
  const Before followed =
      gain_fit(s, order->at(tracking.time_constant_s, tracking.dead_time_s, times));
  return followed.sse < b.sse && followed.level > 0.0 ? followed : b;
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
                               const std::array<double, kGrid>& rhos, const OrderResponse* order,
                               const Tracking& tracking) {
  const auto n_pre =
      static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), t_f) - t.begin());
  if (n_pre == 0) return std::nullopt;
  const Before b = before_onset(t.first(n_pre), s.first(n_pre), t_f, order, tracking);
  if (!(b.level > 0.0)) return std::nullopt;
  const auto sse_of = [&](double tau, double rho, double bound) {
    double sse = b.sse;
    for (std::size_t i = n_pre; i < t.size() && sse < bound; ++i) {
      sse += std::pow(s[i] - b.level * decayed(t[i] - t_f, tau, rho), 2);
    }
    return sse;
  };
  OnsetFit best;
  best.level = b.level;
  best.sse = std::numeric_limits<double>::infinity();
  double best_rho = rhos.front();
  for (const double tau : taus) {
    for (const double rho : rhos) {
      const double sse = sse_of(tau, rho, best.sse);
      if (sse < best.sse) {
        best = {sse, tau, b.level};
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
        best = {sse, tau, b.level};
        best_rho = rho;
        moved = true;
      }
    }
    if (!moved) step *= 0.5;
  }
  return best;
}

// The order's response and how the shaft follows it, from the samples of the minute before the
// search (the order from 8 s before those: 3 s of dead time and 5 s for its response to settle);
// nullopt without an order or samples to fit.
std::optional<Tracking> tracking_before(const std::vector<double>& t, const std::vector<double>& s,
                                        const FallSearch& q, const OrderResponse& response) {
  if (!response.usable()) return std::nullopt;
  static const std::array<double, kGrid> taus = log_grid(0.05, 5.0);
  std::vector<double> tt, st;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] >= q.from_s - kTrackingWindow_s && t[i] < q.from_s && std::isfinite(s[i])) {
      tt.push_back(t[i]);
      st.push_back(s[i]);
    }
  }
  return fit_tracking(tt, st, response, taus);
}

// The first sample from the search's start to the end of its fall window below fallen_fraction
// of what following the order gives (the unit no longer following it) while following it would
// keep the unit above still_ordered of its speed at the search's start (once the order has itself
// dropped, a fall is the unit following it); nullopt if none.
std::optional<double> departure(const std::vector<double>& t, const std::vector<double>& s,
                                const FallSearch& q, const OrderResponse& response,
                                const Tracking& k) {
  std::vector<double> times{q.from_s}, values{0.0};  // the search's start, then its samples
  for (std::size_t i = 0; i < t.size() && t[i] <= q.to_s + q.fall_s; ++i) {
    if (t[i] < q.from_s || !std::isfinite(s[i])) continue;
    times.push_back(t[i]);
    values.push_back(s[i]);
  }
  const std::vector<double> followed = response.at(k.time_constant_s, k.dead_time_s, times);
  const double floor = q.still_ordered * k.gain * followed[0];
  for (std::size_t i = 1; i < times.size(); ++i) {
    const double expected = k.gain * followed[i];
    if (expected < floor) return std::nullopt;
    if (values[i] < q.fallen_fraction * expected) return times[i];
  }
  return std::nullopt;
}

OrderResponse order_response(const std::vector<double>& t, std::span<const double> order,
                             const FallSearch& q) {
  return OrderResponse(t, order, q.from_s - kTrackingWindow_s - 8.0,
                       q.to_s + q.fall_s + kTrackingWindow_s);
}

}  // namespace

std::optional<FallOnset> fit_fall_onset(const std::vector<double>& t, const std::vector<double>& s,
                                        const FallSearch& search, std::span<const double> order) {
  FallSearch q = search;
  const OrderResponse response = order_response(t, order, q);
  const std::optional<Tracking> tracking = tracking_before(t, s, q, response);
  // An ordered ramp may take the feedback below the fall's threshold before the unit trips: the
  // search reaches on to where the feedback leaves the order.
  if (tracking) {
    if (const auto left = departure(t, s, q, response, *tracking)) q.to_s = std::max(q.to_s, *left);
  }
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
  const OrderResponse* with_order = tracking ? &response : nullptr;
  std::vector<std::pair<double, OnsetFit>> fits;
  const auto steps = static_cast<std::size_t>(std::floor((q.to_s - q.from_s) / q.step_s + 1e-9));
  for (std::size_t k = 0; k <= steps; ++k) {
    const double t_f = q.from_s + static_cast<double>(k) * q.step_s;
    if (const auto f = fit_at(ts, ss, t_f, taus, rhos, with_order, tracking.value_or(Tracking{}))) {
      fits.emplace_back(t_f, *f);
    }
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
