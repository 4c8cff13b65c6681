#pragma once
/// \file
/// A hybrid system H = (C, f, D, g) with held inputs u (thesis chapter 5, after Goebel et al.
/// 2012):
///
///     ẋ  = f(t, x, u)   for x ∈ C   (flow map on the flow set)
///     x⁺ = g(t, x, u)   for x ∈ D   (jump map on the jump set)
///
/// The system is a const description: parameters live in the object, the state x and the held
/// inputs u live in the simulator and are passed in. No member function may change the object.
///
/// Why an abstract class and not a concept with type erasure: the simulator, scenarios and the
/// CLI hold systems of different types chosen at run time, and a virtual call costs a few
/// nanoseconds against a flow evaluation that costs far more; a base class also gives the
/// defaults (C = everything, D = ∅, g = identity, no guard) in one place and readable compiler
/// errors. Hot inner loops that need inlining (a fixed-size sub-model stepped many times per
/// tick) use Rk4<N> from rk4.hpp directly with any callable, without this interface.

#include <Eigen/Core>
#include <limits>

namespace dynpos::sim {

/// A read-only view of a state or input vector (binds to Eigen::VectorXd without copying).
using ConstVectorRef = Eigen::Ref<const Eigen::VectorXd>;
/// A writable view of a preallocated vector of the right size.
using VectorRef = Eigen::Ref<Eigen::VectorXd>;

/// The hybrid system H = (C, f, D, g): flow map, flow set, jump set, jump map and an optional
/// guard for locating jump times inside an integration step.
class HybridSystem {
 public:
  virtual ~HybridSystem() = default;

  /// Dimension n of the state x (≥ 1).
  virtual Eigen::Index state_size() const = 0;

  /// Dimension m of the held input u (≥ 0), written by the simulator's periodic tasks.
  virtual Eigen::Index input_size() const { return 0; }

  /// Flow map: dxdt = f(t, x, u), written into the preallocated dxdt of size n.
  /// t [s]; x of size n; u of size m.
  virtual void flow(double t, const ConstVectorRef& x, const ConstVectorRef& u,
                    VectorRef dxdt) const = 0;

  /// True when x ∈ C, where flow is allowed. Default: C = ℝⁿ.
  virtual bool in_flow_set(double /*t*/, const ConstVectorRef& /*x*/,
                           const ConstVectorRef& /*u*/) const {
    return true;
  }

  /// True when x ∈ D, where a jump is allowed. Default: D = ∅.
  virtual bool in_jump_set(double /*t*/, const ConstVectorRef& /*x*/,
                           const ConstVectorRef& /*u*/) const {
    return false;
  }

  /// Jump map: x⁺ = g(t, x, u), written into the preallocated x_plus of size n (never aliases
  /// x). Default: identity.
  virtual void jump(double /*t*/, const ConstVectorRef& x, const ConstVectorRef& /*u*/,
                    VectorRef x_plus) const {
    x_plus = x;
  }

  /// True when guard() is meaningful and the simulator should locate jump times inside a step.
  virtual bool has_guard() const { return false; }

  /// Guard function γ(t, x, u): > 0 while the state is away from D and ≤ 0 once it has entered
  /// D along a flow, so a sign change from > 0 to ≤ 0 over a step brackets a jump time.
  /// Example (bouncing ball): γ = h, the height. Default: +∞ (never crosses).
  virtual double guard(double /*t*/, const ConstVectorRef& /*x*/,
                       const ConstVectorRef& /*u*/) const {
    return std::numeric_limits<double>::infinity();
  }
};

}  // namespace dynpos::sim
