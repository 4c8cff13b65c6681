#include "dynpos/ident/failure_test.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "dynpos/core/error.hpp"
#include "failure_events.hpp"
#include "fall_onset.hpp"
#include "series.hpp"

namespace dynpos::ident {
namespace {

// An order below this share of its level before a fall asked for the fall: a stop (commanded()).
constexpr double kStopShare = 1.0 / 3.0;

// |feedback|, its running median, full scale, noise and near-zero band.
detail::UnitProfile make_profile(const std::vector<double>& t, const UnitFeedback& unit,
                                 const FailureTestOptions& o) {
  detail::UnitProfile p;
  p.abs.resize(unit.values.size());
  std::vector<double> valid;
  for (std::size_t i = 0; i < unit.values.size(); ++i) {
    p.abs[i] = std::abs(unit.values[i]);
    if (!std::isnan(p.abs[i])) valid.push_back(p.abs[i]);
  }
  p.smooth = detail::running_median(t, p.abs, o.median_window_s);
  p.scale.name = unit.name;
  for (const double v : p.smooth) {
    if (!std::isnan(v)) p.scale.full_scale = std::max(p.scale.full_scale, v);
  }
  p.scale.noise_sigma = detail::difference_noise_sigma(valid);
  p.scale.near_zero = std::max(o.zero_fraction * p.scale.full_scale, 4.0 * p.scale.noise_sigma);
  return p;
}

// A fall on the shaft speed: |feedback| and |order| as shaft speeds, and the onset search of
// fall_onset.hpp: onsets from 0.4·max_fall_s before the last sample at fall_from·L (ihi) to the
// next valid one (a rate-limited fall from full speed to 0.6 of it takes a third of that on the
// Gunnerus). nullopt without a sample after ihi.
struct Fall {
  std::vector<double> speed, order;
  detail::FallSearch search;
};

std::optional<Fall> fall_of(const std::vector<double>& t, const detail::UnitProfile& p,
                            const UnitFeedback& feedback, std::size_t ihi,
                            const FailureTestOptions& o) {
  const double exponent = feedback.shaft_speed_exponent;
  std::size_t ib = ihi + 1;
  while (ib < t.size() && std::isnan(p.abs[ib])) ++ib;
  if (ib >= t.size()) return std::nullopt;
  Fall f;
  const auto speed_of = [&](double a) { return std::pow(std::abs(a), 1.0 / exponent); };
  f.speed.resize(p.abs.size());
  std::transform(p.abs.begin(), p.abs.end(), f.speed.begin(), speed_of);
  f.order.resize(feedback.order.size());
  std::transform(feedback.order.begin(), feedback.order.end(), f.order.begin(), speed_of);
  std::vector<double> valid;
  for (const double v : f.speed) {
    if (!std::isnan(v)) valid.push_back(v);
  }
  f.search.from_s = t[ihi] - 0.4 * o.max_fall_s;
  f.search.to_s = t[ib];
  f.search.noise_sigma = detail::difference_noise_sigma(valid);
  f.search.fallen_fraction = speed_of(o.fall_from_fraction);
  f.search.still_ordered = speed_of(kStopShare);
  return f;
}

// The failure instant of a fall that reaches near zero at index iz, last at fall_from·L at ihi.
void time_the_fall(const std::vector<double>& t, const detail::UnitProfile& p,
                   const std::optional<Fall>& fall, std::size_t ihi, std::size_t iz,
                   const FailureTestOptions& o, detail::Trip& trip) {
  if (const auto fit =
          fall ? detail::fit_fall_onset(t, fall->speed, fall->search, fall->order) : std::nullopt) {
    trip.t_f = fit->t_s;
    trip.time_constant_s = fit->time_constant_s;
    trip.onset = OnsetMethod::kFallFit;
    return;
  }
  // The last sample still at the level, searched back to the level window's start.
  const double at_level = trip.level - std::max(0.1 * trip.level, 3.0 * p.scale.noise_sigma);
  const double t_stop = t[iz] - o.max_fall_s - o.level_window_s;
  trip.t_f = t[ihi];
  for (std::size_t i = ihi + 1; i-- > 0 && t[i] >= t_stop;) {
    if (!std::isnan(p.smooth[i]) && p.smooth[i] >= at_level) {
      trip.t_f = t[i];
      break;
    }
  }
  trip.onset = OnsetMethod::kLastLevel;
}

// The first time from `from` at which |x| (its valid samples) is below `below`; nullopt if none.
std::optional<double> first_below(const std::vector<double>& t, const std::vector<double>& x,
                                  double from, double below) {
  for (std::size_t i = detail::first_at(t, from); i < t.size(); ++i) {
    if (!std::isnan(x[i]) && std::abs(x[i]) < below) return t[i];
  }
  return std::nullopt;
}

// The mean of the valid samples of x with t in [from, to]; nullopt without one.
std::optional<double> mean_in(const std::vector<double>& t, const std::vector<double>& x,
                              double from, double to) {
  const std::vector<double> v = detail::valid_in(t, x, from, to);
  if (v.empty()) return std::nullopt;
  double sum = 0.0;
  for (const double a : v) sum += a;
  return sum / static_cast<double>(v.size());
}

// Whether the fall was ordered: when the feedback has fallen below half its value just before
// the fall (its median over the 2 s before t_f), the unit's logged |order| (its mean over the
// 1 s up to then, commanded_within_s later) is below a third of its own value before the fall
// (its mean from 5 s to 2 s before t_f, before an order the feedback lags): the order led the
// fall (a trip's is at 0.53-1.7 of it then on the virtual trial, a slow stop's at 0.21).
// Means, not medians: an order chattering between two allocations at the control rate is
// followed as its mean. A tripped unit's order holds, or drifts with the load, until the DP
// system flags the fault from the feedback, after the feedback has fallen. No order logged, or
// none before: not known to be ordered.
bool commanded(const std::vector<double>& t, const detail::UnitProfile& p,
               const std::vector<double>& order, const detail::Trip& trip,
               const FailureTestOptions& o) {
  if (order.empty()) return false;
  std::vector<double> abs_order(order.size());
  std::transform(order.begin(), order.end(), abs_order.begin(),
                 [](double v) { return std::abs(v); });
  std::vector<double> fb_before = detail::valid_in(t, p.abs, trip.t_f - 2.0, trip.t_f);
  const std::optional<double> order_level = mean_in(t, abs_order, trip.t_f - 5.0, trip.t_f - 2.0);
  if (fb_before.empty() || !order_level || !(*order_level > 0.0)) return false;
  const std::optional<double> fb_half =
      first_below(t, p.abs, trip.t_f, 0.5 * detail::median_in_place(fb_before));
  if (!fb_half) return false;
  const double at = *fb_half + o.commanded_within_s;
  const std::optional<double> order_then = mean_in(t, abs_order, at - 1.0, at);
  return order_then && *order_then < *order_level * kStopShare;
}

// A trip when the stretch near zero from index iz, ending at t_off_end, follows a clearly
// non-zero level with a fast fall; nullopt otherwise.
std::optional<detail::Trip> trip_at(const std::vector<double>& t, const detail::UnitProfile& p,
                                    const UnitFeedback& feedback, std::size_t unit, std::size_t iz,
                                    double t_off_end, const FailureTestOptions& o) {
  const double tz = t[iz];
  if (t_off_end - tz < o.min_off_s) return std::nullopt;
  const double level_to = tz - o.max_fall_s;
  std::vector<double> level = detail::valid_in(t, p.abs, level_to - o.level_window_s, level_to);
  if (level.size() < 3) return std::nullopt;
  detail::Trip trip;
  trip.unit = unit;
  trip.t_z = tz;
  trip.level = detail::median_in_place(level);
  const UnitScale& s = p.scale;
  if (trip.level < std::max(o.min_level_fraction * s.full_scale, 2.0 * s.near_zero)) {
    return std::nullopt;
  }
  // The last sample at fall_from·L before t_z, no further back than max_fall_s.
  std::optional<std::size_t> ihi;
  for (std::size_t i = iz; i-- > 0 && t[i] >= level_to;) {
    if (!std::isnan(p.smooth[i]) && p.smooth[i] >= o.fall_from_fraction * trip.level) {
      ihi = i;
      break;
    }
  }
  if (!ihi) return std::nullopt;
  const std::optional<Fall> fall = fall_of(t, p, feedback, *ihi, o);
  time_the_fall(t, p, fall, *ihi, iz, o, trip);
  if (commanded(t, p, feedback.order, trip, o)) return std::nullopt;
  return trip;
}

// Every trip of one unit: each stretch near zero that starts after a sample above it.
std::vector<detail::Trip> unit_trips(const std::vector<double>& t, const detail::UnitProfile& p,
                                     const UnitFeedback& feedback, std::size_t unit,
                                     const FailureTestOptions& o) {
  std::vector<detail::Trip> trips;
  const double z = p.scale.near_zero;
  bool above = false;  // the last valid sample was above the band
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double v = p.smooth[i];
    if (std::isnan(v)) continue;
    if (v > z) {
      above = true;
      continue;
    }
    if (!above) continue;
    above = false;
    // The stretch lasts until the next valid sample above the band, or the end of the log.
    std::size_t j = i + 1;
    while (j < t.size() && !(p.smooth[j] > z)) ++j;
    const double t_off_end = j < t.size() ? t[j] : t.back();
    if (auto trip = trip_at(t, p, feedback, unit, i, t_off_end, o)) trips.push_back(*trip);
    i = j - 1;
  }
  return trips;
}

// Trips of several units starting within max_fall_s of the first are one event.
std::vector<std::vector<detail::Trip>> group_trips(std::vector<detail::Trip> trips,
                                                   double max_fall_s) {
  std::sort(trips.begin(), trips.end(),
            [](const detail::Trip& a, const detail::Trip& b) { return a.t_f < b.t_f; });
  std::vector<std::vector<detail::Trip>> groups;
  for (const detail::Trip& trip : trips) {
    if (groups.empty() || trip.t_f - groups.back().front().t_f > max_fall_s) groups.emplace_back();
    groups.back().push_back(trip);
  }
  return groups;
}

void check_input(const FailureTestInput& in, bool need_units = true) {
  if (need_units && in.units.empty()) {
    throw core::InputError({{}, {}, {}, "units"}, "no unit feedback (thrust or shaft speed)",
                           "give the thrust or the shaft speed of each unit");
  }
  detail::check_time_axis(in.t_s, "time", 1);
  for (const std::vector<double>* x : {&in.north_m, &in.east_m, &in.heading_rad}) {
    if (!x->empty()) detail::check_same_length(in.t_s.size(), x->size(), "position/heading");
  }
  for (const UnitFeedback& u : in.units) {
    detail::check_same_length(in.t_s.size(), u.values.size(), u.name);
    if (!u.order.empty()) detail::check_same_length(in.t_s.size(), u.order.size(), u.name);
    if (!(u.shaft_speed_exponent > 0.0) || !std::isfinite(u.shaft_speed_exponent)) {
      throw core::InputError({{}, {}, {}, u.name}, "shaft speed exponent must be > 0",
                             "1 for a shaft speed, 2 for a thrust");
    }
  }
}

}  // namespace

