#pragma once
/// \file
/// A transport delay (dead time) e^{−δs} sampled at a fixed period: the discrete part of the
/// actuator models.
///
/// Every actuator here has a command dead time δ (thesis tables 3.23–3.36: the time from a
/// command step until the feedback starts to move). A dead time is not a finite-dimensional
/// ODE, so it is not part of the continuous state integrated by RK4. Instead the caller owns one
/// DelayLine per delayed command and, once per simulator tick (period h), pushes the command
/// and holds the returned delayed value constant over the RK4 step (zero-order hold). The
/// delay is rounded to a whole number of ticks, d = round(δ/h); with h = 0.01 s this is exact
/// for every default in this module.

#include <cstddef>
#include <vector>

namespace dynpos::model {

/// A fixed-length FIFO giving y_k = u_{k−d}, d = round(δ/h); the buffer is allocated once.
class DelayLine {
 public:
  /// An empty line (zero delay, output 0); assign a configured line before use.
  DelayLine() = default;

  /// A line for dead time delay_s [s] (≥ 0) sampled every period_s [s] (> 0), pre-filled with
  /// initial (the command held before t = 0). Throws std::invalid_argument on bad arguments.
  DelayLine(double delay_s, double period_s, double initial = 0.0);

  /// Refills the whole line with value (as if value had been commanded forever).
  void reset(double value);

  /// Pushes the command u_k of this tick and returns the delayed command u_{k−d}.
  double push(double u) noexcept;

  /// The delayed command returned by the last push() (or the initial value).
  double output() const noexcept { return output_; }

  /// The delay in ticks, d = round(δ/h).
  std::size_t delay_ticks() const noexcept { return buffer_.size(); }

 private:
  std::vector<double> buffer_;  // ring of the last d inputs; empty when d = 0
  std::size_t head_ = 0;        // index of the oldest input
  double output_ = 0.0;
};

}  // namespace dynpos::model
