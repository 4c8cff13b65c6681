#include "dynpos/analysis/inertial_bridge.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "dynpos/core/rotation.hpp"
#include "dynpos/core/samples.hpp"

namespace dynpos::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kNever = -std::numeric_limits<double>::infinity();

void check(const BridgeSeries& s) {
  const std::size_t n = s.t_s.size();
  const bool equal = s.accel_b.size() == n && s.north_m.size() == n && s.east_m.size() == n &&
                     s.heading_rad.size() == n && s.roll_rad.size() == n && s.pitch_rad.size() == n;
  if (!equal) throw std::invalid_argument("inertial bridge: the series differ in length");
  for (std::size_t i = 1; i < n; ++i) {
    if (!(s.t_s[i] > s.t_s[i - 1])) {
      throw std::invalid_argument("inertial bridge: time does not increase at row " +
                                  std::to_string(i));
    }
  }
}

// R_nb at each row from the held attitude (NaN where an angle is missing or stale).
std::vector<Eigen::Matrix3d> attitudes(const BridgeSeries& s, double max_hold_s) {
  const std::vector<double> roll = core::hold_samples(s.t_s, s.roll_rad, max_hold_s).value;
  const std::vector<double> pitch = core::hold_samples(s.t_s, s.pitch_rad, max_hold_s).value;
  const std::vector<double> heading = core::hold_samples(s.t_s, s.heading_rad, max_hold_s).value;
  std::vector<Eigen::Matrix3d> R(s.t_s.size(), Eigen::Matrix3d::Constant(kNaN));
  for (std::size_t i = 0; i < R.size(); ++i) {
    if (!std::isnan(roll[i]) && !std::isnan(pitch[i]) && !std::isnan(heading[i])) {
      R[i] = core::R_nb_zyx(roll[i], pitch[i], heading[i]);
    }
  }
  return R;
}

// The MRU's horizontal acceleration in NED at each row: each sample turned by its row's
// attitude, linear between two samples at most max_hold_s apart, NaN elsewhere (no sample near,
// or a stale one: the bridge ends there).
std::vector<Eigen::Vector2d> accel_n(const BridgeSeries& s, const std::vector<Eigen::Matrix3d>& R,
                                     double max_hold_s) {
  std::vector<std::size_t> samples;
  for (std::size_t i = 0; i < s.t_s.size(); ++i) {
    if (s.accel_b[i].allFinite() && R[i].allFinite()) samples.push_back(i);
  }
  std::vector<Eigen::Vector2d> out(s.t_s.size(), Eigen::Vector2d::Constant(kNaN));
  const auto turned = [&](std::size_t i) -> Eigen::Vector2d {
    return (R[i] * s.accel_b[i]).head<2>();
  };
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const std::size_t a = samples[k];
    out[a] = turned(a);
    if (k + 1 == samples.size()) break;
    const std::size_t b = samples[k + 1];
    const double span = s.t_s[b] - s.t_s[a];
    if (span > max_hold_s) continue;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double w = (s.t_s[i] - s.t_s[a]) / span;
      out[i] = (1.0 - w) * turned(a) + w * turned(b);
    }
  }
  return out;
}

bool has_fix(const BridgeSeries& s, std::size_t i) {
  return !std::isnan(s.north_m[i]) && !std::isnan(s.east_m[i]);
}

// The length of the GNSS gap each row without a fix lies in (from the fix before to the fix
// after, or the log's end) [s]; 0 on a fix.
std::vector<double> gap_lengths(const BridgeSeries& s) {
  const std::size_t n = s.t_s.size();
  std::vector<double> next_fix(n), gap(n);
  for (std::size_t i = n; i-- > 0;) {
    next_fix[i] = has_fix(s, i) || i + 1 == n ? s.t_s[i] : next_fix[i + 1];
  }
  double last_fix = kNever;
  for (std::size_t i = 0; i < n; ++i) {
    if (has_fix(s, i)) last_fix = s.t_s[i];
    gap[i] = has_fix(s, i) ? 0.0 : next_fix[i] - last_fix;
  }
  return gap;
}

}  // namespace

BridgedTrack bridge_gnss_gaps(const BridgeSeries& s, const Eigen::Vector3d& arm_b,
                              const control::InertialPositionTuning& tuning, double max_hold_s) {
  check(s);
  const std::vector<Eigen::Matrix3d> R = attitudes(s, max_hold_s);
  const std::vector<Eigen::Vector2d> a_n = accel_n(s, R, max_hold_s);
  const std::vector<double> gap = gap_lengths(s);
  control::InertialPosition ins(tuning);
  BridgedTrack out{s.north_m, s.east_m};
  // The mean of the readings turned into NED, over the samples with an attitude.
  Eigen::Vector3d sum_a = Eigen::Vector3d::Zero();
  std::size_t n_a = 0;
  for (std::size_t i = 0; i < s.t_s.size(); ++i) {
    if (s.accel_b[i].allFinite() && R[i].allFinite()) sum_a += R[i] * s.accel_b[i], ++n_a;
  }
  if (n_a > 0) {
    const Eigen::Vector3d mean = sum_a / static_cast<double>(n_a);
    out.mean_horizontal_accel_mps2 = mean.head<2>().norm();
    out.mean_down_accel_mps2 = mean.z();
  }
  for (std::size_t i = 1; i < s.t_s.size(); ++i) {
    const Eigen::Vector2d arm_n = (R[i] * arm_b).head<2>();
    // Over (t_{i−1}, t_i] on the mean of the accelerations at its ends, then the fix at t_i
    // moved to the MRU's point (NaN without one).
    const Eigen::Vector2d p = ins.step(Eigen::Vector2d(s.north_m[i], s.east_m[i]) + arm_n,
                                       0.5 * (a_n[i - 1] + a_n[i]), s.t_s[i] - s.t_s[i - 1]);
    if (!has_fix(s, i) && gap[i] > max_hold_s && ins.bridging() && arm_n.allFinite()) {
      out.north_m[i] = p.x() - arm_n.x();
      out.east_m[i] = p.y() - arm_n.y();
      ++out.bridged_rows;
      out.longest_gap_bridged_s = std::max(out.longest_gap_bridged_s, gap[i]);
    }
  }
  return out;
}

}  // namespace dynpos::analysis