void FailureTestOptions::validate() const {
  auto positive = [](const char* key, double v) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw core::InputError::for_option(key, fmt::format("{:g} s must be > 0", v));
    }
  };
  positive("pre_window", pre_window_s);
  positive("redistribution_window", redistribution_window_s);
  if (!(hold_s >= 0.0) || !std::isfinite(hold_s)) {
    throw core::InputError::for_option("hold", fmt::format("{:g} s must be ≥ 0", hold_s));
  }
  positive("response_window", response_window_s);
  positive("max_fall", max_fall_s);
  positive("min_off", min_off_s);
  positive("level_window", level_window_s);
  for (const auto& [key, v] :
       {std::pair{"median_window", median_window_s},
        std::pair{"recovery_median", recovery_median_s}, std::pair{"fix_gap", fix_gap_s}}) {
    if (!(v >= 0.0) || !std::isfinite(v)) {
      throw core::InputError::for_option(key, fmt::format("{:g} s must be ≥ 0", v));
    }
  }
  auto fraction = [](const char* key, double v) {
    if (!(v > 0.0 && v < 1.0)) {
      throw core::InputError::for_option(key, fmt::format("{:g} is not in (0, 1)", v));
    }
  };
  fraction("zero_fraction", zero_fraction);
  fraction("min_level_fraction", min_level_fraction);
  fraction("fall_from_fraction", fall_from_fraction);
  if (!(commanded_within_s >= 0.0) || !std::isfinite(commanded_within_s)) {
    throw core::InputError::for_option("commanded_within_s", "must be ≥ 0 s");
  }
  if (!(takeover_fraction >= 0.0) || !std::isfinite(takeover_fraction)) {
    throw core::InputError::for_option("takeover_fraction", "must be ≥ 0");
  }
  if (!(footprint_edge_share >= 0.0) || !std::isfinite(footprint_edge_share)) {
    throw core::InputError::for_option("footprint_edge_share", "must be ≥ 0");
  }
}

