#include "dynpos/model/allocation_bounds.hpp"

#include <limits>

#include "dynpos/model/thrust_configuration.hpp"

namespace dynpos::model {

std::array<Eigen::Matrix<double, 5, 1>, 2> allocation_box(
    std::array<Eigen::Matrix<double, 5, 1>, 2> box, const Eigen::Matrix<double, 5, 1>& previous_N,
    const Eigen::Matrix<double, 5, 1>& rate_limits_N_s, double dt_s, ThrustSignRegion region) {
  using Vector5d = Eigen::Matrix<double, 5, 1>;
  auto& [lo, hi] = box;
  Vector5d rate_lo = Vector5d::Constant(-std::numeric_limits<double>::infinity());
  Vector5d rate_hi = Vector5d::Constant(std::numeric_limits<double>::infinity());
  if (dt_s > 0.0) {
    rate_lo = previous_N - rate_limits_N_s * dt_s;
    rate_hi = previous_N + rate_limits_N_s * dt_s;
  }
  for (int i = 0; i < 5; ++i) {
    const double l = std::max(lo[i], rate_lo[i]);
    const double h = std::min(hi[i], rate_hi[i]);
    if (l <= h) {
      lo[i] = l;
      hi[i] = h;
    } else {
      // The box moved away from the previous value (e.g. the tunnel lost power with speed):
      // the box wins, at the point nearest the previous value.
      lo[i] = hi[i] = std::clamp(previous_N[i], lo[i], hi[i]);
    }
  }
  // The sign region of the main propellers (thrust_allocation.hpp).
  for (int k : {0, 1}) {
    const int j = k == 0 ? ThrustConfiguration::kThrustPort : ThrustConfiguration::kThrustStb;
    if (region[k] > 0) lo[j] = std::min(std::max(lo[j], 0.0), hi[j]);
    if (region[k] < 0) hi[j] = std::max(std::min(hi[j], 0.0), lo[j]);
  }
  return box;
}

}  // namespace dynpos::model
