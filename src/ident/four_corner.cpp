#include "dynpos/ident/four_corner.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dynpos/core/error.hpp"
#include "dynpos/core/samples.hpp"
#include "dynpos/ident/control_origin.hpp"

namespace dynpos::ident {
namespace {

constexpr double kPi = std::numbers::pi;

core::InputError option_error(const char* name, double value, const char* rule) {
  return core::InputError({{}, {}, {}, name},
                          fmt::format("{} = {:g} must be {}", name, value, rule));
}

double wrap(double a) { return std::remainder(a, 2.0 * kPi); }

double at(const std::vector<double>& x, std::size_t i) {
  return i < x.size() ? x[i] : std::nan("");
}

// The last valid sample of x at or before index i (NaN if none).
struct Held {
  const std::vector<double>& x;
  double value = std::nan("");
  std::size_t next = 0;
  double operator()(std::size_t i) {
    for (; next <= i && next < x.size(); ++next) {
      if (!std::isnan(x[next])) value = x[next];
    }
    return value;
  }
};

// Centered moving average of x over [t − w/2, t + w/2], from x's valid samples, at each valid
// sample (NaN elsewhere); angles are averaged as unit vectors. w ≤ 0 returns x.
std::vector<double> centered_mean(const std::vector<double>& t, const std::vector<double>& x,
                                  double w, bool angle) {
  if (!(w > 0.0) || x.empty()) return x;
  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isnan(x[i])) valid.push_back(i);
  }
  std::vector<double> out(x.size(), std::nan(""));
  double sum_a = 0.0, sum_b = 0.0;
  std::size_t lo = 0, hi = 0;  // window [lo, hi) over `valid`
  for (std::size_t k = 0; k < valid.size(); ++k) {
    const double tk = t[valid[k]];
    while (hi < valid.size() && t[valid[hi]] <= tk + 0.5 * w) {
      const double v = x[valid[hi]];
      sum_a += angle ? std::cos(v) : v;
      sum_b += angle ? std::sin(v) : 0.0;
      ++hi;
    }
    while (t[valid[lo]] < tk - 0.5 * w) {
      const double v = x[valid[lo]];
      sum_a -= angle ? std::cos(v) : v;
      sum_b -= angle ? std::sin(v) : 0.0;
      ++lo;
    }
    out[valid[k]] = angle ? std::atan2(sum_b, sum_a) : sum_a / static_cast<double>(hi - lo);
  }
  return out;
}

std::optional<double> add(const std::optional<double>& a, const std::optional<double>& b) {
  return a && b ? std::optional<double>(*a + *b) : std::nullopt;
}

// Accumulated thrust and energy per thruster over [from, to].
void integrate_leg(const FourCornerInput& in, const ChannelIntegralOptions& options, Leg& leg) {
  ChannelIntegralOptions abs = options;
  abs.absolute = true;
  std::optional<double> thrust = 0.0, energy = 0.0;
  for (const ThrusterChannels& c : in.thrusters) {
    ThrusterSummary s;
    s.name = c.name;
    if (!c.thrust_N.empty()) {
      const ChannelIntegral i =
          integrate_channel(in.t_s, c.thrust_N, leg.t_start_s, leg.t_end_s, abs);
      s.mean_abs_thrust_N = i.mean;
      s.accumulated_thrust_Ns = i.integral;
    }
    if (!c.power_W.empty()) {
      s.energy_J =
          integrate_channel(in.t_s, c.power_W, leg.t_start_s, leg.t_end_s, options).integral;
    }
    thrust = add(thrust, s.accumulated_thrust_Ns);
    energy = add(energy, s.energy_J);
    leg.thrusters.push_back(std::move(s));
  }
  if (!in.thrusters.empty()) {
    leg.total_accumulated_thrust_Ns = thrust;
    leg.total_energy_J = energy;
  }
}

