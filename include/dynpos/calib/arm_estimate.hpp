#pragma once
/// \file
/// One estimated lever arm, as every estimator of the calib module reports it.

#include <Eigen/Core>
#include <limits>
#include <string>
#include <string_view>

namespace dynpos::calib {

/// How well a maneuver determines one component of an arm (propositions 1–3).
enum class Determinacy {
  kWell,    ///< excited enough that the estimate is trustworthy
  kWeakly,  ///< observable, but poorly conditioned: the estimate is sensitive to noise
  kNot,     ///< not observable from this maneuver
};
std::string_view determinacy_name(Determinacy d);  // "well", "weakly", "not"

/// A lever arm in BODY (x forward, y starboard, z down) from the control origin [m].
struct ArmEstimate {
  std::string name;  ///< the role prefix of the sensor: "gnss1", "mru2", ...
  Eigen::Vector3d l_b_m = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  /// 1σ per axis [m] from the estimator itself; NaN when the estimator gives none.
  Eigen::Vector3d std_m = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Determinacy determinacy[3] = {Determinacy::kWell, Determinacy::kWell, Determinacy::kWell};
};

}  // namespace dynpos::calib