FailureTestResult analyse_failure_test(const FailureTestInput& in, const FailureTestOptions& o) {
  o.validate();
  check_input(in);
  FailureTestResult r;
  std::vector<detail::UnitProfile> profiles;
  std::vector<detail::Trip> trips;
  for (std::size_t k = 0; k < in.units.size(); ++k) {
    profiles.push_back(make_profile(in.t_s, in.units[k], o));
    r.units.push_back(profiles.back().scale);
    if (in.t_s.size() < 2) continue;
    const std::vector<detail::Trip> found = unit_trips(in.t_s, profiles.back(), in.units[k], k, o);
    trips.insert(trips.end(), found.begin(), found.end());
  }
  const std::vector<std::vector<detail::Trip>> groups = group_trips(std::move(trips), o.max_fall_s);
  // Candidates bound each other's windows; those no other unit answered are dropped, and the
  // figures of the rest taken with the events kept as bounds.
  std::vector<FailureEvent> candidates;
  for (const std::vector<detail::Trip>& g : groups) {
    candidates.push_back(detail::event_of(in, g));
  }
  std::vector<FailureEvent> kept;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    FailureEvent e = candidates[k];
    detail::redistribute(in, profiles, detail::neighbours(candidates, k), o, e);
    const bool answered = std::any_of(e.redistribution.begin(), e.redistribution.end(),
                                      [](const UnitRedistribution& u) { return u.took_over; });
    // With the tripped unit's order logged, the order already told a trip from a stop: a bus
    // failure may leave no unit that can take over.
    const bool ordered_checked = std::any_of(in.units.begin(), in.units.end(), [&](const auto& u) {
      return u.name == e.unit && !u.order.empty();
    });
    if (answered || ordered_checked || e.redistribution.empty()) kept.push_back(candidates[k]);
  }
  for (std::size_t k = 0; k < kept.size(); ++k) {
    FailureEvent e = kept[k];
    const detail::Neighbours around = detail::neighbours(kept, k);
    detail::redistribute(in, profiles, around, o, e);
    detail::excursion(in, around, o, e);
    r.events.push_back(std::move(e));
  }
  return r;
}

FailureEvent failure_excursion(const FailureTestInput& in, double t_f_s,
                               const FailureTestOptions& o) {
  o.validate();
  check_input(in, false);
  FailureEvent e;
  e.time_s = t_f_s;
  if (!in.t_s.empty()) detail::excursion(in, {}, o, e);
  return e;
}

}  // namespace dynpos::ident
