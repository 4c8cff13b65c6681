#include "ins_preintegration.hpp"

#include <algorithm>

#include "dynpos/core/rotation.hpp"

namespace dynpos::calib::detail {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

InsPreintegration::InsPreintegration(const ImuSeries& imu, const std::vector<Vec3>& theta_rad,
                                     double gravity_mps2)
    : t_(imu.t_s), theta_(theta_rad), omega_(imu.omega_b_rps) {
  const Vec3 g_n(0.0, 0.0, imu.accel == MruAccel::kSpecificForce ? gravity_mps2 : 0.0);
  inv_dt_ = static_cast<double>(t_.size() - 1) / (t_.back() - t_.front());
  node_.resize(t_.size());
  for (std::size_t i = 0; i < t_.size(); ++i) {
    Node& n = node_[i];
    n.R = core::R_nb_zyx(theta_rad[i][0], theta_rad[i][1], theta_rad[i][2]);
    n.A = n.R * imu.accel_b_mps2[i] + g_n;
    if (i == 0) {
      n.V.setZero();
      n.W.setZero();
      n.MV.setZero();
      n.MW.setZero();
      continue;
    }
    const Node& p = node_[i - 1];
    const double h = t_[i] - t_[i - 1];
    // Exact for A and R linear over the step.
    n.V = p.V + 0.5 * h * (p.A + n.A);
    n.W = p.W + h * p.V + h * h / 6.0 * (2.0 * p.A + n.A);
    n.MV = p.MV + 0.5 * h * (p.R + n.R);
    n.MW = p.MW + h * p.MV + h * h / 6.0 * (2.0 * p.R + n.R);
  }
}

// A logger samples at a fixed rate: the guess from the mean spacing is the segment or next
// to it; a short walk corrects it for jitter and gaps.
std::size_t InsPreintegration::segment(double s) const {
  const double last = static_cast<double>(t_.size() - 2);
  std::size_t i = static_cast<std::size_t>(std::clamp((s - t_.front()) * inv_dt_, 0.0, last));
  while (i > 0 && t_[i] > s) --i;
  while (i + 2 < t_.size() && t_[i + 1] <= s) ++i;
  return i;
}

InsPoint InsPreintegration::at(double s) const {
  const std::size_t i = segment(s);
  const Node& a = node_[i];
  const Node& b = node_[i + 1];
  const double h = t_[i + 1] - t_[i];
  const double u = s - t_[i];
  const double c2 = u * u / (2.0 * h), c3 = u * u * u / (6.0 * h);
  InsPoint p;
  p.V = a.V + a.A * u + (b.A - a.A) * c2;
  p.W = a.W + a.V * u + a.A * (0.5 * u * u) + (b.A - a.A) * c3;
  p.MV = a.MV + a.R * u + (b.R - a.R) * c2;
  p.MW = a.MW + a.MV * u + a.R * (0.5 * u * u) + (b.R - a.R) * c3;
  return p;
}

InsDelta InsPreintegration::delta(const InsPoint& a, double tau_s, double s) const {
  const InsPoint b = at(s);
  const double h = s - tau_s;
  return {b.W - a.W - a.V * h, b.V - a.V, b.MW - a.MW - a.MV * h, b.MV - a.MV};
}

Mat3 InsPreintegration::rotation(double s) const {
  const std::size_t i = segment(s);
  const double a = std::clamp((s - t_[i]) / (t_[i + 1] - t_[i]), 0.0, 1.0);
  const Vec3 th = (1.0 - a) * theta_[i] + a * theta_[i + 1];
  return core::R_nb_zyx(th[0], th[1], th[2]);
}

Vec3 InsPreintegration::omega_b(double s) const {
  const std::size_t i = segment(s);
  const double a = std::clamp((s - t_[i]) / (t_[i + 1] - t_[i]), 0.0, 1.0);
  return (1.0 - a) * omega_[i] + a * omega_[i + 1];
}

}  // namespace dynpos::calib::detail
