#pragma once
// Linear interpolation of a logged channel onto another time axis, shared by the log adapters
// of the lever-arm estimators.

#include <vector>

namespace dynpos::calib::detail {

/// The valid (finite) samples of v at times t interpolated linearly onto `grid` (increasing);
/// NaN outside them. With `unwrap`, angles [rad] are unwrapped before interpolating.
std::vector<double> resample_onto(const std::vector<double>& t, const std::vector<double>& v,
                                  const std::vector<double>& grid, bool unwrap);

}  // namespace dynpos::calib::detail
