#pragma once
/// \file
/// The dwell-time rule of a hybrid system: two jumps are at least τ_D apart, which keeps a
/// solution away from Zeno behaviour (Goebel et al. 2012; thesis chapter 5). The simulator
/// applies it to the jumps of a HybridSystem; a discrete controller with jumps of its own (the
/// hybrid integral action of a sampled DP controller) applies it the same way.

#include <optional>

namespace dynpos::sim {

/// Whether a jump is allowed at time t: no jump yet, or t − t_J ≥ τ_D − slack, t_J the last one.
class DwellTime {
 public:
  /// τ_D = dwell_s [s] ≥ 0. slack_s [s] ≥ 0 lets t − t_J fall short of τ_D by that much, so a
  /// dwell of exactly n grid steps holds at the n-th step despite rounding of the tick times
  /// (the simulator uses a slack far below dt); 0 compares exactly. Throws
  /// std::invalid_argument if either is negative or not finite.
  explicit DwellTime(double dwell_s = 0.0, double slack_s = 0.0);

  /// True when a jump at t [s] keeps the dwell time.
  bool allows(double t) const noexcept {
    return !(last_jump_ && t - *last_jump_ < dwell_ - slack_);
  }

  /// Records a jump at t [s].
  void record_jump(double t) noexcept { last_jump_ = t; }

  /// Forgets every jump (a new run).
  void reset() noexcept { last_jump_.reset(); }

  /// The time of the last jump [s]; absent before the first.
  const std::optional<double>& last_jump_time() const noexcept { return last_jump_; }

  double dwell_time() const noexcept { return dwell_; }  ///< τ_D [s]

 private:
  double dwell_;
  double slack_;
  std::optional<double> last_jump_;
};

}  // namespace dynpos::sim
