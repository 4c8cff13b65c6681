#include "dynpos/model/thrust_allocation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

#include <Eigen/QR>

#include "actuator_checks.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::model {

using Vector5d = Eigen::Matrix<double, 5, 1>;

namespace {

constexpr double kDegToRad = detail::kPi / 180.0;

// The [allocation] table: every option with its range (core/param_range.hpp).
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> fields(P& p) {
  return {
      {{"weight_thrust_port", "1", 1e-6, 1e6}, &p.weights[0]},
      {{"weight_thrust_stb", "1", 1e-6, 1e6}, &p.weights[1]},
      {{"weight_rudder_port", "1", 1e-6, 1e6}, &p.weights[2]},
      {{"weight_rudder_stb", "1", 1e-6, 1e6}, &p.weights[3]},
      {{"weight_tunnel", "1", 1e-6, 1e6}, &p.weights[4]},
      {{"priority_surge", "1", 1e-6, 1e6}, &p.priority[0]},
      {{"priority_sway", "1", 1e-6, 1e6}, &p.priority[1]},
      {{"priority_yaw", "1", 1e-6, 1e6}, &p.priority[2]},
      {{"force_scale_N", "N", 1, 1e9}, &p.force_scale},
      {{"moment_scale_Nm", "N·m", 1, 1e10}, &p.moment_scale},
      {{"max_rudder_angle_deg", "deg", 1, 60, false, false, kDegToRad}, &p.max_rudder_angle},
      {{"rate_thrust_port_N_per_s", "N/s", 1, 1e8}, &p.rate_limits[0]},
      {{"rate_thrust_stb_N_per_s", "N/s", 1, 1e8}, &p.rate_limits[1]},
      {{"rate_rudder_port_N_per_s", "N/s", 1, 1e8}, &p.rate_limits[2]},
      {{"rate_rudder_stb_N_per_s", "N/s", 1, 1e8}, &p.rate_limits[3]},
      {{"rate_tunnel_N_per_s", "N/s", 1, 1e8}, &p.rate_limits[4]},
      {{"rudder_drag_compensation", "1", 0, 1}, &p.rudder_drag_compensation},
      {{"hold_weight", "1", 0, 1e3}, &p.hold_weight},
  };
}

}  // namespace

std::vector<core::ParamField> param_fields(ThrustAllocationOptions& options) {
  return fields(options);
}

void ThrustAllocationOptions::validate() const {
  core::check_ranges("allocation", fields(*this));
  for (int k = 0; k < 5; ++k) {
    if (!std::isfinite(capacity(k)) || capacity(k) < 0.0) {
      throw core::InputError({}, "allocation capacity " + std::to_string(capacity(k)) +
                                     " of variable " + std::to_string(k) + " is not ≥ 0");
    }
  }
}

ThrustAllocator::ThrustAllocator(const Thruster& propeller, const Rudder& rudder,
                                 const TunnelThruster& tunnel,
                                 const ThrustConfiguration& configuration,
                                 const ThrustAllocationOptions& options)
    : propeller_(propeller),
      rudder_(rudder),
      tunnel_(tunnel),
      configuration_(configuration),
      options_(options) {
  options_.validate();
}

std::array<Vector5d, 2> ThrustAllocator::bounds(double surge_speed) const noexcept {
  Vector5d lo;
  Vector5d hi;
  const double t_fwd = propeller_.max_thrust_forward();
  const double t_rev = propeller_.max_thrust_reverse();
  // The widest rudder side force: the cone at full ahead thrust.
  const double rudder_angle = std::min(options_.max_rudder_angle, rudder_.params().stall_angle);
  const double y_max = rudder_.dynamic_pressure(std::max(surge_speed, 0.0), t_fwd) *
                       rudder_.params().area * rudder_.params().lift_slope *
                       std::min(rudder_angle, rudder_.params().max_angle);
  lo << -t_rev, -t_rev, -y_max, -y_max, -tunnel_.max_thrust_port(surge_speed);
  hi << t_fwd, t_fwd, y_max, y_max, tunnel_.max_thrust_starboard(surge_speed);
  return {lo.cwiseProduct(options_.capacity), hi.cwiseProduct(options_.capacity)};
}

