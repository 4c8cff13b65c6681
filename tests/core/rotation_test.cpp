#include "dynpos/core/rotation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "dynpos/core/angle.hpp"
#include "matchers.hpp"

namespace dynpos::core {
namespace {

using testing::AnglesNear;
using testing::MatricesNear;

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct AttitudeCase {
  std::string name;
  EulerAngles theta;
  bool principal;  // roll, yaw in (−π, π] and pitch in (−π/2, π/2): a unique Euler triple
};

EulerAngles deg(double roll_deg, double pitch_deg, double yaw_deg) {
  return {deg_to_rad(roll_deg), deg_to_rad(pitch_deg), deg_to_rad(yaw_deg)};
}

// The fixed property table: identity, tiny, generic, near-wrap (ψ = ±π), large, near-gimbal.
const std::array<AttitudeCase, 13>& cases() {
  static const std::array<AttitudeCase, 13> kCases{{
      {"identity", {0.0, 0.0, 0.0}, true},
      {"tiny", {1e-9, -2e-9, 3e-9}, true},
      {"generic", deg(10.0, -20.0, 30.0), true},
      {"ship_like", deg(-3.0, 2.0, 137.0), true},
      {"yaw_plus_pi", {0.02, -0.01, kPi}, true},
      {"yaw_minus_pi", {0.02, -0.01, -kPi}, true},
      {"yaw_just_below_pi", {-0.1, 0.05, kPi - 1e-9}, true},
      {"large_principal", deg(170.0, -80.0, -179.9), true},
      {"large_unwrapped", {4.0, 2.0, 10.0}, false},
      {"negative_multiturn", {-7.0, -3.5, -20.0}, false},
      {"pitch_89", deg(30.0, 89.0, -60.0), true},
      {"pitch_minus_89", deg(-45.0, -89.0, 100.0), true},
      {"gimbal_lock", {0.3, kPi / 2.0, 1.0}, false},
  }};
  return kCases;
}

bool at_gimbal_lock(const EulerAngles& theta) {
  return std::abs(std::cos(theta.pitch_rad)) < kGimbalCosTolerance;
}

TEST(Rotation, IsOrthonormalWithUnitDeterminant) {
  for (const AttitudeCase& c : cases()) {
    SCOPED_TRACE(c.name);
    const Eigen::Matrix3d R = R_nb_zyx(c.theta);
    // Each element of RᵀR is a 3-term dot product of rounded unit-size numbers: a few eps.
    EXPECT_TRUE(MatricesNear(R.transpose() * R, Eigen::Matrix3d::Identity(), 8 * kEps));
    // The determinant is 6 triple products of unit-size rounded numbers: a few eps each.
    EXPECT_NEAR(R.determinant(), 1.0, 16 * kEps);
  }
}

TEST(Rotation, MatchesComposedElementaryRotations) {
  for (const AttitudeCase& c : cases()) {
    SCOPED_TRACE(c.name);
    const Eigen::Matrix3d expected =
        (Eigen::AngleAxisd(c.theta.yaw_rad, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(c.theta.pitch_rad, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(c.theta.roll_rad, Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    // Two independent roundings of the same products of unit-size sines and cosines.
    EXPECT_TRUE(MatricesNear(R_nb_zyx(c.theta), expected, 8 * kEps));
  }
}

TEST(Rotation, MapsBodyAxesToNedByTheConvention) {
  // Heading 90°: the bow (BODY x) points east (NED y).
  const Eigen::Vector3d bow_n = R_nb_zyx(0.0, 0.0, deg_to_rad(90.0)) * Eigen::Vector3d::UnitX();
  // cos(π/2) ≈ 6e-17 leaves an eps-sized north component.
  EXPECT_TRUE(MatricesNear(bow_n, Eigen::Vector3d::UnitY(), 4 * kEps));
  // Positive pitch lifts the bow: the bow points up, negative NED z.
  EXPECT_LT((R_nb_zyx(0.0, deg_to_rad(5.0), 0.0) * Eigen::Vector3d::UnitX()).z(), 0.0);
  // Positive roll lowers starboard: BODY y gets a positive (down) NED z.
  EXPECT_GT((R_nb_zyx(deg_to_rad(5.0), 0.0, 0.0) * Eigen::Vector3d::UnitY()).z(), 0.0);
}

TEST(Rotation, YawOnlyEqualsFullRotationWithLevelAttitude) {
  for (const AttitudeCase& c : cases()) {
    SCOPED_TRACE(c.name);
    // With φ = θ = 0 every extra factor of (2.4) is exactly 0 or 1, so (2.19) is bit-identical.
    EXPECT_TRUE(MatricesNear(R_yaw(c.theta.yaw_rad), R_nb_zyx(0.0, 0.0, c.theta.yaw_rad), 0.0));
  }
}

TEST(Skew, IsCrossProductAndSkewSymmetric) {
  const std::array<Eigen::Vector3d, 4> omegas{
      Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(1e-9, -2e-9, 3e-9),
      Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(-40.0, 7.5, 1e3)};
  const std::array<Eigen::Vector3d, 3> xs{Eigen::Vector3d(1.0, 0.0, 0.0),
                                          Eigen::Vector3d(-3.0, 2.0, 0.5),
                                          Eigen::Vector3d(1e4, -1e-3, 7.0)};
  for (const Eigen::Vector3d& omega : omegas) {
    const Eigen::Matrix3d S = skew(omega);
    EXPECT_TRUE(MatricesNear(S.transpose(), -S, 0.0));  // negation is exact
    for (const Eigen::Vector3d& x : xs) {
      // Both sides sum the same two products, possibly in another order: 2 eps relative.
      const double tol = 2 * kEps * omega.norm() * x.norm();
      EXPECT_TRUE(MatricesNear(S * x, omega.cross(x), tol));
    }
  }
}

TEST(EulerRates, InverseTimesMatrixIsIdentity) {
  for (const AttitudeCase& c : cases()) {
    if (at_gimbal_lock(c.theta)) continue;
    SCOPED_TRACE(c.name);
    const Eigen::Matrix3d T = euler_rate_matrix(c.theta.roll_rad, c.theta.pitch_rad);
    const Eigen::Matrix3d T_inv = euler_rate_matrix_inverse(c.theta.roll_rad, c.theta.pitch_rad);
    // Entries of T reach 1/cos θ ≈ 57 at 89°, so the products carry ≈ 57 × a few eps.
    EXPECT_TRUE(MatricesNear(T * T_inv, Eigen::Matrix3d::Identity(), 1e-13));
    EXPECT_TRUE(MatricesNear(T_inv * T, Eigen::Matrix3d::Identity(), 1e-13));
  }
}

TEST(EulerRates, InverseHasDeterminantCosPitch) {
  for (const AttitudeCase& c : cases()) {
    SCOPED_TRACE(c.name);
    // det T⁻¹ = cos θ in closed form; the 3x3 determinant of unit-size entries rounds to a few eps.
    EXPECT_NEAR(euler_rate_matrix_inverse(c.theta.roll_rad, c.theta.pitch_rad).determinant(),
                std::cos(c.theta.pitch_rad), 8 * kEps);
  }
}

TEST(EulerRates, ThrowsAtGimbalLock) {
  EXPECT_THROW(euler_rate_matrix(0.1, kPi / 2.0), std::domain_error);
  EXPECT_THROW(euler_rate_matrix(-0.3, -kPi / 2.0), std::domain_error);
  EXPECT_THROW(euler_rate_matrix(0.0, kPi / 2.0 + kTwoPi), std::domain_error);
  EXPECT_THROW(euler_rate_matrix(0.0, std::numeric_limits<double>::quiet_NaN()), std::domain_error);
  EXPECT_NO_THROW(euler_rate_matrix(0.0, deg_to_rad(89.9)));
  EXPECT_NO_THROW(euler_rate_matrix_inverse(0.1, kPi / 2.0));
}

// One RK4 step of Θ̇ = T(Θ)·ω with constant body rate ω.
EulerAngles rk4_euler_step(const EulerAngles& theta, const Eigen::Vector3d& omega, double h) {
  auto f = [&omega](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return euler_rate_matrix(x.x(), x.y()) * omega;
  };
  const Eigen::Vector3d x(theta.roll_rad, theta.pitch_rad, theta.yaw_rad);
  const Eigen::Vector3d k1 = f(x);
  const Eigen::Vector3d k2 = f(x + 0.5 * h * k1);
  const Eigen::Vector3d k3 = f(x + 0.5 * h * k2);
  const Eigen::Vector3d k4 = f(x + h * k3);
  const Eigen::Vector3d next = x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  return {next.x(), next.y(), next.z()};
}

TEST(Rotation, DerivativeIsRTimesSkewOfBodyRate) {
  // Ṙ = R·S(ω) (2.5) along Θ̇ = T(Θ)·ω. With ω constant, R(t) = R₀·exp(S(ω)t), so the
  // central difference (R(h) − R(−h))/2h has truncation error h²/6·|R₀S³| ≤ h²|ω|³/6.
  const Eigen::Vector3d omega(0.05, -0.08, 0.12);  // [rad/s], DP-like body rates
  const double h = 1e-4;                           // [s]
  for (const AttitudeCase& c : cases()) {
    if (at_gimbal_lock(c.theta)) continue;
    SCOPED_TRACE(c.name);
    const Eigen::Matrix3d R_dot_fd = (R_nb_zyx(rk4_euler_step(c.theta, omega, h)) -
                                      R_nb_zyx(rk4_euler_step(c.theta, omega, -h))) /
                                     (2.0 * h);
    const Eigen::Matrix3d R_dot = R_nb_zyx(c.theta) * skew(omega);
    // Truncation h²|ω|³/6 ≈ 4e-12; rounding of R (a few eps per element) divided by 2h adds
    // ≈ 1e-11; RK4's own error is O(h⁵), negligible. 1e-10 leaves a margin of ten; a wrong T
    // (e.g. transposed) gives errors above 1e-2 on every non-trivial case.
    EXPECT_TRUE(MatricesNear(R_dot_fd, R_dot, 1e-10));
  }
}

TEST(Rotation, DerivativeCheckConvergesAtSecondOrder) {
  // A coarse step makes truncation dominate rounding, so halving h must divide the error by 4.
  const Eigen::Vector3d omega(0.3, -0.4, 0.5);  // [rad/s], fast enough for visible truncation
  const EulerAngles theta = deg(10.0, -20.0, 30.0);
  auto error = [&](double h) {
    const Eigen::Matrix3d fd =
        (R_nb_zyx(rk4_euler_step(theta, omega, h)) - R_nb_zyx(rk4_euler_step(theta, omega, -h))) /
        (2.0 * h);
    return (fd - R_nb_zyx(theta) * skew(omega)).cwiseAbs().maxCoeff();
  };
  const double ratio = error(0.02) / error(0.01);
  // Second order gives 4; the O(h⁴) next term and RK4's O(h⁵) error shift it by < 1 %.
  EXPECT_NEAR(ratio, 4.0, 0.05);
}

TEST(EulerFromR, RoundTripsPrincipalAngles) {
  for (const AttitudeCase& c : cases()) {
    if (!c.principal) continue;
    SCOPED_TRACE(c.name);
    const EulerAngles back = euler_from_R(R_nb_zyx(c.theta));
    // Element errors of a few eps become angle errors of eps/cos θ: ≈ 1e-14 at 89° pitch.
    EXPECT_TRUE(AnglesNear(back.roll_rad, c.theta.roll_rad, 1e-13));
    EXPECT_NEAR(back.pitch_rad, c.theta.pitch_rad, 1e-13);
    EXPECT_TRUE(AnglesNear(back.yaw_rad, c.theta.yaw_rad, 1e-13));
  }
}

TEST(EulerFromR, ReturnsPrincipalRangesAndReproducesR) {
  for (const AttitudeCase& c : cases()) {
    SCOPED_TRACE(c.name);
    const Eigen::Matrix3d R = R_nb_zyx(c.theta);
    const EulerAngles back = euler_from_R(R);
    EXPECT_GT(back.roll_rad, -kPi);
    EXPECT_LE(back.roll_rad, kPi);
    EXPECT_GE(back.pitch_rad, -kPi / 2.0);
    EXPECT_LE(back.pitch_rad, kPi / 2.0);
    EXPECT_GT(back.yaw_rad, -kPi);
    EXPECT_LE(back.yaw_rad, kPi);
    // Recomputing R from recovered angles: a few eps per element, even at gimbal lock where
    // only ψ ∓ φ is recovered (cos θ ≈ 6e-17 there adds less than eps).
    EXPECT_TRUE(MatricesNear(R_nb_zyx(back), R, 1e-14));
  }
}

TEST(EulerFromR, GimbalLockPutsVerticalRotationInYaw) {
  // θ = +90°: R depends on ψ − φ only; θ = −90°: on ψ + φ.
  const EulerAngles up = euler_from_R(R_nb_zyx(0.3, kPi / 2.0, 1.0));
  EXPECT_EQ(up.roll_rad, 0.0);
  EXPECT_NEAR(up.pitch_rad, kPi / 2.0, 1e-15);  // atan2 of an exact 1 over ≈ 6e-17: eps-level
  EXPECT_TRUE(AnglesNear(up.yaw_rad, 1.0 - 0.3, 1e-14));  // a few eps from the sums in (2.4)
  const EulerAngles down = euler_from_R(R_nb_zyx(0.3, -kPi / 2.0, 1.0));
  EXPECT_EQ(down.roll_rad, 0.0);
  EXPECT_NEAR(down.pitch_rad, -kPi / 2.0, 1e-15);           // as above
  EXPECT_TRUE(AnglesNear(down.yaw_rad, 1.0 + 0.3, 1e-14));  // as above
}

TEST(EulerFromR, YawOfMinusPiIsReportedAsPi) {
  // A half turn about z written with −0 where atan2 would otherwise return exactly −π.
  Eigen::Matrix3d R;
  R << -1.0, 0.0, 0.0,  //
      -0.0, -1.0, 0.0,  //
      0.0, 0.0, 1.0;
  EXPECT_EQ(euler_from_R(R).yaw_rad, kPi);
  R(1, 0) = 0.0;
  EXPECT_EQ(euler_from_R(R).yaw_rad, kPi);
}

}  // namespace
}  // namespace dynpos::core
