#include "failure_events.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "dynpos/core/circular_stats.hpp"
#include "fix_spline.hpp"
#include "series.hpp"

namespace dynpos::ident::detail {
namespace {

std::optional<double> mean_of(const std::vector<double>& v) {
  if (v.size() < 3) return std::nullopt;
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

bool tripped(const FailureEvent& e, const std::string& unit) {
  return std::find(e.units.begin(), e.units.end(), unit) != e.units.end();
}

// The largest |heading − pre-failure mean| over the response span.
void heading_figures(const FailureTestInput& in, FailureEvent& e) {
  const std::vector<double>& t = in.t_s;
  e.pre_heading_rad = core::circular_mean(valid_in(t, in.heading_rad, e.pre_from_s, e.pre_to_s));
  if (!e.pre_heading_rad) return;
  for (std::size_t i = first_at(t, e.time_s); i < t.size() && t[i] <= e.response_to_s; ++i) {
    if (std::isnan(in.heading_rad[i])) continue;
    const double d =
        std::abs(std::remainder(in.heading_rad[i] - *e.pre_heading_rad, 2.0 * std::numbers::pi));
    e.peak_heading_rad = std::max(e.peak_heading_rad.value_or(0.0), d);
  }
}

// The pre-failure mean position and footprint over the rows of the joined fixes (north, east);
// false with fewer than 3 logged fixes (fix_north, fix_east) in the window.
bool pre_failure_position(const std::vector<double>& t, const std::vector<double>& fix_north,
                          const std::vector<double>& fix_east, const std::vector<double>& north,
                          const std::vector<double>& east, FailureEvent& e) {
  double sn = 0.0, se = 0.0;
  std::vector<std::size_t> fixes;
  std::size_t logged = 0;
  for (std::size_t i = first_at(t, e.pre_from_s); i < t.size() && t[i] <= e.pre_to_s; ++i) {
    if (!std::isnan(fix_north[i]) && !std::isnan(fix_east[i])) ++logged;
    if (std::isnan(north[i]) || std::isnan(east[i])) continue;
    sn += north[i];
    se += east[i];
    fixes.push_back(i);
  }
  if (logged < 3) return false;
  const auto n = static_cast<double>(fixes.size());
  e.pre_north_m = sn / n;
  e.pre_east_m = se / n;
  e.footprint_m = 0.0;
  for (const std::size_t i : fixes) {
    const double d = std::hypot(north[i] - *e.pre_north_m, east[i] - *e.pre_east_m);
    e.footprint_m = std::max(*e.footprint_m, d);
  }
  return true;
}

// The first time at or after index `from` of d from which d stays ≤ radius for hold_s, within
// t ≤ t_last; d is NaN where the position is missing.
std::optional<double> back_within(const std::vector<double>& t, const std::vector<double>& d,
                                  std::size_t from, double radius, double hold_s, double t_last) {
  // next_out[i]: the time of the first sample at or after i outside the radius.
  std::vector<double> next_out(d.size() + 1, std::numeric_limits<double>::infinity());
  for (std::size_t i = d.size(); i-- > 0;) {
    next_out[i] = (!std::isnan(d[i]) && d[i] > radius) ? t[i] : next_out[i + 1];
  }
  for (std::size_t i = from; i < d.size() && t[i] + hold_s <= t_last; ++i) {
    if (!std::isnan(d[i]) && d[i] <= radius && next_out[i] > t[i] + hold_s) return t[i];
  }
  return std::nullopt;
}

}  // namespace

std::size_t first_at(const std::vector<double>& t, double from) {
  return static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), from) - t.begin());
}

std::vector<double> valid_in(const std::vector<double>& t, const std::vector<double>& x,
                             double from, double to) {
  std::vector<double> v;
  for (std::size_t i = first_at(t, from); i < t.size() && t[i] <= to; ++i) {
    if (!std::isnan(x[i])) v.push_back(x[i]);
  }
  return v;
}

std::vector<double> running_median(const std::vector<double>& t, const std::vector<double>& x,
                                   double w) {
  if (!(w > 0.0)) return x;
  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isnan(x[i])) valid.push_back(i);
  }
  std::vector<double> out(x.size(), std::nan(""));
  std::vector<double> window;
  std::size_t lo = 0, hi = 0;  // [lo, hi) over `valid`
  for (std::size_t k = 0; k < valid.size(); ++k) {
    const double tk = t[valid[k]];
    while (t[valid[lo]] < tk - 0.5 * w) ++lo;
    while (hi < valid.size() && t[valid[hi]] <= tk + 0.5 * w) ++hi;
    window.clear();
    for (std::size_t j = lo; j < hi; ++j) window.push_back(x[valid[j]]);
    out[valid[k]] = median_in_place(window);
  }
  return out;
}