ThrustAllocationResult ThrustAllocator::allocate(const ThrustAllocationInput& input) const {
  ThrustAllocationResult plain = allocate_with_drag(input, {0, 0}, false);
  if (!input.hold_forces || options_.hold_weight <= 0.0 ||
      plain.status == AllocationStatus::kInvalidInput) {
    return plain;
  }
  // Holding (file comment): the candidates are the plain solve, the solve within each sign
  // region of the two main propellers, and the pulled solve over both signs and within the
  // region of the held thrusts. The plain one comes first and wins ties.
  const Vector5d& h = *input.hold_forces;
  const SignRegion held_region{h[0] >= 0.0 ? 1 : -1, h[1] >= 0.0 ? 1 : -1};
  constexpr std::size_t kCount = 7;
  std::array<ThrustAllocationResult, kCount> candidates{
      std::move(plain),
      allocate_with_drag(input, {1, 1}, false),
      allocate_with_drag(input, {1, -1}, false),
      allocate_with_drag(input, {-1, 1}, false),
      allocate_with_drag(input, {-1, -1}, false),
      allocate_with_drag(input, {0, 0}, true),
      allocate_with_drag(input, held_region, true)};
  // Demand first: eligible are the candidates that meet τ_d or, when none does, those whose
  // priority-weighted unmet part is within 5 % of the least, so that two saturated branches
  // whose unmet parts cross do not alternate on the waves' noise, and no larger than the plain
  // one's, so that holding never costs demand.
  bool any_met = false;
  double least_unmet = std::numeric_limits<double>::infinity();
  const double plain_unmet = weighted_unmet(candidates[0]);
  std::array<double, kCount> unmet{};
  for (std::size_t i = 0; i < kCount; ++i) {
    any_met = any_met || candidates[i].status == AllocationStatus::kOk;
    unmet[i] = weighted_unmet(candidates[i]);
    least_unmet = std::min(least_unmet, unmet[i]);
  }
  // Then the eligible split nearest the held forces, in the weighted norm with each force over
  // its box bound.
  const auto [lo, hi] = bounds(input.surge_speed);
  const auto distance = [&, &lo = lo, &hi = hi](const Vector5d& f) {
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) {
      const double s = std::max({std::abs(lo[i]), std::abs(hi[i]), 1.0});
      sum += options_.weights[i] * std::pow((f[i] - h[i]) / s, 2);
    }
    return sum;
  };
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < kCount; ++i) {
    const bool eligible = any_met ? candidates[i].status == AllocationStatus::kOk
                                  : unmet[i] <= std::min(1.05 * least_unmet, plain_unmet);
    if (!eligible) continue;
    const double d = distance(candidates[i].forces);
    if (d < best_distance) {
      best = i;
      best_distance = d;
    }
  }
  return std::move(candidates[best]);
}

double ThrustAllocator::weighted_unmet(const ThrustAllocationResult& r) const {
  const Eigen::Vector3d e = normalised_unmet(r);
  return e.cwiseProduct(e).dot(options_.priority);
}

ThrustAllocationResult ThrustAllocator::allocate_with_drag(const ThrustAllocationInput& input,
                                                           SignRegion region, bool hold) const {
  ThrustAllocationResult result = solve(input, region, hold);
  if (result.status == AllocationStatus::kInvalidInput ||
      options_.rudder_drag_compensation <= 0.0) {
    return result;
  }
  // Fixed point on the rudder drag (file comment): solve for τ_d − τ_drag(f) until the drag
  // predicted at the commands settles to half the tolerance of "met" (1e-6 of the force and
  // moment scales). Each pass scales the change by about C_D/C_L ≤ 0.3, so a few passes
  // suffice; 20 is a safe cap. Without rudder deflection the first solve already settles.
  constexpr int kMaxPasses = 20;
  const double tol_force = 1e-6 * options_.force_scale;
  const double tol_moment = 1e-6 * options_.moment_scale;
  ThrustAllocationInput corrected = input;
  Eigen::Vector3d drag = Eigen::Vector3d::Zero();   // the drag `result` was solved for
  Eigen::Vector3d predicted = rudder_drag(result);  // the drag at the commands of `result`
  int iterations = result.iterations;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    const bool settled = std::abs(predicted.x() - drag.x()) <= 0.5 * tol_force &&
                         std::abs(predicted.z() - drag.z()) <= 0.5 * tol_moment;
    if (settled) break;
    drag = predicted;
    corrected.tau_d_b = input.tau_d_b - drag;
    result = solve(corrected, region, hold);
    iterations += result.iterations;
    predicted = rudder_drag(result);
  }
  result.iterations = iterations;
  result.tau_rudder_drag_b = predicted;
  result.tau_achieved_b = configuration_.matrix() * result.forces + predicted;
  result.tau_unmet_b = input.tau_d_b - result.tau_achieved_b;
  result.status = AllocationStatus::kOk;
  result.message.clear();
  set_met_status(result);
  return result;
}

