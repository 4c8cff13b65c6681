#pragma once
/// \file
/// Seeded noise processes for sensors and environment disturbances, built on Rng.
///
/// Each process owns its Rng (seed it from (master seed, source name), random.hpp), so the
/// numbers one source draws never depend on how many other sources exist or in which order
/// they are stepped. Everything here is deterministic given the seed, on every platform.

#include <cstddef>
#include <utility>
#include <vector>

#include "dynpos/sim/random.hpp"

namespace dynpos::sim {

/// Discrete white Gaussian noise: independent samples w_k ~ N(0, σ²).
class WhiteNoise {
 public:
  /// Noise of standard deviation std_dev (≥ 0, in the signal's unit) drawn from rng.
  /// Throws std::invalid_argument if std_dev is negative or not finite.
  WhiteNoise(double std_dev, Rng rng);

  /// The next sample w_k = σ·N(0, 1).
  double sample() { return std_dev_ * rng_.normal(); }

  double std_dev() const noexcept { return std_dev_; }

 private:
  double std_dev_;
  Rng rng_;
};

/// The std of discrete samples at step dt [s] (> 0) that stand for continuous white noise of
/// two-sided power spectral density psd [unit²·s] (≥ 0): σ_d = √(psd/dt).
double discrete_std_from_psd(double psd, double dt);

/// First-order Gauss–Markov process, thesis (2.22): ḃ = −b/T + w with w white of intensity q
/// (E[w(t)w(s)] = q²·δ(t − s)), stepped at a fixed dt by its exact discretisation
///
///     b_{k+1} = φ·b_k + s·n_k,   φ = e^{−dt/T},   s = σ·√(1 − e^{−2dt/T}),   n_k ~ N(0, 1),
///
/// where σ = q·√(T/2) is the stationary std. The limit T → ∞ is the random walk ḃ = w
/// (the bracketed form of (2.22)): φ = 1, s = q·√dt. The correlation time is T: in steady
/// state E[b_k·b_{k+m}] = σ²·e^{−m·dt/T}.
class GaussMarkov {
 public:
  /// A process with time constant T = time_constant [s] (> 0, or +∞ for the random walk),
  /// stationary std σ = stationary_std (≥ 0, finite T only), step dt [s] (> 0), initial value b₀.
  /// Throws std::invalid_argument on an out-of-range argument.
  static GaussMarkov with_stationary_std(double time_constant, double stationary_std, double dt,
                                         Rng rng, double initial = 0.0);

  /// A process with time constant T [s] (> 0, +∞ allowed) driven by white noise of intensity
  /// q = noise_intensity [unit/√s] (≥ 0), step dt [s] (> 0), initial value b₀.
  static GaussMarkov with_noise_intensity(double time_constant, double noise_intensity, double dt,
                                          Rng rng, double initial = 0.0);

  /// The random walk ḃ = w, (2.22) in brackets: b_{k+1} = b_k + q·√dt·n_k.
  static GaussMarkov random_walk(double noise_intensity, double dt, Rng rng, double initial = 0.0);

  /// b_k.
  double value() const noexcept { return value_; }

  /// Advances one step dt and returns b_{k+1}.
  double step() {
    value_ = phi_ * value_ + step_std_ * rng_.normal();
    return value_;
  }

  /// Sets b_k.
  void reset(double value) noexcept { value_ = value; }

  /// Draws b_k from the stationary distribution N(0, σ²), so statistics hold from the start.
  /// Throws std::logic_error for the random walk, which has none.
  void reset_stationary();

  double time_constant() const noexcept { return time_constant_; }    ///< T [s] (+∞: random walk)
  double stationary_std() const noexcept { return stationary_std_; }  ///< σ (+∞: random walk)
  double phi() const noexcept { return phi_; }                        ///< φ = e^{−dt/T}
  double step_std() const noexcept { return step_std_; }  ///< s, the std of the increment noise
  double dt() const noexcept { return dt_; }              ///< [s]

 private:
  GaussMarkov(double time_constant, double stationary_std, double phi, double step_std, double dt,
              Rng rng, double initial);

  double time_constant_;
  double stationary_std_;
  double phi_;
  double step_std_;
  double dt_;
  Rng rng_;
  double value_;
};

/// The value rounded to the nearest multiple of resolution (> 0; ties away from zero), as a
/// sensor with that resolution reports it; resolution 0 returns the value unchanged.
/// Throws std::invalid_argument if resolution is negative or not finite.
double quantize(double value, double resolution);

/// A fixed delay of an integer number of pushes: push(x_k) returns x_{k−d}, and the initial
/// value while fewer than d samples have been pushed. Push once per tick of the owning task
/// (every simulator tick for a delay of d ticks; TimeGrid::ticks() turns a delay [s] into d).
template <typename T = double>
class DelayLine {
 public:
  /// A line of delay d = delay (≥ 0 pushes) that outputs `initial` until it has filled.
  DelayLine(std::size_t delay, T initial) : buffer_(delay, std::move(initial)) {}

  /// Stores this push's sample and returns the sample of d pushes ago.
  T push(T sample) {
    if (buffer_.empty()) return sample;
    T out = std::move(buffer_[head_]);
    buffer_[head_] = std::move(sample);
    head_ = head_ + 1 == buffer_.size() ? 0 : head_ + 1;
    return out;
  }

  /// The delay d in pushes.
  std::size_t delay() const noexcept { return buffer_.size(); }

 private:
  std::vector<T> buffer_;
  std::size_t head_ = 0;
};

}  // namespace dynpos::sim