// Legs from the setpoint changes; empty when the setpoints never change.
std::vector<Leg> setpoint_legs(const FourCornerInput& in, const FourCornerOptions& o) {
  std::vector<Leg> legs;
  const std::vector<double>& t = in.t_s;
  Held sn{in.setpoint_north_m}, se{in.setpoint_east_m}, sh{in.setpoint_heading_rad};
  // The circle is tested on the low-frequency motion, as a DP system's wave filter gives it.
  const std::vector<double> north = centered_mean(t, in.north_m, o.wave_filter_s, false);
  const std::vector<double> east = centered_mean(t, in.east_m, o.wave_filter_s, false);
  const std::vector<double> heading_lf = centered_mean(t, in.heading_rad, o.wave_filter_s, true);
  Held h{heading_lf};
  double n_prev = std::nan(""), e_prev = std::nan(""), h_prev = std::nan("");
  // The last tested (filtered) position and heading.
  double last_north = std::nan(""), last_east = std::nan(""), last_heading = std::nan("");
  Leg* open = nullptr;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double n = sn(i), e = se(i), hd = sh(i), heading = h(i);
    const bool changed = (!std::isnan(n_prev) && std::abs(n - n_prev) > 1e-6) ||
                         (!std::isnan(e_prev) && std::abs(e - e_prev) > 1e-6) ||
                         (!std::isnan(h_prev) && std::abs(wrap(hd - h_prev)) > 1e-6);
    if (changed) {
      if (open != nullptr && !open->reached) {
        // A change with the vessel at the edge of the circle is the DP system's own "reached"
        // (a sequence issues its next setpoint there); the filtered position may differ from
        // the DP's estimate by decimetres, so the edge is widened by the margins.
        open->t_end_s = t[i];
        const double dn = last_north - n_prev, de = last_east - e_prev;
        open->reached = !std::isnan(last_north) && !std::isnan(last_heading) &&
                        (std::isnan(n_prev) || std::isnan(e_prev) ||
                         std::hypot(dn, de) <= o.radius_m + o.reach_margin_m) &&
                        (std::isnan(h_prev) || std::abs(wrap(last_heading - h_prev)) <=
                                                   o.heading_tol_rad + o.reach_margin_rad);
      }
      Leg leg;
      leg.t_start_s = t[i];
      leg.t_end_s = t.back();
      leg.reached = false;
      leg.setpoint_north_m = n;
      leg.setpoint_east_m = e;
      leg.setpoint_heading_rad = hd;
      // The move in the frame of the previous setpoint heading (0 if none was logged).
      const double psi0 = std::isnan(h_prev) ? 0.0 : h_prev;
      const double dn = std::isnan(n_prev) ? 0.0 : n - n_prev;
      const double de = std::isnan(e_prev) ? 0.0 : e - e_prev;
      leg.forward_m = std::cos(psi0) * dn + std::sin(psi0) * de;
      leg.starboard_m = -std::sin(psi0) * dn + std::cos(psi0) * de;
      leg.heading_change_rad = std::isnan(h_prev) ? 0.0 : wrap(hd - h_prev);
      legs.push_back(std::move(leg));
      open = &legs.back();
    }
    n_prev = n;
    e_prev = e;
    h_prev = hd;
    // The operating circle, tested where the position is sampled.
    if (!std::isnan(at(north, i)) && !std::isnan(at(east, i)) && !std::isnan(heading)) {
      last_north = north[i];
      last_east = east[i];
      last_heading = heading;
    }
    if (open != nullptr && !open->reached && !std::isnan(at(north, i)) &&
        !std::isnan(at(east, i)) && !std::isnan(heading)) {
      const bool in_circle =
          (std::isnan(n) || std::isnan(e) || std::hypot(north[i] - n, east[i] - e) <= o.radius_m) &&
          (std::isnan(hd) || std::abs(wrap(heading - hd)) <= o.heading_tol_rad);
      if (in_circle) {
        open->reached = true;
        open->t_end_s = t[i];
      }
    }
  }
  return legs;
}