void ThrustAllocator::set_met_status(ThrustAllocationResult& r) const {
  // "Met": every component of τ_unmet within 1e-6 of its force or moment scale.
  // (Written as "not all within", so a NaN would count as not met.)
  if (!(normalised_unmet(r).array().abs() <= 1e-6).all()) {
    r.status = AllocationStatus::kSaturated;
    r.message = "demand not attainable within actuator limits; see tau_unmet_b";
  }
}

Eigen::Vector3d ThrustAllocator::normalised_unmet(const ThrustAllocationResult& r) const {
  return {r.tau_unmet_b.x() / options_.force_scale, r.tau_unmet_b.y() / options_.force_scale,
          r.tau_unmet_b.z() / options_.moment_scale};
}

Eigen::Vector3d ThrustAllocator::rudder_drag(const ThrustAllocationResult& r) const {
  // The drag the deflection adds in the propeller's slipstream at zero ship speed: at DP and
  // joystick speeds (< 1 m/s) the slipstream (3–6 m/s) dominates the inflow, and a prediction
  // that does not follow the ship's speed keeps a joystick step a step. The profile drag at
  // zero angle is left out: it is part of the hull's resistance as the surge steps see it.
  // The surge component of the rudder force is its drag; its moment is −y·D_x (2.37).
  const auto induced = [&](double angle, double thrust) {
    return rudder_.force(angle, {0.0, 0.0, thrust}).f_b.x() -
           rudder_.force(0.0, {0.0, 0.0, thrust}).f_b.x();
  };
  const double dx_port = induced(r.rudder_port, r.forces[0]);
  const double dx_stb = induced(r.rudder_stb, r.forces[1]);
  const ThrustConfigurationParams& p = configuration_.params();
  const double c = options_.rudder_drag_compensation;
  return c * Eigen::Vector3d(dx_port + dx_stb, 0.0,
                             -p.p_port_rudder_b.y() * dx_port - p.p_stb_rudder_b.y() * dx_stb);
}

namespace {

constexpr int kT1 = ThrustConfiguration::kThrustPort;
constexpr int kT2 = ThrustConfiguration::kThrustStb;
constexpr int kY1 = ThrustConfiguration::kRudderPort;
constexpr int kY2 = ThrustConfiguration::kRudderStb;
constexpr int kT3 = ThrustConfiguration::kTunnel;

int thrust_of(int rudder) { return rudder == kY1 ? kT1 : kT2; }

bool finite(const ThrustAllocationInput& input) {
  return input.tau_d_b.allFinite() && std::isfinite(input.surge_speed) && std::isfinite(input.dt) &&
         input.previous_forces.allFinite() &&
         !(input.hold_forces && !input.hold_forces->allFinite());
}

// The redistributed pseudo-inverse (file comment of thrust_allocation.hpp) on the scaled
// variables y, f_i = d_i·y_i: each variable is free in the least squares, fixed at a bound, or
// (a rudder) tied to its thrust on its cone, Y = σ(κ·T⁺ + c).
class Clipping {
 public:
  Clipping(const ThrustConfiguration::Matrix& B, const Vector5d& d, const RudderCone& cone)
      : B_(B), d_(d), cone_(cone) {
    role_.fill(Role::kFree);
  }

  // The forces of one weighted least-squares solve over the free variables: the minimum-norm
  // solution, or with `hold` (weight μ) the minimum-norm shift from the pull towards it.
  Vector5d solve(const Eigen::Vector3d& tau_d_b, const Eigen::Vector3d& qh,
                 const std::optional<Vector5d>& hold, double hold_weight) const;
  // A tie is only the cone for T ≥ 0; below, the cone is the constant c. Fixes the first tied
  // rudder whose thrust went astern at ±c; true if there was one.
  bool untie_astern(const Vector5d& f);
  // Fixes the free variable that violates its bound most (relative to its scale) at that
  // bound, or ties a rudder that is on its cone; false if no free variable violates a bound.
  bool fix_most_violated(const Vector5d& f, const Vector5d& lo, const Vector5d& hi,
                         const Vector5d& scale, double y_scale);
  // Projects f onto the bounds, thrusts first, then the rudder cones with those thrusts, and
  // marks what is not free or had to move.
  void project(Vector5d& f, const Vector5d& lo, const Vector5d& hi,
               std::array<bool, 5>& saturated) const;

 private:
  enum class Role { kFree, kFixed, kTied };

