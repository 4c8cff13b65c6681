#include "dynpos/analysis/inertial_bridge.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynpos/core/rotation.hpp"

namespace dynpos::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The last valid sample of each attitude angle, held.
struct Attitude {
  double roll = kNaN, pitch = kNaN, heading = kNaN;
  void take(const BridgeSeries& s, std::size_t i) {
    if (!std::isnan(s.roll_rad[i])) roll = s.roll_rad[i];
    if (!std::isnan(s.pitch_rad[i])) pitch = s.pitch_rad[i];
    if (!std::isnan(s.heading_rad[i])) heading = s.heading_rad[i];
  }
  bool known() const { return !std::isnan(roll) && !std::isnan(pitch) && !std::isnan(heading); }
};

void check_lengths(const BridgeSeries& s) {
  const std::size_t n = s.t_s.size();
  for (const std::vector<double>* v :
       {&s.north_m, &s.east_m, &s.heading_rad, &s.roll_rad, &s.pitch_rad}) {
    if (v->size() != n) throw std::invalid_argument("inertial bridge: the series differ in length");
  }
  if (s.accel_b.size() != n) {
    throw std::invalid_argument("inertial bridge: the series differ in length");
  }
}

}  // namespace

BridgedTrack bridge_gnss_gaps(const BridgeSeries& s, const Eigen::Vector3d& arm_b,
                              const control::InertialPositionTuning& tuning, double max_hold_s) {
  check_lengths(s);
  control::InertialPosition ins(tuning);
  BridgedTrack out{s.north_m, s.east_m, 0, 0.0};
  Attitude att;
  Eigen::Vector2d accel_n = Eigen::Vector2d::Constant(kNaN);  // held since its sample
  double last_fix_s = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < s.t_s.size(); ++i) {
    att.take(s, i);
    const Eigen::Matrix3d R = att.known() ? core::R_nb_zyx(att.roll, att.pitch, att.heading)
                                          : Eigen::Matrix3d::Constant(kNaN);
    const Eigen::Vector2d arm_n = (R * arm_b).head<2>();
    const Eigen::Vector2d fix(s.north_m[i], s.east_m[i]);
    const bool has_fix = fix.allFinite();
    if (i > 0 && s.t_s[i] > s.t_s[i - 1]) {
      // Over (t_{i−1}, t_i] on the acceleration held before t_i, then the fix at t_i (at P).
      const Eigen::Vector2d p =
          ins.step(has_fix ? Eigen::Vector2d(fix + arm_n) : Eigen::Vector2d::Constant(kNaN),
                   accel_n, s.t_s[i] - s.t_s[i - 1]);
      if (!has_fix && s.t_s[i] - last_fix_s > max_hold_s && ins.bridging() && arm_n.allFinite()) {
        out.north_m[i] = p.x() - arm_n.x();
        out.east_m[i] = p.y() - arm_n.y();
        ++out.bridged_rows;
        out.longest_gap_bridged_s = std::max(out.longest_gap_bridged_s, s.t_s[i] - last_fix_s);
      }
    }
    if (has_fix) last_fix_s = s.t_s[i];
    if (s.accel_b[i].allFinite()) accel_n = (R * s.accel_b[i]).head<2>();
  }
  return out;
}

}  // namespace dynpos::analysis
