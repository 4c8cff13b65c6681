#pragma once
/// \file
/// The classic fixed-step fourth-order Runge–Kutta method with a preallocated workspace.
///
/// For ẋ = f(t, x) and a step h from (t, x₀):
///
///     k₁ = f(t, x₀)
///     k₂ = f(t + h/2, x₀ + h/2·k₁)
///     k₃ = f(t + h/2, x₀ + h/2·k₂)
///     k₄ = f(t + h, x₀ + h·k₃)
///     x₁ = x₀ + h/6·(k₁ + 2k₂ + 2k₃ + k₄)
///
/// Local error O(h⁵), global error O(h⁴). Rk4<N> is one template for both kinds of state:
/// Rk4<> (N = Eigen::Dynamic) holds Eigen::VectorXd workspace sized once in the constructor, so
/// a step never allocates; Rk4<N> with a fixed N holds Eigen::Matrix<double, N, 1> workspace
/// inside the object, and with a callable f the compiler can inline the whole step (the hot path
/// for fixed-size sub-models).
///
/// The callable is invoked as f(t, x, dxdt) with x a const State& and dxdt a State& of the right
/// size that f must fill; parameters belong in f (a const system), never in the stepper.

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <utility>

namespace dynpos::sim {

/// A classic RK4 stepper for states of compile-time size N (or Eigen::Dynamic).
template <int N = Eigen::Dynamic>
class Rk4 {
 public:
  using State = Eigen::Matrix<double, N, 1>;

  /// A stepper for states of size n (≥ 0; must equal N when N is fixed).
  /// Throws std::invalid_argument on a wrong size.
  explicit Rk4(Eigen::Index n = (N == Eigen::Dynamic ? 0 : N)) {
    if constexpr (N == Eigen::Dynamic) {
      if (n < 0) throw std::invalid_argument("Rk4: state size must be >= 0");
      k1_.resize(n);
      k2_.resize(n);
      k3_.resize(n);
      k4_.resize(n);
      xt_.resize(n);
    } else {
      if (n != N) {
        throw std::invalid_argument("Rk4<" + std::to_string(N) + ">: state size " +
                                    std::to_string(n) + " differs from the template size");
      }
    }
  }

  /// The state size the workspace was built for.
  Eigen::Index size() const noexcept { return k1_.size(); }

  /// One RK4 step of length h [s] from (t, x0) into x1 (x1 may be x0). Both must have size().
  template <typename F>
  void step(F&& f, double t, double h, const State& x0, State& x1) {
    const double half = 0.5 * h;
    f(t, x0, k1_);
    xt_ = x0 + half * k1_;
    f(t + half, xt_, k2_);
    xt_ = x0 + half * k2_;
    f(t + half, xt_, k3_);
    xt_ = x0 + h * k3_;
    f(t + h, xt_, k4_);
    // One fused loop; reads x0 element by element before writing x1, so x1 may alias x0.
    x1 = x0 + (h / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
  }

  /// One RK4 step of length h [s] from (t, x), in place.
  template <typename F>
  void step(F&& f, double t, double h, State& x) {
    step(std::forward<F>(f), t, h, x, x);
  }

 private:
  State k1_;
  State k2_;
  State k3_;
  State k4_;
  State xt_;
};

}  // namespace dynpos::sim
