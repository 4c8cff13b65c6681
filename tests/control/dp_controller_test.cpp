#include "dynpos/control/dp_controller.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "dynpos/core/rotation.hpp"

namespace dynpos::control {
namespace {

// The design model (5.32)–(5.34) with the controller (5.38) and the bias estimate (5.36)
// integrated together: z = (η, ν, b̂) ∈ ℝ⁹, classic RK4.
struct ClosedLoop {
  DpController controller;
  Eigen::Vector3d bias_n;  // true constant bias b (NED)
  DpReference ref;

  Eigen::Matrix<double, 9, 1> f(const Eigen::Matrix<double, 9, 1>& z) const {
    const Eigen::Vector3d eta = z.segment<3>(0), nu = z.segment<3>(3), b_hat = z.segment<3>(6);
    const DpCommand c = controller.control(eta, nu, ref, b_hat);
    const DpControllerParams& p = controller.params();
    Eigen::Matrix<double, 9, 1> dz;
    dz.segment<3>(0) = core::R_yaw(eta.z()) * nu;
    dz.segment<3>(3) =
        p.M.inverse() * (-p.D * nu + core::R_yaw(eta.z()).transpose() * bias_n + c.tau_b);
    dz.segment<3>(6) = controller.bias_rate(eta.z(), c.x2);
    return dz;
  }
  void step(Eigen::Matrix<double, 9, 1>& z, double h) const {
    const auto k1 = f(z);
    const auto k2 = f(z + 0.5 * h * k1);
    const auto k3 = f(z + 0.5 * h * k2);
    const auto k4 = f(z + h * k3);
    z += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
};

TEST(DpController, IntegralActionRemovesAConstantBias) {
  ClosedLoop loop{DpController{}, Eigen::Vector3d(2.0e4, -1.0e4, 1.0e5), {}};
  loop.ref.eta_d = Eigen::Vector3d(10.0, -5.0, 0.5);
  Eigen::Matrix<double, 9, 1> z = Eigen::Matrix<double, 9, 1>::Zero();
  // 4000 s ≫ the slowest closed-loop time constant (≈ 300 s, the yaw bias mode with the default
  // gains), so the initial bias error has decayed by ≈ e^−13.
  for (int k = 0; k < 40000; ++k) loop.step(z, 0.1);
  // Converged: position to 1 cm, heading to 0.01°, and b̂ equals the true bias.
  EXPECT_NEAR(z[0], 10.0, 0.01);
  EXPECT_NEAR(z[1], -5.0, 0.01);
  EXPECT_NEAR(z[2], 0.5, 2e-4);
  EXPECT_NEAR(z[6], 2.0e4, 20.0);  // 0.1 % of the bias
  EXPECT_NEAR(z[7], -1.0e4, 10.0);
  EXPECT_NEAR(z[8], 1.0e5, 100.0);
}

TEST(DpController, LyapunovFunctionNeverIncreases) {
  ClosedLoop loop{DpController{}, Eigen::Vector3d(1.5e4, 5.0e3, -4.0e4), {}};
  loop.ref.eta_d = Eigen::Vector3d(0.0, 0.0, 0.0);
  Eigen::Matrix<double, 9, 1> z;
  z << 8.0, -6.0, 0.7, 0.3, -0.2, 0.01, 0.0, 0.0, 0.0;
  auto v = [&](const Eigen::Matrix<double, 9, 1>& s) {
    const DpCommand c =
        loop.controller.control(s.segment<3>(0), s.segment<3>(3), loop.ref, s.segment<3>(6));
    return loop.controller.lyapunov(c.x1, c.x2, loop.bias_n - s.segment<3>(6));
  };
  double previous = v(z);
  for (int k = 0; k < 5000; ++k) {
    loop.step(z, 0.05);
    const double now = v(z);
    // V̇ = −x₁ᵀK_p x₁ − x₂ᵀK_d x₂ ≤ 0 (5.48); RK4 at h = 0.05 s adds ≲ 1e-9 relative error.
    EXPECT_LE(now, previous * (1.0 + 1e-9) + 1e-12) << "step " << k;
    previous = now;
  }
}

TEST(DpController, HeadingErrorTakesTheShortWay) {
  const DpController c;
  DpReference ref;
  ref.eta_d = Eigen::Vector3d(0, 0, -3.1);
  const DpCommand cmd =
      c.control(Eigen::Vector3d(0, 0, 3.1), Eigen::Vector3d::Zero(), ref, Eigen::Vector3d::Zero());
  // ψ − ψ_d = 6.2 rad wraps to −0.083 rad: a small turn to starboard, not a 355° one.
  EXPECT_NEAR(cmd.x1.z(), 6.2 - 2 * M_PI, 1e-12);
  EXPECT_GT(cmd.tau_b.z(), 0.0);
}

TEST(DpController, AntiWindupBoundsTheBiasEstimate) {
  const DpController c;
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int k = 0; k < 100000; ++k) b = c.advance_bias(b, 0.0, Eigen::Vector3d(1, -1, 1), 0.1);
  EXPECT_EQ(b, Eigen::Vector3d(6.0e4, -4.0e4, 6.0e5));
}

TEST(DpControllerParams, RejectsNonPositiveGains) {
  DpControllerParams p;
  p.Kp(1, 1) = 0.0;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = DpControllerParams{};
  p.M(0, 1) = 1.0;  // not symmetric
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::control
