#pragma once
/// \file
/// The typical sample spacing of a time series: the median of its spacings, robust to gaps.

#include <vector>

namespace dynpos::core {

/// The median of the spacings t[i+1] − t[i] [s] of a strictly increasing sequence (the mean of
/// the two middle ones for an even count). Throws std::invalid_argument with fewer than two
/// times. A long axis is counted in pieces on `jobs` threads (0 = every core); the result does
/// not depend on how many.
double median_spacing_s(const std::vector<double>& time_s, unsigned jobs);

}  // namespace dynpos::core