// Legs from the track: stretches where the speed over ground or the turn rate is above its
// threshold.
std::vector<Leg> track_legs(const FourCornerInput& in, const FourCornerOptions& o) {
  // Valid position samples, with the heading held from its last valid sample and unwrapped.
  struct Sample {
    double t, n, e, psi;
  };
  std::vector<Sample> s;
  Held h{in.heading_rad};
  double psi_prev = std::nan("");
  double turns = 0.0;
  for (std::size_t i = 0; i < in.t_s.size(); ++i) {
    const double heading = h(i);
    const double n = at(in.north_m, i), e = at(in.east_m, i);
    if (std::isnan(n) || std::isnan(e) || std::isnan(heading)) continue;
    if (!std::isnan(psi_prev)) turns += wrap(heading - psi_prev);
    psi_prev = heading;
    const double psi = s.empty() ? heading : s.front().psi + turns;
    s.push_back({in.t_s[i], n, e, psi});
  }
  std::vector<bool> moving(s.size(), false);
  std::size_t lo = 0, hi = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    while (s[k].t - s[lo].t > o.smoothing_s) ++lo;
    if (hi < k) hi = k;
    while (hi + 1 < s.size() && s[hi + 1].t - s[k].t <= o.smoothing_s) ++hi;
    const double dt = s[hi].t - s[lo].t;
    if (dt <= 0.0) continue;
    const double speed = std::hypot(s[hi].n - s[lo].n, s[hi].e - s[lo].e) / dt;
    const double rate = std::abs(s[hi].psi - s[lo].psi) / dt;
    moving[k] = speed > o.moving_speed_mps || rate > o.moving_rate_rad_s;
  }
  // Runs of motion, short pauses bridged, short runs dropped.
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (!moving[k]) continue;
    if (!runs.empty() && s[k].t - s[runs.back().second].t < o.min_pause_s) {
      runs.back().second = k;
    } else {
      runs.emplace_back(k, k);
    }
  }
  // Corners of each run (Douglas–Peucker): split [a, b] at the sample farthest from the chord
  // while that distance exceeds the tolerance.
  std::vector<std::pair<std::size_t, std::size_t>> segments;
  const auto split = [&](auto&& self, std::size_t a, std::size_t b) -> void {
    const double dn = s[b].n - s[a].n, de = s[b].e - s[a].e;
    const double len = std::hypot(dn, de);
    double worst = 0.0;
    std::size_t at_worst = a;
    for (std::size_t k = a + 1; k < b; ++k) {
      const double pn = s[k].n - s[a].n, pe = s[k].e - s[a].e;
      const double d = len > 0.0 ? std::abs(pn * de - pe * dn) / len : std::hypot(pn, pe);
      if (d > worst) {
        worst = d;
        at_worst = k;
      }
    }
    if (worst > o.corner_tolerance_m) {
      self(self, a, at_worst);
      self(self, at_worst, b);
    } else {
      segments.emplace_back(a, b);
    }
  };
  for (const auto& [a, b] : runs) split(split, a, b);
  std::vector<Leg> legs;
  for (const auto& [a, b] : segments) {
    if (s[b].t - s[a].t < o.min_leg_s) continue;
    Leg leg;
    leg.t_start_s = s[a].t;
    leg.t_end_s = s[b].t;
    const double dn = s[b].n - s[a].n, de = s[b].e - s[a].e, psi0 = s[a].psi;
    leg.forward_m = std::cos(psi0) * dn + std::sin(psi0) * de;
    leg.starboard_m = -std::sin(psi0) * dn + std::cos(psi0) * de;
    leg.heading_change_rad = s[b].psi - s[a].psi;
    if (std::hypot(dn, de) < o.min_move_m && std::abs(leg.heading_change_rad) < o.min_turn_rad) {
      continue;  // swaying in place, not a leg
    }
    legs.push_back(std::move(leg));
  }
  return legs;
}

}  // namespace