  const ThrustConfiguration::Matrix& B_;
  const Vector5d& d_;
  const RudderCone& cone_;
  std::array<Role, 5> role_{};
  Vector5d fixed_value_ = Vector5d::Zero();
  std::array<double, 5> tie_sign_{};  // σ for a tied rudder
};

Vector5d Clipping::solve(const Eigen::Vector3d& tau_d_b, const Eigen::Vector3d& qh,
                         const std::optional<Vector5d>& hold, double hold_weight) const {
  // M·y = rhs over the free variables (tied rudders folded into their thrust column).
  ThrustConfiguration::Matrix M = ThrustConfiguration::Matrix::Zero();
  Eigen::Vector3d rhs = tau_d_b;
  for (int j = 0; j < 5; ++j) {
    if (role_[j] == Role::kFree) M.col(j) = B_.col(j) * d_[j];
    if (role_[j] == Role::kFixed) rhs -= B_.col(j) * fixed_value_[j];
  }
  for (int j : {kY1, kY2}) {
    if (role_[j] != Role::kTied) continue;
    const int t = thrust_of(j);
    if (role_[t] == Role::kFixed) {
      rhs -= B_.col(j) * tie_sign_[j] * cone_.limit(fixed_value_[t]);
    } else {
      M.col(t) += B_.col(j) * tie_sign_[j] * cone_.kappa * d_[t];
      rhs -= B_.col(j) * tie_sign_[j] * cone_.c_N;
    }
  }
  const ThrustConfiguration::Matrix A = qh.asDiagonal() * M;
  const Eigen::Vector3d b = qh.cwiseProduct(rhs);
  const Eigen::CompleteOrthogonalDecomposition<ThrustConfiguration::Matrix> cod(A);
  // Minimum-norm least-squares solution; when holding, min ‖y‖² + μ‖y − y_h‖² is the
  // minimum-norm shift from c = y_h·μ/(1+μ) (file comment), on the free variables only.
  Vector5d c = Vector5d::Zero();
  if (hold) {
    const double mu = hold_weight;
    for (int j = 0; j < 5; ++j) {
      if (role_[j] == Role::kFree) c[j] = mu / (1.0 + mu) * (*hold)[j] / d_[j];
    }
  }
  const Vector5d y = c + cod.solve(b - A * c);

  Vector5d f;
  for (int j = 0; j < 5; ++j) {
    f[j] = role_[j] == Role::kFree ? d_[j] * y[j] : fixed_value_[j];
  }
  for (int j : {kY1, kY2}) {
    if (role_[j] == Role::kTied) {
      f[j] = tie_sign_[j] * cone_.limit(f[thrust_of(j)]);
    }
  }
  return f;
}

bool Clipping::untie_astern(const Vector5d& f) {
  for (int j : {kY1, kY2}) {
    if (role_[j] == Role::kTied && f[thrust_of(j)] < 0.0) {
      role_[j] = Role::kFixed;
      fixed_value_[j] = tie_sign_[j] * cone_.c_N;
      return true;
    }
  }
  return false;
}

bool Clipping::fix_most_violated(const Vector5d& f, const Vector5d& lo, const Vector5d& hi,
                                 const Vector5d& scale, double y_scale) {
  int worst = -1;
  double worst_violation = 1e-9;
  double worst_bound = 0.0;
  for (int j = 0; j < 5; ++j) {
    if (role_[j] != Role::kFree) continue;
    double l = lo[j];
    double h = hi[j];
    if (j == kY1 || j == kY2) std::tie(l, h) = cone_.bounds(f[thrust_of(j)], lo[j], hi[j]);
    const double violation = std::max(f[j] - h, l - f[j]) / scale[j];
    if (violation > worst_violation) {
      worst = j;
      worst_violation = violation;
      worst_bound = f[j] > h ? h : l;
    }
  }
  if (worst < 0) return false;
  const bool rudder = worst == kY1 || worst == kY2;
  const double cone = rudder ? cone_.limit(f[thrust_of(worst)]) : 0.0;
  if (rudder && std::abs(std::abs(worst_bound) - cone) <= 1e-12 * y_scale && cone > 0.0 &&
      role_[thrust_of(worst)] != Role::kFixed) {
    role_[worst] = Role::kTied;  // on its cone: keep it proportional to the thrust
    tie_sign_[worst] = worst_bound > 0.0 ? 1.0 : -1.0;
  } else {
    role_[worst] = Role::kFixed;
    fixed_value_[worst] = worst_bound;
  }
  return true;
}

void Clipping::project(Vector5d& f, const Vector5d& lo, const Vector5d& hi,
                       std::array<bool, 5>& saturated) const {
  for (int j : {kT1, kT2, kT3}) {
    const double c = std::clamp(f[j], lo[j], hi[j]);
    saturated[j] = role_[j] != Role::kFree || c != f[j];
    f[j] = c;
  }
  for (int j : {kY1, kY2}) {
    const auto [l, h] = cone_.bounds(f[thrust_of(j)], lo[j], hi[j]);
    const double c = std::clamp(f[j], std::min(l, h), std::max(l, h));
    saturated[j] = role_[j] != Role::kFree || c != f[j];
    f[j] = c;
  }
}

}  // namespace

