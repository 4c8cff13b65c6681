#include "dynpos/model/thrust_configuration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

#include "dynpos/core/error.hpp"

namespace dynpos::model {
namespace {

TEST(ThrustConfiguration, PortPropellerAheadTurnsBowToStarboard) {
  const ThrustConfiguration config;
  ActuatorForces f;
  f.thrust_port = 10e3;
  const Eigen::Vector3d tau = config.tau(f);
  // N = x·F_y − y·F_x with y = −2.7 m: +2.7·10 kN·m, bow to starboard.
  EXPECT_DOUBLE_EQ(tau.x(), 10e3);
  EXPECT_DOUBLE_EQ(tau.y(), 0.0);
  EXPECT_DOUBLE_EQ(tau.z(), 2.7 * 10e3);
  ActuatorForces g;
  g.thrust_stb = 10e3;
  EXPECT_DOUBLE_EQ(config.tau(g).z(), -2.7 * 10e3);
}

TEST(ThrustConfiguration, TunnelAndRudderMomentSigns) {
  const ThrustConfiguration config;
  ActuatorForces f;
  f.tunnel = 1e3;  // bow pushed to starboard
  EXPECT_DOUBLE_EQ(config.tau(f).z(), 12.5e3);
  ActuatorForces g;
  g.rudder_port_b = Eigen::Vector2d(-100.0, -1e3);  // stern pushed to port, with drag
  const Eigen::Vector3d tau = config.tau(g);
  EXPECT_DOUBLE_EQ(tau.x(), -100.0);
  EXPECT_DOUBLE_EQ(tau.y(), -1e3);
  // N = (−14.5)(−1000) − (−2.7)(−100) = 14500 − 270.
  EXPECT_DOUBLE_EQ(tau.z(), 14500.0 - 270.0);
}

TEST(ThrustConfiguration, MatrixColumnsAgreeWithTheFullMap) {
  const ThrustConfiguration config;
  const ThrustConfiguration::Matrix& B = config.matrix();
  ActuatorForces f;
  f.thrust_port = 1.0;
  EXPECT_TRUE(B.col(ThrustConfiguration::kThrustPort).isApprox(config.tau(f)));
  f = {};
  f.thrust_stb = 1.0;
  EXPECT_TRUE(B.col(ThrustConfiguration::kThrustStb).isApprox(config.tau(f)));
  f = {};
  f.rudder_port_b = {0.0, 1.0};
  EXPECT_TRUE(B.col(ThrustConfiguration::kRudderPort).isApprox(config.tau(f)));
  f = {};
  f.rudder_stb_b = {0.0, 1.0};
  EXPECT_TRUE(B.col(ThrustConfiguration::kRudderStb).isApprox(config.tau(f)));
  f = {};
  f.tunnel = 1.0;
  EXPECT_TRUE(B.col(ThrustConfiguration::kTunnel).isApprox(config.tau(f)));
  // B has full row rank: every (X, Y, N) is reachable without bounds.
  EXPECT_EQ(Eigen::FullPivLU<ThrustConfiguration::Matrix>(B).rank(), 3);
}

TEST(ThrustConfiguration, VelocityAtAPoint) {
  // (u − r·y, v + r·x) for (u, v, r) = (2, 0.5, 0.1) at (−14.5, 2.7).
  const Eigen::Vector2d v = ThrustConfiguration::velocity_at({2.0, 0.5, 0.1}, {-14.5, 2.7});
  EXPECT_DOUBLE_EQ(v.x(), 2.0 - 0.27);
  EXPECT_DOUBLE_EQ(v.y(), 0.5 - 1.45);
}

TEST(ThrustConfiguration, ValidateRejectsSwappedSides) {
  ThrustConfigurationParams p;
  p.p_port_propeller_b = {-13.0, 2.7};
  EXPECT_THROW(ThrustConfiguration{p}, core::InputError);
  p = ThrustConfigurationParams{};
  p.p_tunnel_b = {std::nan(""), 0.0};
  EXPECT_THROW(p.validate(), core::InputError);
}

}  // namespace
}  // namespace dynpos::model
