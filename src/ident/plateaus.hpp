#pragma once
// The plateaus of a step detector's input (private; see step_detector.hpp for the method).

#include <cstddef>
#include <span>
#include <vector>

#include "dynpos/ident/step_detector.hpp"

namespace dynpos::ident::detail {

/// A stretch of the valid samples where the input holds a level.
struct Plateau {
  std::size_t begin = 0;  ///< first and last index into the valid samples
  std::size_t end = 0;
  double start_level = 0.0;  ///< median of its first min_plateau_s/2: the level next to a step
  double end_level = 0.0;    ///< median of its last min_plateau_s/2
  double head_level = 0.0;   ///< median of its first 20·min_plateau_s: the level after a step
  double tail_level = 0.0;   ///< median of its last 20·min_plateau_s: the level before a step
};

/// Plateaus of the valid samples (tv, uv): unions of windows [tᵢ, tᵢ + w] in which the input
/// varies by at most 2h, split where the window level moves more than h from the plateau's
/// first level (a slow drift), with their levels. Scanned in pieces on `jobs` threads (0 = every
/// core); the result does not depend on how many.
std::vector<Plateau> find_plateaus(std::span<const double> tv, std::span<const double> uv, double h,
                                   double w, unsigned jobs);

/// Neighbouring plateaus joined into one level unless the input changes by the threshold
/// between them; a short level left by a small change back is the re-settling of the step into
/// it.
std::vector<Plateau> merge_levels(const std::vector<Plateau>& in, std::span<const double> tv,
                                  std::span<const double> uv, double h, double threshold,
                                  const StepDetectorOptions& options);

}  // namespace dynpos::ident::detail