void FourCornerOptions::validate() const {
  const auto positive = [](const char* name, double v) {
    if (!(v > 0.0) || !std::isfinite(v)) throw option_error(name, v, "finite and > 0");
  };
  positive("radius_m", radius_m);
  positive("heading_tol_rad", heading_tol_rad);
  positive("moving_speed_mps", moving_speed_mps);
  positive("moving_rate_rad_s", moving_rate_rad_s);
  positive("smoothing_s", smoothing_s);
  positive("min_leg_s", min_leg_s);
  if (!(reach_margin_m >= 0.0) || !std::isfinite(reach_margin_m)) {
    throw option_error("reach_margin_m", reach_margin_m, "finite and >= 0");
  }
  if (!(reach_margin_rad >= 0.0) || !std::isfinite(reach_margin_rad)) {
    throw option_error("reach_margin_rad", reach_margin_rad, "finite and >= 0");
  }
  if (!(wave_filter_s >= 0.0) || !std::isfinite(wave_filter_s)) {
    throw option_error("wave_filter_s", wave_filter_s, "finite and >= 0");
  }
  positive("corner_tolerance_m", corner_tolerance_m);
  positive("min_move_m", min_move_m);
  positive("min_turn_rad", min_turn_rad);
  if (!(min_pause_s >= 0.0) || !std::isfinite(min_pause_s)) {
    throw option_error("min_pause_s", min_pause_s, "finite and >= 0");
  }
}

std::string leg_name(double forward_m, double starboard_m, double heading_change_rad,
                     double min_move_m, double min_turn_rad) {
  const double larger = std::max(std::abs(forward_m), std::abs(starboard_m));
  std::vector<std::string> parts;
  const auto named = [&](double v) {
    return std::abs(v) > min_move_m && std::abs(v) >= 0.25 * larger;
  };
  if (named(forward_m)) {
    parts.push_back(
        fmt::format("{} {:.0f} m", forward_m > 0 ? "ahead" : "astern", std::abs(forward_m)));
  }
  if (named(starboard_m)) {
    parts.push_back(fmt::format("crab to {} {:.0f} m", starboard_m > 0 ? "starboard" : "port",
                                std::abs(starboard_m)));
  }
  if (std::abs(heading_change_rad) > min_turn_rad) {
    parts.push_back(fmt::format("heading change {:+.0f}°", heading_change_rad * 180.0 / kPi));
  }
  if (parts.empty()) return "hold";
  std::string name = parts.front();
  for (std::size_t i = 1; i < parts.size(); ++i) name += ", " + parts[i];
  return name;
}

namespace {
FourCornerResult analyse_at_origin(const FourCornerInput& in, const FourCornerOptions& o);
}  // namespace

FourCornerResult analyse_four_corner(const FourCornerInput& in, const FourCornerOptions& o) {
  o.validate();
  if (in.t_s.size() < 2) {
    throw core::InputError({{}, {}, {}, "time"}, "the log has fewer than two rows");
  }
  if (!core::has_valid_sample(in.north_m) || !core::has_valid_sample(in.east_m)) {
    throw core::InputError({{}, {}, {}, "north/east"}, "the position is not in the log",
                           "map north and east (e.g. --col north=gnss1.north --col "
                           "east=gnss1.east) or lat and lon");
  }
  if (!core::has_valid_sample(in.heading_rad)) {
    throw core::InputError({{}, {}, {}, "heading"}, "the heading is not in the log",
                           "map heading (e.g. --col heading=gyro)");
  }
  const bool have_setpoints = core::has_valid_sample(in.setpoint_north_m) ||
                              core::has_valid_sample(in.setpoint_east_m) ||
                              core::has_valid_sample(in.setpoint_heading_rad);
  if (o.segmentation == LegSegmentation::kSetpoints && !have_setpoints) {
    throw core::InputError({{}, {}, {}, "setpoint.north"}, "the DP setpoints are not in the log",
                           "map setpoint.north, setpoint.east, setpoint.heading, or segment "
                           "from the track");
  }
  if (!std::isfinite(in.arm_x_m) || !std::isfinite(in.arm_y_m)) {
    throw core::InputError({{}, {}, {}, "arm"}, "the antenna lever arm is not finite");
  }
  const FourCornerInput at_origin = in.arm_x_m == 0.0 && in.arm_y_m == 0.0 ? in : [&] {
    FourCornerInput moved = in;
    move_to_control_origin(moved.north_m, moved.east_m, in.heading_rad, in.arm_x_m, in.arm_y_m);
    return moved;
  }();
  return analyse_at_origin(at_origin, o);
}

