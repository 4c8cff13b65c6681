#include "dynpos/model/delay_line.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dynpos::model {

DelayLine::DelayLine(double delay_s, double period_s, double initial) {
  if (!(period_s > 0.0) || !std::isfinite(period_s)) {
    throw std::invalid_argument("DelayLine: period_s = " + std::to_string(period_s) +
                                ": must be finite and > 0");
  }
  if (!(delay_s >= 0.0) || !std::isfinite(delay_s)) {
    throw std::invalid_argument("DelayLine: delay_s = " + std::to_string(delay_s) +
                                ": must be finite and >= 0");
  }
  const double ticks = std::round(delay_s / period_s);
  if (ticks > 1.0e7) {
    throw std::invalid_argument("DelayLine: delay_s / period_s = " + std::to_string(ticks) +
                                ": must be <= 1e7 ticks");
  }
  buffer_.assign(static_cast<std::size_t>(ticks), initial);
  output_ = initial;
}

void DelayLine::reset(double value) {
  std::fill(buffer_.begin(), buffer_.end(), value);
  head_ = 0;
  output_ = value;
}

double DelayLine::push(double u) noexcept {
  if (buffer_.empty()) {
    output_ = u;
    return output_;
  }
  // The oldest entry is u_{k−d}; replace it by u_k and advance.
  output_ = buffer_[head_];
  buffer_[head_] = u;
  head_ = (head_ + 1 == buffer_.size()) ? 0 : head_ + 1;
  return output_;
}

}  // namespace dynpos::model
