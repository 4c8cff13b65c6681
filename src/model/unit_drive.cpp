#include "dynpos/model/unit_drive.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dynpos/model/azimuth_region.hpp"

namespace dynpos::model {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kDeg = kPi / 180.0;

// Sources of the defaults, each scaled from the rated thrust:
// Thrust over disc area at the rating [Pa]: the Gunnerus main propeller (73 kN on D = 2.0 m,
// 23 kPa) and tunnel thruster (25 kN on D = 1.2 m, 22 kPa); 25 kPa for a heavier-loaded DP unit.
constexpr double kThrustLoadingPa = 25.0e3;
// K_T at J = 0 ahead: between the Gunnerus main propeller's 0.50 and tunnel's 0.40.
constexpr double kKtAhead = 0.45;
// K_T/K_Q of an open fixed-pitch propeller: 5.5, as the Gunnerus main propeller's K_Q.
constexpr double kKtOverKq = 5.5;
// Shaft time constant at the Gunnerus tunnel thruster's 5.42 rps: its 1 s. A larger propeller
// turns slower and its drive's time constant grows with 1/n_max (spin-up ∝ I·ω/Q ∝ 1/n).
constexpr double kTimeConstantAtRefS = 1.0;
constexpr double kRefShaftSpeedRps = 5.42;
// From rest to full speed in 4 time constants at the rate limit: the tunnel's 5.42/1.4 = 3.9 s.
constexpr double kRampTimeConstants = 4.0;
// Rudder: 35° hard over (IMO steering gear), servo 6.3°/s (the Gunnerus rudder's).
constexpr double kMaxRudderDeg = 35.0;
constexpr double kRudderRateDegS = 6.3;
// The steering servo's gain inside its rate limit [1/s]: settles within ≈ 2 s of the target.
constexpr double kSteeringGain = 2.0;

// Whether the arc from `start` over `length` ≥ 0 [rad] (increasing angle α) crosses the
// interior of a forbidden sector.
bool crosses(const std::vector<AngleSector>& forbidden, double start, double length) {
  constexpr double kEdge = 1e-6;  // touching a sector's edge is allowed
  for (const AngleSector& s : forbidden) {
    const double from = s.from_deg * kDeg;
    const double span = std::fmod(s.to_deg * kDeg - from + kTwoPi, kTwoPi);
    const double d = std::fmod(from - start + 2.0 * kTwoPi, kTwoPi);  // sector start on the arc
    if (d + kEdge < length) return true;         // the sector begins inside the arc
    if (d + span > kTwoPi + kEdge) return true;  // the arc begins inside the sector
  }
  return false;
}

}  // namespace

UnitDriveParams drive_params(const ThrusterUnit& unit) {
  UnitDriveParams p;
  const double rated = std::max(unit.max_thrust_N, unit.max_reverse_thrust_N);
  p.diameter_m = std::sqrt(4.0 * rated / (kPi * kThrustLoadingPa));
  const double d4 = std::pow(p.diameter_m, 4);
  p.max_shaft_speed_rps = std::sqrt(rated / (p.rho * kKtAhead * d4));
  const double c = p.rho * d4 * p.max_shaft_speed_rps * p.max_shaft_speed_rps;
  p.kt_ahead = unit.max_thrust_N / c;
  p.kt_astern = unit.max_reverse_thrust_N / c;
  p.kq = kKtAhead / kKtOverKq;
  p.time_constant_s = unit.time_constant_s.value_or(kTimeConstantAtRefS * kRefShaftSpeedRps /
                                                    p.max_shaft_speed_rps);
  p.rate_limit_rps2 = p.max_shaft_speed_rps / (kRampTimeConstants * p.time_constant_s);
  p.dead_time_s = unit.dead_time_s;
  if (unit.type == UnitType::kPropellerRudder) {
    p.max_rudder_rad = kMaxRudderDeg * kDeg;
    p.rudder_rate_rad_s = kRudderRateDegS * kDeg;
  }
  if (unit.type == UnitType::kPropellerRudder || unit.type == UnitType::kAzimuth) {
    p.steering_gain_per_s = kSteeringGain;
  }
  return p;
}

UnitDrive::UnitDrive(const ThrusterUnit& unit) : unit_(unit) {
  unit_.validate();
  p_ = drive_params(unit_);
}

double UnitDrive::thrust_N(double n) const noexcept {
  const double kt = n >= 0.0 ? p_.kt_ahead : p_.kt_astern;
  return p_.rho * kt * std::pow(p_.diameter_m, 4) * n * std::abs(n);
}

double UnitDrive::shaft_speed_for(double thrust_N) const noexcept {
  const double kt = thrust_N >= 0.0 ? p_.kt_ahead : p_.kt_astern;
  if (kt <= 0.0) return 0.0;
  const double n = std::sqrt(std::abs(thrust_N) / (p_.rho * kt * std::pow(p_.diameter_m, 4)));
  return std::copysign(std::min(n, p_.max_shaft_speed_rps), thrust_N);
}

double UnitDrive::shaft_acceleration(double n, double n_command) const noexcept {
  const double target = std::clamp(n_command, -p_.max_shaft_speed_rps, p_.max_shaft_speed_rps);
  return std::clamp((target - n) / p_.time_constant_s, -p_.rate_limit_rps2, p_.rate_limit_rps2);
}

