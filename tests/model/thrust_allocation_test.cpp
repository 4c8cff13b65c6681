#include "dynpos/model/thrust_allocation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "dynpos/core/error.hpp"

namespace dynpos::model {
namespace {

using Vector5d = Eigen::Matrix<double, 5, 1>;
constexpr int kT1 = ThrustConfiguration::kThrustPort;
constexpr int kT2 = ThrustConfiguration::kThrustStb;
constexpr int kY1 = ThrustConfiguration::kRudderPort;
constexpr int kY2 = ThrustConfiguration::kRudderStb;
constexpr int kT3 = ThrustConfiguration::kTunnel;

ThrustAllocationInput demand(double x, double y, double n, double u = 0.0) {
  ThrustAllocationInput in;
  in.tau_d_b = {x, y, n};
  in.surge_speed = u;
  return in;
}

// Checks every bound of the result: box, rudder cone (|Y| ≤ κT⁺ + c from the rudder model's
// own maximum side force) and finiteness. Slack 1e-6 N covers rounding of ~1e5 N values.
void expect_within_limits(const ThrustAllocator& alloc, const ThrustAllocationResult& r, double u) {
  const Rudder rudder;
  const auto [lo, hi] = alloc.bounds(u);
  ASSERT_TRUE(r.forces.allFinite());
  for (int j : {kT1, kT2, kT3}) {
    EXPECT_GE(r.forces[j], lo[j] - 1e-6) << j;
    EXPECT_LE(r.forces[j], hi[j] + 1e-6) << j;
  }
  EXPECT_LE(std::abs(r.forces[kY1]), rudder.max_side_force(u, r.forces[kT1]) + 1e-6);
  EXPECT_LE(std::abs(r.forces[kY2]), rudder.max_side_force(u, r.forces[kT2]) + 1e-6);
  EXPECT_LE(std::abs(r.rudder_port), alloc.options().max_rudder_angle + 1e-12);
  EXPECT_LE(std::abs(r.rudder_stb), alloc.options().max_rudder_angle + 1e-12);
}

// The priority-weighted squared unmet demand Σ Q_i (τ_unmet,i / scale_i)², as the allocator
// compares saturated results.
double weighted_unmet(const ThrustAllocator& alloc, const ThrustAllocationResult& r) {
  const Eigen::Vector3d e(r.tau_unmet_b.x() / alloc.options().force_scale,
                          r.tau_unmet_b.y() / alloc.options().force_scale,
                          r.tau_unmet_b.z() / alloc.options().moment_scale);
  return e.cwiseProduct(e).dot(alloc.options().priority);
}

// The linear allocation alone (rudder drag not compensated): τ_achieved = B·f exactly.
ThrustAllocator linear_allocator() {
  ThrustAllocationOptions o;
  o.rudder_drag_compensation = 0.0;
  return ThrustAllocator(Thruster{}, Rudder{}, TunnelThruster{}, ThrustConfiguration{}, o);
}

TEST(ThrustAllocator, FeasibleDemandIsMetExactly) {
  const ThrustAllocator alloc = linear_allocator();
  for (const ThrustAllocationInput& in : {demand(20e3, 5e3, 50e3), demand(-10e3, -3e3, -20e3),
                                          demand(30e3, 0, 0, 2.0), demand(5e3, 8e3, 60e3, 1.0)}) {
    const ThrustAllocationResult r = alloc.allocate(in);
    SCOPED_TRACE(in.tau_d_b.transpose());
    EXPECT_EQ(r.status, AllocationStatus::kOk) << r.message;
    // Met up to the rounding of a 3×5 complete orthogonal decomposition on O(1) normalised
    // numbers (≈ 1e-15 relative) times the 1e5 N scale: 1e-6 N and 1e-5 N·m are ample.
    EXPECT_NEAR(r.tau_unmet_b.x(), 0.0, 1e-6);
    EXPECT_NEAR(r.tau_unmet_b.y(), 0.0, 1e-6);
    EXPECT_NEAR(r.tau_unmet_b.z(), 0.0, 1e-5);
    EXPECT_TRUE(r.tau_achieved_b.isApprox(alloc.configuration().matrix() * r.forces));
    expect_within_limits(alloc, r, in.surge_speed);
  }
}

TEST(ThrustAllocator, RudderDragIsCompensated) {
  const ThrustAllocator alloc;  // default: rudder_drag_compensation = 1
  const ThrustAllocator linear = linear_allocator();
  const Rudder rudder;
  const double force_tol = 1e-6 * alloc.options().force_scale;  // the allocation's "met"
  const double moment_tol = 1e-6 * alloc.options().moment_scale;
  for (const ThrustAllocationInput& in :
       {demand(0.0, 15e3, 0.0), demand(5e3, 8e3, 60e3), demand(20e3, -6e3, -40e3, 1.0)}) {
    SCOPED_TRACE(in.tau_d_b.transpose());
    const ThrustAllocationResult r = alloc.allocate(in);
    ASSERT_EQ(r.status, AllocationStatus::kOk) << r.message;
    // The prediction is the rudder model's added drag in the slipstream at zero speed.
    const auto added = [&](double angle, double thrust) {
      return rudder.force(angle, {0.0, 0.0, thrust}).f_b.x() -
             rudder.force(0.0, {0.0, 0.0, thrust}).f_b.x();
    };
    const double dx = added(r.rudder_port, r.forces[kT1]) + added(r.rudder_stb, r.forces[kT2]);
    EXPECT_NEAR(r.tau_rudder_drag_b.x(), dx, 1e-9 * std::max(1.0, std::abs(dx)));
    // Deflected rudders: drag astern, far above the 0.1 N tolerance (so the checks below bite).
    EXPECT_LT(r.tau_rudder_drag_b.x(), -50.0);
    EXPECT_EQ(r.tau_rudder_drag_b.y(), 0.0);
    // Forces plus drag meet the demand within the allocation's tolerance.
    const Eigen::Vector3d total = alloc.configuration().matrix() * r.forces + r.tau_rudder_drag_b;
    EXPECT_TRUE(total.isApprox(r.tau_achieved_b, 1e-12));
    EXPECT_LE(std::abs(r.tau_unmet_b.x()), force_tol);
    EXPECT_LE(std::abs(r.tau_unmet_b.y()), force_tol);
    EXPECT_LE(std::abs(r.tau_unmet_b.z()), moment_tol);
    // Without compensation the same demand leaves the drag as an unmet surge force.
    const ThrustAllocationResult r0 = linear.allocate(in);
    const Eigen::Vector3d with_drag =
        alloc.configuration().matrix() * r0.forces +
        Eigen::Vector3d(
            added(r0.rudder_port, r0.forces[kT1]) + added(r0.rudder_stb, r0.forces[kT2]), 0.0, 0.0);
    EXPECT_GT(std::abs(in.tau_d_b.x() - with_drag.x()), 50.0);
  }
  // Rudders amidships add no drag: a pure surge demand is unchanged by the compensation.
  const ThrustAllocationResult ahead = alloc.allocate(demand(30e3, 0.0, 0.0));
  EXPECT_EQ(ahead.tau_rudder_drag_b, Eigen::Vector3d::Zero());
  EXPECT_EQ(ahead.forces, linear.allocate(demand(30e3, 0.0, 0.0)).forces);
}

TEST(ThrustAllocator, InfeasibleDemandReportsTheUnmetPart) {
  const ThrustAllocator alloc;
  const ThrustAllocationInput in = demand(500e3, 0.0, 0.0);
  const ThrustAllocationResult r = alloc.allocate(in);
  EXPECT_EQ(r.status, AllocationStatus::kSaturated);
  EXPECT_FALSE(r.message.empty());
  const Eigen::Vector3d unmet = in.tau_d_b - alloc.configuration().matrix() * r.forces;
  EXPECT_TRUE(r.tau_unmet_b.isApprox(unmet, 1e-12));
  EXPECT_GT(r.tau_unmet_b.x(), 300e3);
  // Both propellers at full ahead thrust and flagged.
  const Thruster propeller;
  EXPECT_NEAR(r.forces[kT1], propeller.max_thrust_forward(), 1e-6);
  EXPECT_NEAR(r.forces[kT2], propeller.max_thrust_forward(), 1e-6);
  EXPECT_TRUE(r.saturated[kT1]);
  EXPECT_TRUE(r.saturated[kT2]);
  EXPECT_NEAR(r.n_port, propeller.params().max_shaft_speed, 1e-9);
  expect_within_limits(alloc, r, 0.0);
}

TEST(ThrustAllocator, SaturationsRespectedOverADemandGrid) {
  const ThrustAllocator alloc;
  for (double u : {0.0, 1.5, 3.0}) {
    for (double x : {-200e3, -20e3, 0.0, 40e3, 200e3}) {
      for (double y : {-100e3, -10e3, 0.0, 10e3, 100e3}) {
        for (double n : {-1e6, -100e3, 0.0, 100e3, 1e6}) {
          SCOPED_TRACE(testing::Message() << u << " " << x << " " << y << " " << n);
          expect_within_limits(alloc, alloc.allocate(demand(x, y, n, u)), u);
        }
      }
    }
  }
}

TEST(ThrustAllocator, PureYawUsesDifferentialThrustAndTunnel) {
  const ThrustAllocator alloc;
  const ThrustAllocationResult r = alloc.allocate(demand(0.0, 0.0, 100e3));
  EXPECT_EQ(r.status, AllocationStatus::kOk) << r.message;
  // N > 0 (bow to starboard): port propeller ahead, starboard astern, tunnel to starboard.
  EXPECT_GT(r.forces[kT1], 0.0);
  EXPECT_LT(r.forces[kT2], 0.0);
  EXPECT_GT(r.forces[kT3], 0.0);
  EXPECT_GT(r.n_port, 0.0);
  EXPECT_LT(r.n_stb, 0.0);
  EXPECT_GT(r.n_tunnel, 0.0);
}

TEST(ThrustAllocator, PureSwayUsesTunnelAndRudders) {
  const ThrustAllocator alloc;
  const ThrustAllocationResult r = alloc.allocate(demand(0.0, 10e3, 0.0));
  EXPECT_EQ(r.status, AllocationStatus::kOk) << r.message;
  EXPECT_GT(r.forces[kT3], 0.0);
  // The tunnel's bow moment is balanced at the stern: a rudder pushes the stern to starboard
  // (Y > 0 at x < 0), which needs ahead thrust on that propeller.
  const double rudder_y = r.forces[kY1] + r.forces[kY2];
  EXPECT_GT(rudder_y, 1e3);
  const int used = r.forces[kY1] > r.forces[kY2] ? kT1 : kT2;
  EXPECT_GT(r.forces[used], 0.0);
  // A starboard side force at the stern needs α < 0 on the rudder that gives it.
  EXPECT_LT(used == kT1 ? r.rudder_port : r.rudder_stb, 0.0);
  expect_within_limits(alloc, r, 0.0);
}

TEST(ThrustAllocator, CommandsReproduceTheAllocatedForces) {
  const ThrustAllocator alloc;
  const double u = 1.5;
  const ThrustAllocationResult r = alloc.allocate(demand(20e3, 6e3, 40e3, u));
  ASSERT_EQ(r.status, AllocationStatus::kOk) << r.message;
  const Thruster propeller;
  const Rudder rudder;
  const TunnelThruster tunnel;
  // Inverse maps are exact up to sqrt/square rounding: 1e-6 N.
  EXPECT_NEAR(propeller.thrust(r.n_port), r.forces[kT1], 1e-6);
  EXPECT_NEAR(propeller.thrust(r.n_stb), r.forces[kT2], 1e-6);
  EXPECT_NEAR(tunnel.thrust(r.n_tunnel, u), r.forces[kT3], 1e-6);
  // In straight flow at speed u with the allocated thrust, the rudder model gives the
  // allocated side force (linear region, v = 0).
  EXPECT_NEAR(rudder.force(r.rudder_port, {u, 0.0, r.forces[kT1]}).f_b.y(), r.forces[kY1], 1e-6);
  EXPECT_NEAR(rudder.force(r.rudder_stb, {u, 0.0, r.forces[kT2]}).f_b.y(), r.forces[kY2], 1e-6);
}

TEST(ThrustAllocator, RateLimitsBoundTheChange) {
  const ThrustAllocator alloc;
  ThrustAllocationInput in = demand(100e3, 20e3, 200e3);
  in.previous_forces = Vector5d::Zero();
  in.dt = 1.0;
  const ThrustAllocationResult r = alloc.allocate(in);
  const Vector5d rate = alloc.options().rate_limits;
  for (int j = 0; j < 5; ++j) {
    EXPECT_LE(std::abs(r.forces[j]), rate[j] * 1.0 + 1e-6) << j;  // rounding slack only
  }
  EXPECT_EQ(r.status, AllocationStatus::kSaturated);
  EXPECT_TRUE(r.tau_unmet_b.isApprox(in.tau_d_b - r.tau_achieved_b));
}

// Linear allocator with the given hold weight μ.
ThrustAllocator holding_allocator(double mu) {
  ThrustAllocationOptions o;
  o.rudder_drag_compensation = 0.0;
  o.hold_weight = mu;
  return ThrustAllocator(Thruster{}, Rudder{}, TunnelThruster{}, ThrustConfiguration{}, o);
}

TEST(ThrustAllocator, HoldingMovesTheSplitWithinTheNullSpace) {
  // When the held split f_h itself meets τ_d and no bound is active, the minimiser of
  // ‖x‖² + μ‖x − x_h‖² on {B f = τ_d} is (μ f_h + f_plain)/(1 + μ) exactly: write x = x_h + z
  // with z in the null space; the plain split is x_h − P x_h, the held one x_h − P x_h/(1+μ).
  // The identity is linear in f, so it holds whatever the allocator's internal scaling.
  for (double mu : {0.5, 4.0, 20.0}) {
    const ThrustAllocator alloc = holding_allocator(mu);
    Vector5d f_h;
    f_h << 30e3, 18e3, 2e3, -1.5e3, 3e3;  // both propellers ahead: rudder cones open
    ThrustAllocationInput in;
    in.tau_d_b = alloc.configuration().matrix() * f_h;
    const ThrustAllocationResult plain = alloc.allocate(in);
    ASSERT_EQ(plain.status, AllocationStatus::kOk);
    ASSERT_TRUE(
        std::none_of(plain.saturated.begin(), plain.saturated.end(), [](bool b) { return b; }));
    ASSERT_GT((plain.forces - f_h).norm(), 1e3);  // f_h is not the minimum-norm split
    in.hold_forces = f_h;
    const ThrustAllocationResult held = alloc.allocate(in);
    SCOPED_TRACE(mu);
    EXPECT_EQ(held.status, AllocationStatus::kOk) << held.message;
    // Same demand met (rounding of a 3×5 solve on 1e5 N scales, as above).
    EXPECT_NEAR(held.tau_unmet_b.x(), 0.0, 1e-6);
    EXPECT_NEAR(held.tau_unmet_b.y(), 0.0, 1e-6);
    EXPECT_NEAR(held.tau_unmet_b.z(), 0.0, 1e-5);
    const Vector5d expected = (mu * f_h + plain.forces) / (1.0 + mu);
    for (int j = 0; j < 5; ++j) EXPECT_NEAR(held.forces[j], expected[j], 1e-6) << j;
    expect_within_limits(alloc, held, 0.0);
  }
}

TEST(ThrustAllocator, HoldingNeverCostsDemandOrMovesMoreThanPlain) {
  const ThrustAllocator alloc = holding_allocator(4.0);
  const ThrustAllocator no_hold = holding_allocator(0.0);
  // Over a grid of demands (some beyond the thrusters' limits) and held splits (some far
  // outside the bounds): the result meets the demand whenever the plain allocation does, leaves
  // no more unmet when it does not, and, whenever the plain split meets the demand at least as
  // well as the result, lies at least as near the held split (weighted by 1/bound² as the
  // allocator measures it). A result that meets a demand the plain split misses may lie
  // farther away.
  const auto [lo, hi] = alloc.bounds(0.0);
  const auto distance = [&](const Vector5d& f, const Vector5d& h) {
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) {
      const double s = std::max(std::abs(lo[i]), std::abs(hi[i]));
      sum += alloc.options().weights[i] * std::pow((f[i] - h[i]) / s, 2);
    }
    return sum;
  };
  const auto unmet = [&](const ThrustAllocationResult& r) { return weighted_unmet(alloc, r); };
  int held_differs = 0, saturated = 0;
  for (double x : {-40e3, 0.0, 60e3, -110e3}) {
    for (double n : {-150e3, -20e3, 0.0, 90e3}) {
      for (double t1 : {-50e3, 0.0, 40e3, 1e6}) {
        Vector5d h;
        h << t1, -t1 / 2, 0.0, 0.0, 5e3;
        ThrustAllocationInput in = demand(x, 5e3, n);
        const ThrustAllocationResult plain = alloc.allocate(in);
        in.hold_forces = h;
        const ThrustAllocationResult r = alloc.allocate(in);
        SCOPED_TRACE(testing::Message() << x << " " << n << " " << t1);
        if (plain.status == AllocationStatus::kOk) {
          EXPECT_EQ(r.status, AllocationStatus::kOk);
        } else {
          ++saturated;
          EXPECT_LE(unmet(r), unmet(plain)) << "saturated: the held split leaves more unmet";
        }
        const bool plain_as_good = plain.status == AllocationStatus::kOk ||
                                   (r.status != AllocationStatus::kOk && unmet(plain) <= unmet(r));
        if (plain_as_good) {
          EXPECT_LE(distance(r.forces, h), distance(plain.forces, h) + 1e-12);
        }
        expect_within_limits(alloc, r, 0.0);
        // μ = 0 ignores the held split.
        EXPECT_EQ(no_hold.allocate(in).forces, plain.forces);
        if ((r.forces - plain.forces).norm() > 1.0) ++held_differs;
      }
    }
  }
  EXPECT_GT(held_differs, 10);  // the hold acts on a good part of the grid
  EXPECT_GT(saturated, 5);      // and the grid reaches past the thrusters' limits
}

TEST(ThrustAllocator, HoldingKeepsTheBranchWhenTheDemandWavers) {
  // Astern and to port at rest, τ_d = (−10 kN, −10 kN, N): the plain allocation changes its
  // active set near N ≈ 4.75 kN·m, and a jump of ≈ 41 kN in one force separates two splits
  // that both meet the demand (found by a sweep of N). A demand wavering across that point,
  // as the DP loop's does in waves, makes the plain split swap at each crossing — faster than
  // the propellers follow (dead time 1.3 s). Holding the last split must keep one branch.
  const ThrustAllocator alloc(Thruster{}, Rudder{}, TunnelThruster{}, ThrustConfiguration{}, {});
  double plain_max_step = 0.0, held_max_step = 0.0;
  Vector5d plain_prev = Vector5d::Zero(), held_prev = Vector5d::Zero();
  for (int k = 0; k < 200; ++k) {
    const double n = 4.75e3 + 3e3 * std::sin(0.3 * k) + 1e3 * std::sin(1.7 * k);
    ThrustAllocationInput in = demand(-10e3, -10e3, n);
    const ThrustAllocationResult plain = alloc.allocate(in);
    ASSERT_EQ(plain.status, AllocationStatus::kOk) << k;
    in.hold_forces = held_prev;
    const ThrustAllocationResult held = alloc.allocate(in);
    ASSERT_EQ(held.status, AllocationStatus::kOk) << k;
    if (k > 0) {
      plain_max_step = std::max(plain_max_step, (plain.forces - plain_prev).cwiseAbs().maxCoeff());
      held_max_step = std::max(held_max_step, (held.forces - held_prev).cwiseAbs().maxCoeff());
    }
    plain_prev = plain.forces;
    held_prev = held.forces;
  }
  std::printf("largest change of one force between allocations: plain %.1f kN, held %.1f kN\n",
              plain_max_step / 1e3, held_max_step / 1e3);
  // The demand itself moves by at most 1.2 kN·m per step, a few kN of force; a branch swap
  // moves tens of kN.
  EXPECT_GT(plain_max_step, 30e3);
  EXPECT_LT(held_max_step, 10e3);
}

TEST(ThrustAllocator, HoldingFindsTheBranchTheClippingMisses) {
  // Weather from astern, surging ahead at 0.8 m/s in the waves: τ_d = (−50 kN, −2 kN,
  // 120 kN·m), as the DP loop demands in pure DP at 180° to the weather. The propellers can
  // give it with port ≈ 8 kN and starboard ≈ 42 kN astern, but the iterative clipping, which
  // fixes one bound at a time, lands on port full astern with starboard ahead and its rudder,
  // which cannot meet the yaw moment (found by a sweep of u, X and N). Stationkeeping, the
  // allocation also solves within each sign region of the two propellers (where the rudder
  // cones are convex) and must find the branch that meets the demand, even with the missed
  // branch as the held split.
  const ThrustAllocator alloc(Thruster{}, Rudder{}, TunnelThruster{}, ThrustConfiguration{}, {});
  ThrustAllocationInput in = demand(-50e3, -2e3, 120e3, 0.8);
  const auto report = [&](const char* label, const ThrustAllocationResult& r) {
    std::printf("%s: status %d, forces (%.1f, %.1f, %.1f, %.1f, %.1f) kN, unmet %.2e\n", label,
                static_cast<int>(r.status), r.forces[0] / 1e3, r.forces[1] / 1e3, r.forces[2] / 1e3,
                r.forces[3] / 1e3, r.forces[4] / 1e3, weighted_unmet(alloc, r));
  };
  const ThrustAllocationResult plain = alloc.allocate(in);
  report("plain", plain);
  ASSERT_EQ(plain.status, AllocationStatus::kSaturated);  // the case this test is about
  for (const Vector5d& h : {plain.forces, Vector5d(Vector5d::Zero())}) {
    in.hold_forces = h;
    const ThrustAllocationResult held = alloc.allocate(in);
    report("held", held);
    EXPECT_EQ(held.status, AllocationStatus::kOk);
    expect_within_limits(alloc, held, 0.8);
    EXPECT_LE(held.forces[1], -40e3);  // starboard astern carries the demand
  }
}

TEST(ThrustAllocator, IsDeterministic) {
  const ThrustAllocator alloc;
  const ThrustAllocationInput in = demand(33e3, -7e3, 81e3, 0.7);
  const ThrustAllocationResult a = alloc.allocate(in);
  const ThrustAllocationResult b = alloc.allocate(in);
  EXPECT_EQ(a.forces, b.forces);  // bit-identical
  EXPECT_EQ(a.rudder_port, b.rudder_port);
  EXPECT_EQ(a.n_tunnel, b.n_tunnel);
}

TEST(ThrustAllocator, ZeroDemandGivesZeroAndNoNaN) {
  const ThrustAllocator alloc;
  const ThrustAllocationResult r = alloc.allocate(demand(0.0, 0.0, 0.0));
  EXPECT_EQ(r.status, AllocationStatus::kOk);
  EXPECT_EQ(r.forces, Vector5d::Zero());
  EXPECT_EQ(r.n_port, 0.0);
  EXPECT_EQ(r.n_stb, 0.0);
  EXPECT_EQ(r.rudder_port, 0.0);
  EXPECT_EQ(r.rudder_stb, 0.0);
  EXPECT_EQ(r.n_tunnel, 0.0);
}

TEST(ThrustAllocator, InvalidInputIsReportedNotThrown) {
  const ThrustAllocator alloc;
  const ThrustAllocationResult r =
      alloc.allocate(demand(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0));
  EXPECT_EQ(r.status, AllocationStatus::kInvalidInput);
  EXPECT_EQ(r.forces, Vector5d::Zero());
  ThrustAllocationInput held = demand(1e3, 0.0, 0.0);
  held.hold_forces = Vector5d::Constant(std::numeric_limits<double>::infinity());
  EXPECT_EQ(alloc.allocate(held).status, AllocationStatus::kInvalidInput);
  ThrustAllocationOptions bad;
  bad.weights[2] = 0.0;
  EXPECT_THROW(ThrustAllocator(Thruster{}, Rudder{}, TunnelThruster{}, ThrustConfiguration{}, bad),
               core::InputError);
  ThrustAllocationOptions negative_hold;
  negative_hold.hold_weight = -1.0;
  EXPECT_THROW(
      ThrustAllocator(Thruster{}, Rudder{}, TunnelThruster{}, ThrustConfiguration{}, negative_hold),
      core::InputError);
}

}  // namespace
}  // namespace dynpos::model
