#include "dynpos/capability/thrust_region.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "dynpos/core/error.hpp"

namespace dynpos::capability {
namespace {

using Vector5d = Eigen::Matrix<double, 5, 1>;
using Row5d = Eigen::Matrix<double, 1, 5>;
constexpr int kT[2] = {model::ThrustConfiguration::kThrustPort,
                       model::ThrustConfiguration::kThrustStb};
constexpr int kY[2] = {model::ThrustConfiguration::kRudderPort,
                       model::ThrustConfiguration::kRudderStb};
// A limit within this fraction of the largest bound counts as reached: near the edge of the
// attainable set (a bisection ends within its tolerance of it) the polygon of allocations is
// small but not a point, and its vertices sit that close to the limits that close it.
constexpr double kLimitBand = 2e-3;

// One limit a·f ≤ b on f, and the actuator it bounds; a sign limit (T ≥ 0 or T ≤ 0 of the
// region) is not a saturation.
struct Limit {
  Row5d a;
  double b;
  int actuator;
  bool saturates = true;
};

// The box, and each rudder's cone within the sign region (s₁, s₂) of the main thrusts: ahead
// (s = +1) |Y| ≤ κT + c with T ≥ 0, astern (s = −1) |Y| ≤ c with T ≤ 0.
std::vector<Limit> limits_in_region(const ThrustLimits& l, std::array<int, 2> region) {
  std::vector<Limit> out;
  for (int k = 0; k < 5; ++k) {
    out.push_back({Row5d::Unit(k), l.hi_N(k), k});
    out.push_back({-Row5d::Unit(k), -l.lo_N(k), k});
  }
  for (int i = 0; i < 2; ++i) {
    const double kappa = region[i] > 0 ? l.cone.kappa : 0.0;
    out.push_back({-region[i] * Row5d::Unit(kT[i]), 0.0, kT[i], false});
    for (int sign : {1, -1}) {
      out.push_back({sign * Row5d::Unit(kY[i]) - kappa * Row5d::Unit(kT[i]), l.cone.c_N, kY[i]});
    }
  }
  return out;
}

}  // namespace

ThrustLimits thrust_limits(const model::ThrustAllocator& allocator, double surge_speed_mps,
                           bool propeller_inflow) {
  ThrustLimits l;
  l.B = allocator.configuration().matrix();
  const auto box = allocator.bounds(surge_speed_mps);
  l.lo_N = box[0];
  l.hi_N = box[1];
  l.cone = allocator.rudder_cone(surge_speed_mps);
  const Vector5d& capacity = allocator.options().capacity;
  if (propeller_inflow) {
    const model::Thruster& p = allocator.propeller();
    const double n_max = p.params().max_shaft_speed;
    for (const int k : kT) {
      l.hi_N(k) = capacity(k) * std::max(p.thrust(n_max, surge_speed_mps), 0.0);
      l.lo_N(k) = capacity(k) * std::min(p.thrust(-n_max, surge_speed_mps), 0.0);
    }
  }
  for (int k = 0; k < 5; ++k) l.failed[static_cast<std::size_t>(k)] = capacity(k) == 0.0;
  return l;
}

std::optional<Attainment> attain(const ThrustLimits& limits, const Eigen::Vector3d& tau_b) {
  // f = f₀ + N·z: the least-norm solution and the null space of B (rank 3 for any layout
  // that passes ThrustConfigurationParams::validate()).
  const Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 3, 5>> cod(limits.B);
  const Vector5d f0 = cod.solve(tau_b);
  const Eigen::Matrix<double, 5, 5> P =
      Eigen::Matrix<double, 5, 5>::Identity() - cod.pseudoInverse() * limits.B;
  const Eigen::JacobiSVD<Eigen::Matrix<double, 5, 5>> svd(P, Eigen::ComputeFullU);
  const Eigen::Matrix<double, 5, 2> N = svd.matrixU().leftCols<2>();
  const double scale = std::max(
      {limits.hi_N.cwiseAbs().maxCoeff(), limits.lo_N.cwiseAbs().maxCoeff(), limits.cone.c_N, 1.0});
  const double tol = 1e-9 * scale;
  for (const std::array<int, 2> region :
       {std::array{1, 1}, std::array{1, -1}, std::array{-1, 1}, std::array{-1, -1}}) {
    const std::vector<Limit> set = limits_in_region(limits, region);
    // Each limit as a half-plane g·z ≤ h in z.
    std::vector<Eigen::RowVector2d> g(set.size());
    std::vector<double> h(set.size());
    for (std::size_t k = 0; k < set.size(); ++k) {
      g[k] = set[k].a * N;
      h[k] = set[k].b - set[k].a * f0;
    }
    for (std::size_t i = 0; i < set.size(); ++i) {
      for (std::size_t j = i + 1; j < set.size(); ++j) {
        Eigen::Matrix2d A;
        A << g[i], g[j];
        if (std::abs(A.determinant()) < 1e-12 * (g[i].norm() * g[j].norm() + 1e-300)) continue;
        const Eigen::Vector2d z = A.partialPivLu().solve(Eigen::Vector2d(h[i], h[j]));
        bool inside = true;
        for (std::size_t k = 0; k < set.size() && inside; ++k) inside = g[k] * z <= h[k] + tol;
        if (!inside) continue;
        Attainment a;
        a.forces_N = f0 + N * z;
        for (std::size_t k = 0; k < set.size(); ++k) {
          const auto actuator = static_cast<std::size_t>(set[k].actuator);
          // A force held at a zero bound (a lost actuator, a rudder without slipstream) is
          // not a saturation.
          const double force = (f0 + N * z)(set[k].actuator);
          if (set[k].saturates && !limits.failed[actuator] && std::abs(force) > 1e-6 * scale &&
              h[k] - g[k] * z <= kLimitBand * scale) {
            a.at_limit[actuator] = true;
          }
        }
        return a;
      }
    }
  }
  return std::nullopt;
}

}  // namespace dynpos::capability
