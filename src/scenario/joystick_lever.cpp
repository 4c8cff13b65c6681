#include "dynpos/scenario/joystick_lever.hpp"

#include <algorithm>
#include <cmath>

namespace dynpos::scenario {

Eigen::Vector3d lever_to_demand_fraction(const Eigen::Vector3d& lever_pct, double exponent) {
  const Eigen::Vector3d p = lever_pct / 100.0;
  const double r = std::hypot(p.x(), p.y());
  // r^(e−1) is 0 at r = 0 for e > 1 and 1 for e = 1 (std::pow(0, 0) = 1), as the curve needs.
  const double shape = std::pow(r, exponent - 1.0);
  const double yaw = std::copysign(std::pow(std::abs(p.z()), exponent), p.z());
  return Eigen::Vector3d(p.x() * shape, p.y() * shape, yaw).cwiseMax(-1.0).cwiseMin(1.0);
}

double lever_pct_for_fraction(double fraction, double exponent) {
  return std::copysign(100.0 * std::pow(std::abs(fraction), 1.0 / exponent), fraction);
}

}  // namespace dynpos::scenario