double UnitDrive::angle_rate(double angle, double command) const noexcept {
  if (unit_.type == UnitType::kPropellerRudder) {
    const double target = std::clamp(command, -p_.max_rudder_rad, p_.max_rudder_rad);
    return std::clamp(p_.steering_gain_per_s * (target - angle), -p_.rudder_rate_rad_s,
                      p_.rudder_rate_rad_s);
  }
  if (unit_.type != UnitType::kAzimuth) return 0.0;
  const double rate = unit_.rate_deg_per_s * kDeg;
  return std::clamp(p_.steering_gain_per_s * turn_rad(angle, command), -rate, rate);
}

bool UnitDrive::turn_crosses(double angle, double turn) const noexcept {
  const double start = turn >= 0.0 ? angle : angle + turn;
  return crosses(unit_.forbidden_deg, std::fmod(std::fmod(start, kTwoPi) + kTwoPi, kTwoPi),
                 std::abs(turn));
}

bool UnitDrive::short_way_blocked(double angle, double command) const noexcept {
  return unit_.type == UnitType::kAzimuth &&
         turn_crosses(angle, std::remainder(command - angle, kTwoPi));
}

double UnitDrive::turn_rad(double angle, double command) const noexcept {
  if (unit_.type != UnitType::kAzimuth) return 0.0;
  const double turn = std::remainder(command - angle, kTwoPi);  // the short way, (−π, π]
  if (!turn_crosses(angle, turn)) return turn;
  const double long_way = turn - std::copysign(kTwoPi, turn);
  // Both ways blocked (an order in another gap between sectors): the short way, through the
  // sector, its thrust cut to nothing meanwhile (the control task's order, cos of the turn left).
  return turn_crosses(angle, long_way) ? turn : long_way;
}

std::optional<AllowedArc> UnitDrive::reachable(double angle, double reach_rad) const noexcept {
  if (unit_.type != UnitType::kAzimuth) return std::nullopt;
  const double a = std::fmod(std::fmod(angle, kTwoPi) + kTwoPi, kTwoPi);
  if (in_forbidden_sector(a, unit_.forbidden_deg)) return std::nullopt;
  const double reach = std::clamp(reach_rad, 0.0, 0.5 * kPi);
  // Clear of the sectors each way: the largest turn up to `reach` that crosses none.
  double ahead = reach, back = reach;
  for (const AngleSector& sector : unit_.forbidden_deg) {
    const double from = sector.from_deg * kDeg;
    const double to = sector.to_deg * kDeg;
    // A turn to a sector's edge; a hair past the edge (round-off) is no turn at all.
    const auto turn = [](double d) {
      d = std::fmod(d + 2.0 * kTwoPi, kTwoPi);
      return d > kTwoPi - 1e-6 ? 0.0 : d;
    };
    ahead = std::min(ahead, turn(from - a));
    back = std::min(back, turn(a - to));
  }
  return AllowedArc{a - back, ahead + back};
}

double UnitDrive::rudder_angle_for(double force_N, double thrust_N) const noexcept {
  if (unit_.type != UnitType::kPropellerRudder) return 0.0;
  const double cone =
      unit_.rudder_lift_per_thrust * std::max(thrust_N, 0.0) + unit_.rudder_lift_at_zero_N;
  if (cone <= 0.0) return 0.0;
  return std::clamp(force_N / cone, -1.0, 1.0) * p_.max_rudder_rad;
}

double UnitDrive::rudder_force(double thrust_N, double rudder_rad) const noexcept {
  const double cone =
      unit_.rudder_lift_per_thrust * std::max(thrust_N, 0.0) + unit_.rudder_lift_at_zero_N;
  const double y = cone * rudder_rad / p_.max_rudder_rad;
  const double cap = unit_.rudder_max_force_N;
  return cap > 0.0 ? std::clamp(y, -cap, cap) : y;
}

UnitOutput UnitDrive::outputs(double n, double angle, double capacity) const noexcept {
  UnitOutput o;
  o.shaft_speed_rps = n;
  o.angle_rad = angle;
  o.thrust_N = capacity * thrust_N(n);
  o.power_W = capacity * kTwoPi * p_.rho * p_.kq * std::pow(p_.diameter_m, 5) * std::abs(n) * n * n;
  double fx = 0.0, fy = 0.0, x_side = unit_.x_m;
  switch (unit_.type) {
    case UnitType::kAzimuth:
      o.thrust_N *= loss_factor(unit_.loss, angle);  // the interaction loss there
      fx = o.thrust_N * std::cos(angle);
      fy = o.thrust_N * std::sin(angle);
      break;
    case UnitType::kTunnel:
      fy = o.thrust_N;
      break;
    case UnitType::kPropeller:
      fx = o.thrust_N;
      break;
    case UnitType::kPropellerRudder:
      fx = o.thrust_N;
      o.rudder_force_N = capacity > 0.0 ? rudder_force(o.thrust_N, angle) : 0.0;
      fy = o.rudder_force_N;
      x_side = unit_.rudder_x_m.value_or(unit_.x_m);
      break;
  }
  o.tau_b = {fx, fy, x_side * fy - unit_.y_m * fx};  // (2.2)
  return o;
}

}  // namespace dynpos::model