namespace {

FourCornerResult analyse_at_origin(const FourCornerInput& in, const FourCornerOptions& o) {
  const bool have_setpoints = core::has_valid_sample(in.setpoint_north_m) ||
                              core::has_valid_sample(in.setpoint_east_m) ||
                              core::has_valid_sample(in.setpoint_heading_rad);
  FourCornerResult r;
  if (o.segmentation != LegSegmentation::kTrack && have_setpoints) {
    r.legs = setpoint_legs(in, o);
    r.segmentation = "setpoints";
    if (r.legs.empty() && o.segmentation == LegSegmentation::kSetpoints) {
      throw core::InputError({{}, {}, {}, "setpoint.north"},
                             "the DP setpoints never change in the log: no leg",
                             "segment from the track instead");
    }
  }
  if (r.legs.empty()) {
    r.legs = track_legs(in, o);
    r.segmentation = "track";
  }
  if (r.legs.empty()) {
    throw core::InputError(
        {{}, {}, {}, "north/east"},
        fmt::format("no leg found: no setpoint change and no motion faster "
                    "than {:g} m/s or {:g} deg/s for {:g} s or more",
                    o.moving_speed_mps, o.moving_rate_rad_s * 180.0 / kPi, o.min_leg_s),
        "check the position and heading columns and the time window");
  }
  Leg& total = r.total;
  total.name = "total";
  total.t_start_s = r.legs.front().t_start_s;
  total.t_end_s = r.legs.back().t_end_s;
  total.reached = true;
  total.total_accumulated_thrust_Ns = in.thrusters.empty() ? std::nullopt : std::optional(0.0);
  total.total_energy_J = total.total_accumulated_thrust_Ns;
  for (const ThrusterChannels& c : in.thrusters) {
    ThrusterSummary s;
    s.name = c.name;
    s.accumulated_thrust_Ns = 0.0;
    s.energy_J = 0.0;
    total.thrusters.push_back(s);
  }
  for (Leg& leg : r.legs) {
    leg.duration_s = leg.t_end_s - leg.t_start_s;
    leg.name = leg_name(leg.forward_m, leg.starboard_m, leg.heading_change_rad, o.radius_m,
                        o.heading_tol_rad);
    integrate_leg(in, o.integrals, leg);
    total.duration_s += leg.duration_s;
    total.reached = total.reached && leg.reached;
    for (std::size_t k = 0; k < leg.thrusters.size(); ++k) {
      ThrusterSummary& s = total.thrusters[k];
      s.accumulated_thrust_Ns =
          add(s.accumulated_thrust_Ns, leg.thrusters[k].accumulated_thrust_Ns);
      s.energy_J = add(s.energy_J, leg.thrusters[k].energy_J);
    }
    total.total_accumulated_thrust_Ns =
        add(total.total_accumulated_thrust_Ns, leg.total_accumulated_thrust_Ns);
    total.total_energy_J = add(total.total_energy_J, leg.total_energy_J);
  }
  for (ThrusterSummary& s : total.thrusters) {
    if (s.accumulated_thrust_Ns && total.duration_s > 0.0) {
      s.mean_abs_thrust_N = *s.accumulated_thrust_Ns / total.duration_s;
    }
  }
  return r;
}

}  // namespace
}  // namespace dynpos::ident