RudderCone ThrustAllocator::rudder_cone(double surge_speed) const noexcept {
  // |Y| ≤ κ·T⁺ + c from the rudder model's linear lift (exact, see rudder.hpp).
  const RudderParams& rp = rudder_.params();
  const double lift_per_q =
      rp.area * rp.lift_slope * std::min({options_.max_rudder_angle, rp.stall_angle, rp.max_angle});
  return {rudder_.dynamic_pressure(0.0, 1.0) * lift_per_q,
          rudder_.dynamic_pressure(std::max(surge_speed, 0.0), 0.0) * lift_per_q};
}

ThrustAllocationResult ThrustAllocator::solve(const ThrustAllocationInput& input, SignRegion region,
                                              bool hold) const {
  ThrustAllocationResult result;
  if (!finite(input)) {
    result.status = AllocationStatus::kInvalidInput;
    result.message = "tau_d_b, surge_speed, dt, previous_forces and hold_forces must be finite";
    return result;
  }
  const double u = input.surge_speed;
  const RudderCone cone = rudder_cone(u);
  // Box bounds, tightened by the rate limits when a previous allocation is given, and the
  // sign region of the main propellers (file comment).
  const auto [lo, hi] =
      allocation_box(bounds(u), input.previous_forces, options_.rate_limits, input.dt, region);

  // Scaling: f_i = d_i·y_i with d_i = s_i/√w_i, so ‖y‖² = Σ w_i (f_i/s_i)².
  Vector5d scale;
  const double t_fwd = propeller_.max_thrust_forward();
  const double y_scale = cone.kappa * t_fwd + cone.c_N;
  scale[kT1] = scale[kT2] = t_fwd;
  scale[kY1] = scale[kY2] = y_scale;
  scale[kT3] = std::max(tunnel_.max_thrust_starboard(u), tunnel_.max_thrust_port(u));
  const Vector5d d = scale.cwiseQuotient(options_.weights.cwiseSqrt());
  const Eigen::Vector3d qh(std::sqrt(options_.priority[0]) / options_.force_scale,
                           std::sqrt(options_.priority[1]) / options_.force_scale,
                           std::sqrt(options_.priority[2]) / options_.moment_scale);

  const std::optional<Vector5d> held = hold ? input.hold_forces : std::nullopt;
  Clipping clipping(configuration_.matrix(), d, cone);
  Vector5d f = Vector5d::Zero();
  // Each pass changes one role (free → tied/fixed, tied → fixed), at most 5 + 2 changes.
  for (int iteration = 0; iteration < 10; ++iteration) {
    f = clipping.solve(input.tau_d_b, qh, held, options_.hold_weight);
    ++result.iterations;
    if (clipping.untie_astern(f)) continue;
    if (!clipping.fix_most_violated(f, lo, hi, scale, y_scale)) break;
  }
  clipping.project(f, lo, hi, result.saturated);

  result.forces = f;
  result.tau_achieved_b = configuration_.matrix() * f;
  result.tau_unmet_b = input.tau_d_b - result.tau_achieved_b;
  set_met_status(result);
  set_commands(result, u);
  return result;
}

void ThrustAllocator::set_commands(ThrustAllocationResult& r, double surge_speed) const {
  const Vector5d& f = r.forces;
  const double u = surge_speed;
  r.n_port = propeller_.shaft_speed_for_thrust(f[kT1]);
  r.n_stb = propeller_.shaft_speed_for_thrust(f[kT2]);
  const double a_max = std::min(options_.max_rudder_angle, rudder_.params().max_angle);
  r.rudder_port = detail::clamp_abs(rudder_.angle_for_side_force(f[kY1], u, f[kT1]), a_max);
  r.rudder_stb = detail::clamp_abs(rudder_.angle_for_side_force(f[kY2], u, f[kT2]), a_max);
  r.tunnel_thrust = f[kT3];
  r.n_tunnel = tunnel_.shaft_speed_for_thrust(f[kT3], u);
}

}  // namespace dynpos::model
