#include "dynpos/model/thruster_unit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::model {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDeg = std::numbers::pi / 180.0;

[[noreturn]] void bad_field(const ThrusterUnit& unit, std::string_view key, std::string what) {
  throw core::InputError::for_option(fmt::format("thruster.{}.{}", unit.name, key),
                                     std::move(what));
}

// The forbidden sectors as intervals [a, b] ⊂ [0, 2π], merged and sorted.
std::vector<std::pair<double, double>> forbidden_intervals(
    const std::vector<AngleSector>& forbidden_deg) {
  std::vector<std::pair<double, double>> out;
  for (const AngleSector& s : forbidden_deg) {
    const double a = s.from_deg * kDeg;
    const double b = s.to_deg * kDeg;
    if (a <= b) {
      out.emplace_back(a, b);
    } else {  // across 0°
      out.emplace_back(a, kTwoPi);
      out.emplace_back(0.0, b);
    }
  }
  std::sort(out.begin(), out.end());
  std::vector<std::pair<double, double>> merged;
  for (const auto& iv : out) {
    if (!merged.empty() && iv.first <= merged.back().second) {
      merged.back().second = std::max(merged.back().second, iv.second);
    } else {
      merged.push_back(iv);
    }
  }
  return merged;
}

}  // namespace

std::string_view unit_type_name(UnitType type) noexcept {
  switch (type) {
    case UnitType::kTunnel:
      return "tunnel";
    case UnitType::kPropeller:
      return "propeller";
    case UnitType::kPropellerRudder:
      return "propeller_rudder";
    default:
      return "azimuth";
  }
}

ThrusterUnit thruster_unit(std::string name, UnitType type, double x_m, double y_m,
                           double max_thrust_N, double max_reverse_thrust_N,
                           std::vector<AngleSector> forbidden_deg) {
  ThrusterUnit u;
  u.name = std::move(name);
  u.type = type;
  u.x_m = x_m;
  u.y_m = y_m;
  u.max_thrust_N = max_thrust_N;
  u.max_reverse_thrust_N = max_reverse_thrust_N;
  u.forbidden_deg = std::move(forbidden_deg);
  return u;
}

