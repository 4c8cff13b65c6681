#include "dynpos/ident/station_keeping.hpp"

#include <fmt/core.h>

#include <cmath>
#include <numbers>

#include "dynpos/core/circular_stats.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::ident {
namespace {

// An error of the window, named by its request key (analysis/options.hpp).
core::InputError window_error(const std::string& what, const std::string& hint = {}) {
  return core::InputError::for_option("from/to", what, hint);
}

// Valid samples of x with t in [from, to].
std::vector<double> in_window(const std::vector<double>& t, const std::vector<double>& x,
                              double from, double to) {
  std::vector<double> out;
  for (std::size_t i = 0; i < t.size() && i < x.size(); ++i) {
    if (t[i] >= from && t[i] <= to && !std::isnan(x[i])) out.push_back(x[i]);
  }
  return out;
}

MeanStd linear_stats(const std::vector<double>& v) {
  if (v.empty()) return {};
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  double var = 0.0;
  for (double x : v) var += (x - mean) * (x - mean);
  return {mean, std::sqrt(var / static_cast<double>(v.size()))};
}

MeanStd circular(const std::vector<double>& v) {
  const core::CircularStats s = core::circular_stats(v);
  return {s.mean_rad, s.std_rad};
}

std::optional<double> add(const std::optional<double>& a, const std::optional<double>& b) {
  return a && b ? std::optional<double>(*a + *b) : std::nullopt;
}

}  // namespace

StationKeepingResult analyse_station_keeping(const StationKeepingInput& in, const TimeWindow& w,
                                             const ChannelIntegralOptions& integrals,
                                             std::size_t min_position_samples) {
  if (in.t_s.size() < 2) throw window_error("the log has fewer than two rows");
  const double t0 = in.log_start_s.value_or(in.t_s.front());
  const double t1 = in.log_end_s.value_or(in.t_s.back());
  if (!(w.t_to_s > w.t_from_s)) {
    throw window_error(fmt::format("the window {:g} … {:g} s is empty", w.t_from_s, w.t_to_s));
  }
  if (w.t_from_s < t0 - 1e-9 || w.t_to_s > t1 + 1e-9) {
    throw window_error(fmt::format("the window {:g} … {:g} s is not inside the log ({:g} … {:g} s)",
                                   w.t_from_s, w.t_to_s, t0, t1),
                       "choose --from/--to inside the log, or a shorter --duration");
  }
  if (in.north_m.empty() || in.east_m.empty()) {
    throw core::InputError({{}, {}, {}, "north/east"}, "the position is not in the log",
                           "map north and east (e.g. --col north=gnss1.north --col "
                           "east=gnss1.east) or lat and lon");
  }
  StationKeepingResult r;
  r.window = w;
  const auto north = in_window(in.t_s, in.north_m, w.t_from_s, w.t_to_s);
  const auto east = in_window(in.t_s, in.east_m, w.t_from_s, w.t_to_s);
  r.position_samples = std::min(north.size(), east.size());
  if (r.position_samples < min_position_samples) {
    throw window_error("only " + std::to_string(r.position_samples) +
                           " position samples in the window '" + w.name + "' (at least " +
                           std::to_string(min_position_samples) + " needed)",
                       "use a longer window");
  }
  r.position_std_north_m = linear_stats(north).std;
  r.position_std_east_m = linear_stats(east).std;
  r.heading_rad = circular(in_window(in.t_s, in.heading_rad, w.t_from_s, w.t_to_s));
  r.wind_speed_mps = linear_stats(in_window(in.t_s, in.wind_speed_mps, w.t_from_s, w.t_to_s));
  r.wind_dir_rad = circular(in_window(in.t_s, in.wind_dir_rad, w.t_from_s, w.t_to_s));

  ChannelIntegralOptions abs = integrals;
  abs.absolute = true;
  std::optional<double> total_thrust = 0.0, total_acc = 0.0, total_energy = 0.0;
  for (const ThrusterChannels& c : in.thrusters) {
    ThrusterSummary s;
    s.name = c.name;
    if (!c.thrust_N.empty()) {
      const ChannelIntegral i = integrate_channel(in.t_s, c.thrust_N, w.t_from_s, w.t_to_s, abs);
      s.mean_abs_thrust_N = i.mean;
      s.accumulated_thrust_Ns = i.integral;
    }
    if (!c.power_W.empty()) {
      s.energy_J = integrate_channel(in.t_s, c.power_W, w.t_from_s, w.t_to_s, integrals).integral;
    }
    total_thrust = add(total_thrust, s.mean_abs_thrust_N);
    total_acc = add(total_acc, s.accumulated_thrust_Ns);
    total_energy = add(total_energy, s.energy_J);
    r.thrusters.push_back(std::move(s));
  }
  if (!in.thrusters.empty()) {
    r.total_mean_abs_thrust_N = total_thrust;
    r.total_accumulated_thrust_Ns = total_acc;
    r.total_energy_J = total_energy;
  }
  return r;
}

std::vector<TimeWindow> setpoint_windows(const std::vector<double>& t,
                                         const std::vector<double>& sp_north,
                                         const std::vector<double>& sp_east,
                                         const std::vector<double>& sp_heading, double duration_s) {
  std::vector<TimeWindow> out;
  if (t.size() < 2 || !(duration_s > 0.0)) return out;
  const auto at = [](const std::vector<double>& x, std::size_t i) {
    return i < x.size() ? x[i] : std::nan("");
  };
  double n = std::nan(""), e = std::nan(""), h = std::nan("");
  double hold_start = t.front();
  const auto close = [&](double t_end) {
    if (std::isnan(h) && std::isnan(n)) return;
    TimeWindow w;
    const double deg = std::isnan(h) ? 0.0 : h * 180.0 / std::numbers::pi;
    w.name = std::isnan(h) ? "setpoint" : "heading " + std::to_string(std::lround(deg));
    w.t_to_s = t_end;
    w.t_from_s = std::max(hold_start, t_end - duration_s);
    if (w.t_to_s - w.t_from_s >= 0.5 * duration_s) out.push_back(w);
  };
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double ni = at(sp_north, i), ei = at(sp_east, i), hi = at(sp_heading, i);
    const bool changed = (!std::isnan(ni) && !std::isnan(n) && std::abs(ni - n) > 1e-6) ||
                         (!std::isnan(ei) && !std::isnan(e) && std::abs(ei - e) > 1e-6) ||
                         (!std::isnan(hi) && !std::isnan(h) &&
                          std::abs(std::remainder(hi - h, 2.0 * std::numbers::pi)) > 1e-6);
    if (changed) {
      close(t[i - 1]);
      hold_start = t[i];
    }
    if (!std::isnan(ni)) n = ni;
    if (!std::isnan(ei)) e = ei;
    if (!std::isnan(hi)) h = hi;
  }
  close(t.back());
  return out;
}

}  // namespace dynpos::ident