Neighbours neighbours(const std::vector<FailureEvent>& events, std::size_t k) {
  Neighbours n;
  if (k > 0) n.previous_s = events[k - 1].time_s;
  if (k + 1 < events.size()) n.next_s = events[k + 1].time_s;
  return n;
}

FailureEvent event_of(const FailureTestInput& in, const std::vector<Trip>& trips) {
  const Trip& first = trips.front();
  FailureEvent e;
  e.time_s = first.t_f;
  e.unit = in.units[first.unit].name;
  e.onset = first.onset;
  e.level_before = first.level;
  e.fall_time_constant_s = first.time_constant_s;
  e.near_zero_s = first.t_z;
  for (const Trip& trip : trips) {
    if (!tripped(e, in.units[trip.unit].name)) e.units.push_back(in.units[trip.unit].name);
  }
  return e;
}

void redistribute(const FailureTestInput& in, const std::vector<UnitProfile>& profiles,
                  const Neighbours& around, const FailureTestOptions& o, FailureEvent& e) {
  const std::vector<double>& t = in.t_s;
  const double w = o.redistribution_window_s;
  e.redistribution.clear();
  for (std::size_t k = 0; k < in.units.size(); ++k) {
    if (tripped(e, in.units[k].name)) continue;
    const UnitProfile& p = profiles[k];
    UnitRedistribution u;
    u.unit = in.units[k].name;
    u.mean_before =
        mean_of(valid_in(t, p.abs, std::max(e.time_s - w, around.previous_s), e.time_s));
    u.mean_after = mean_of(valid_in(t, p.abs, e.time_s, std::min(e.time_s + w, around.next_s)));
    if (u.mean_before && u.mean_after) {
      u.change = *u.mean_after - *u.mean_before;
      const double threshold =
          std::max(o.takeover_fraction * p.scale.full_scale, 3.0 * p.scale.noise_sigma);
      u.took_over = std::abs(*u.change) >= threshold && std::abs(*u.change) > 0.0;
    }
    e.redistribution.push_back(std::move(u));
  }
}

void excursion(const FailureTestInput& in, const Neighbours& around, const FailureTestOptions& o,
               FailureEvent& e) {
  const std::vector<double>& t = in.t_s;
  e.pre_from_s = std::max({e.time_s - o.pre_window_s, around.previous_s, t.front()});
  e.pre_to_s = e.time_s;
  e.response_to_s = std::min({e.time_s + o.response_window_s, around.next_s, t.back()});
  if (!in.heading_rad.empty()) heading_figures(in, e);
  if (in.north_m.empty() || in.east_m.empty()) return;
  // The position at every row of the log, the fixes joined (fix_spline.hpp).
  const std::vector<double> north = fill_between_fixes(t, in.north_m, o.fix_gap_s);
  const std::vector<double> east = fill_between_fixes(t, in.east_m, o.fix_gap_s);
  if (!pre_failure_position(t, in.north_m, in.east_m, north, east, e)) return;
  // Distances from the pre-failure mean over the response span.
  const std::size_t i0 = first_at(t, e.time_s);
  std::vector<double> span_t, d;
  std::optional<std::size_t> peak;
  for (std::size_t i = i0; i < t.size() && t[i] <= e.response_to_s; ++i) {
    span_t.push_back(t[i]);
    d.push_back(std::hypot(north[i] - *e.pre_north_m, east[i] - *e.pre_east_m));
    if (!std::isnan(d.back()) && (!peak || d.back() > d[*peak])) peak = d.size() - 1;
  }
  if (!peak) return;
  e.peak_excursion_m = d[*peak];
  e.time_to_peak_s = span_t[*peak] - e.time_s;
  // Out of and back within the footprint on the running median of the distance: a single
  // noisy fix or wave crest neither takes the vessel out nor holds the recovery back, and a
  // monotone return is not moved by it.
  const std::vector<double> smooth = running_median(span_t, d, o.recovery_median_s);
  std::optional<std::size_t> smooth_peak;
  for (std::size_t k = 0; k < smooth.size(); ++k) {
    if (!std::isnan(smooth[k]) && (!smooth_peak || smooth[k] > smooth[*smooth_peak])) {
      smooth_peak = k;
    }
  }
  if (smooth_peak) {
    e.median_peak_m = smooth[*smooth_peak];
    e.recovery_at_footprint_edge =
        std::abs(*e.median_peak_m - *e.footprint_m) <= o.footprint_edge_share * *e.footprint_m;
  }
  if (!smooth_peak || !(smooth[*smooth_peak] > *e.footprint_m)) {
    e.recovery_s = 0.0;  // never left the footprint
    return;
  }
  // Back from the median's peak: a single fix before or after it moves no recovery.
  if (const auto back =
          back_within(span_t, smooth, *smooth_peak, *e.footprint_m, o.hold_s, e.response_to_s)) {
    e.recovery_s = *back - e.time_s;
  }
}

}  // namespace dynpos::ident::detail