void ThrusterUnit::validate() const {
  if (name.empty()) throw core::InputError::for_option("thruster.name", "a unit has no name");
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!finite(x_m)) bad_field(*this, "x_m", "the position must be finite");
  if (!finite(y_m)) bad_field(*this, "y_m", "the position must be finite");
  if (!finite(max_thrust_N) || max_thrust_N <= 0.0) {
    bad_field(*this, "max_thrust_N", fmt::format("{} N is not a positive thrust", max_thrust_N));
  }
  if (!finite(max_reverse_thrust_N) || max_reverse_thrust_N < 0.0) {
    bad_field(*this, "max_reverse_thrust_N",
              fmt::format("{} N is not a thrust ≥ 0", max_reverse_thrust_N));
  }
  if (!finite(rate_deg_per_s) || rate_deg_per_s <= 0.0) {
    bad_field(*this, "rate_deg_per_s", fmt::format("{}°/s is not a positive rate", rate_deg_per_s));
  }
  if (time_constant_s && (!finite(*time_constant_s) || *time_constant_s <= 0.0)) {
    bad_field(*this, "time_constant_s",
              fmt::format("{} s is not a positive time constant", *time_constant_s));
  }
  if (thrust_rate_N_per_s && (!finite(*thrust_rate_N_per_s) || *thrust_rate_N_per_s <= 0.0)) {
    bad_field(*this, "thrust_rate_N_per_s",
              fmt::format("{} N/s is not a positive rate", *thrust_rate_N_per_s));
  }
  if (!finite(dead_time_s) || dead_time_s < 0.0) {
    bad_field(*this, "dead_time_s", fmt::format("{} s is not a dead time ≥ 0", dead_time_s));
  }
  if (!finite(weight) || weight <= 0.0) {
    bad_field(*this, "weight", fmt::format("{} is not a positive weight", weight));
  }
  if (!forbidden_deg.empty() && type != UnitType::kAzimuth) {
    bad_field(*this, "forbidden_deg", "only an azimuth has forbidden sectors");
  }
  for (const AngleSector& s : forbidden_deg) {
    for (const double a : {s.from_deg, s.to_deg}) {
      if (!finite(a) || a < 0.0 || a >= 360.0) {
        bad_field(*this, "forbidden_deg", fmt::format("{}° is not in [0, 360)", a));
      }
    }
    if (s.from_deg == s.to_deg) {
      bad_field(*this, "forbidden_deg",
                fmt::format("the sector [{}, {}] is empty", s.from_deg, s.to_deg));
    }
  }
  if (!loss.empty() && type != UnitType::kAzimuth) {
    bad_field(*this, "loss", "only an azimuth has a loss table (scale a fixed unit's ratings)");
  }
  double largest = 0.0;
  for (std::size_t i = 0; i < loss.size(); ++i) {
    const LossPoint& p = loss[i];
    if (!finite(p.angle_deg) || p.angle_deg < 0.0 || p.angle_deg >= 360.0) {
      bad_field(*this, "loss", fmt::format("{}° is not in [0, 360)", p.angle_deg));
    }
    if (i > 0 && p.angle_deg <= loss[i - 1].angle_deg) {
      bad_field(*this, "loss",
                fmt::format("the angles must increase: {}° after {}°", p.angle_deg,
                            loss[i - 1].angle_deg));
    }
    if (!finite(p.factor) || p.factor < 0.0 || p.factor > 1.0) {
      bad_field(*this, "loss", fmt::format("the factor {} is not in [0, 1]", p.factor));
    }
    largest = std::max(largest, p.factor);
  }
  if (!loss.empty() && largest <= 0.0) bad_field(*this, "loss", "every factor is 0");
  if (type == UnitType::kAzimuth && allowed_arcs(forbidden_deg).empty()) {
    bad_field(*this, "forbidden_deg", "the sectors forbid every direction");
  }
  if (!finite(rudder_lift_per_thrust) || rudder_lift_per_thrust < 0.0 ||
      !finite(rudder_lift_at_zero_N) || rudder_lift_at_zero_N < 0.0) {
    bad_field(*this, "rudder_lift_per_thrust", "the rudder's lift must be finite and ≥ 0");
  }
  if (!finite(rudder_max_force_N) || rudder_max_force_N < 0.0) {
    bad_field(*this, "rudder_max_force_N", "the rudder's largest force must be finite and ≥ 0");
  }
  if (rudder_x_m && !finite(*rudder_x_m)) {
    bad_field(*this, "rudder_x_m", "the rudder's position must be finite");
  }
}

std::vector<AllowedArc> allowed_arcs(const std::vector<AngleSector>& forbidden_deg) {
  const auto forbidden = forbidden_intervals(forbidden_deg);
  if (forbidden.empty()) return {{0.0, kTwoPi}};
  // The gaps between forbidden intervals, the one across 0 joined into one arc.
  std::vector<std::pair<double, double>> gaps;  // (from, span)
  for (std::size_t i = 0; i < forbidden.size(); ++i) {
    const double from = forbidden[i].second;
    const double to =
        i + 1 < forbidden.size() ? forbidden[i + 1].first : forbidden.front().first + kTwoPi;
    if (to - from > 1e-12) gaps.emplace_back(std::fmod(from, kTwoPi), to - from);
  }
  std::vector<AllowedArc> out;
  for (const auto& [from, span] : gaps) {
    const int pieces = static_cast<int>(std::ceil(span / std::numbers::pi - 1e-12));
    for (int k = 0; k < pieces; ++k) {
      out.push_back({std::fmod(from + k * span / pieces, kTwoPi), span / pieces});
    }
  }
  return out;
}

bool in_forbidden_sector(double alpha_rad, const std::vector<AngleSector>& forbidden_deg,
                         double tolerance_rad) {
  const auto wrap = [](double a) { return std::fmod(std::fmod(a, kTwoPi) + kTwoPi, kTwoPi); };
  for (const AngleSector& s : forbidden_deg) {
    const double span = wrap((s.to_deg - s.from_deg) * kDeg);
    const double after = wrap(alpha_rad - s.from_deg * kDeg);
    if (after > tolerance_rad && after < span - tolerance_rad) return true;
  }
  return false;
}

}  // namespace dynpos::model
