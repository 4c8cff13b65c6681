#include "dynpos/hybrid/first_order_system.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dynpos::hybrid {

FirstOrderCheck FirstOrderParams::check() const {
  return check_first_order_conditions(a_prime(), ki, lambda, P, epsilon, sigma);
}

void FirstOrderParams::validate() const {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("FirstOrderParams: " + what);
  };
  require(std::isfinite(a) && a > 0.0, "a must be finite and > 0 (5.4)");
  require(std::isfinite(kp) && kp >= 0.0, "kp must be finite and >= 0 (5.6)");
  require(std::isfinite(z_d), "z_d must be finite");
  const FirstOrderCheck c = check();
  require(c.ok(), c.reason);
}

FirstOrderSystem::FirstOrderSystem(const FirstOrderParams& params)
    : params_(params), check_(params.check()) {
  params_.validate();
}

void FirstOrderSystem::flow(double, const sim::ConstVectorRef& x, const sim::ConstVectorRef&,
                            sim::VectorRef dxdt) const {
  const double x1 = x(kZ) - params_.z_d;
  const double x2 = x(kD) - x(kDHat);
  dxdt(kZ) = -params_.a_prime() * x1 + x2;  // (5.7)
  dxdt(kDHat) = params_.ki * x1;            // (5.8): d̃̇ = −d̂̇ = −k_i x₁
  dxdt(kD) = 0.0;                           // (5.5)
  dxdt(kLastJump) = 0.0;
}

Eigen::Vector2d FirstOrderSystem::errors(const sim::ConstVectorRef& x) const {
  return {x(kZ) - params_.z_d, x(kD) - x(kDHat)};  // (5.9)
}

bool FirstOrderSystem::in_ideal_jump_set(const Eigen::Vector2d& e) const {
  const double x1 = e(0);
  const double x2 = e(1);
  if (!(std::abs(x1) >= params_.epsilon)) return false;
  const double sigma = params_.sigma;
  return x1 * x2 >= ((check_.gamma + sigma) * x1 * x1 + sigma * x2 * x2) / check_.beta;  // (5.20)
}

bool FirstOrderSystem::in_jump_set(double, const sim::ConstVectorRef& x,
                                   const sim::ConstVectorRef& u) const {
  switch (params_.jump_set) {
    case JumpSet::kNone:
      return false;
    case JumpSet::kIdeal:
      return in_ideal_jump_set(errors(x));
    case JumpSet::kSampled: {
      // An estimate across the last jump mixes two slopes; NaN (no estimate) fails the test.
      if (!(u(kOlderSampleTime) >= x(kLastJump))) return false;
      const double x1 = x(kZ) - params_.z_d;
      return in_ideal_jump_set({x1, estimate_x2(x1, u(kX1DotHat))});  // (5.30)–(5.31)
    }
  }
  return false;
}

void FirstOrderSystem::jump(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef&,
                            sim::VectorRef x_plus) const {
  x_plus = x;
  x_plus(kDHat) = x(kDHat) + params_.lambda * (x(kZ) - params_.z_d);  // (5.12)
  x_plus(kLastJump) = t;
}

Eigen::VectorXd FirstOrderSystem::initial_state(double d0, double t0) const {
  Eigen::VectorXd x(kStateSize);
  x << params_.z_d, d0, d0, t0;
  return x;
}

}  // namespace dynpos::hybrid
