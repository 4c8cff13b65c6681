#include "dynpos/model/azimuth_region.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace dynpos::model {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kSides = 32;

bool in_piece(const ConvexPiece& p, const Eigen::Vector2d& f, double tol = 1e-9) {
  if (f.norm() > tol && p.wedge.span_rad < 2.0 * std::numbers::pi) {
    const double after =
        std::fmod(std::atan2(f.y(), f.x()) - p.wedge.from_rad + 4.0 * std::numbers::pi,
                  2.0 * std::numbers::pi);
    if (after > p.wedge.span_rad + tol) return false;
  }
  for (std::size_t k = 0; k < p.normals.size(); ++k) {
    if (p.normals[k].dot(f) > p.distances[k] + tol) return false;
  }
  return true;
}

// The star-shaped polygon's radius in direction α: on the chord between the corners around it.
double star_radius(const std::vector<LossPoint>& loss, double alpha) {
  const double step = 2.0 * std::numbers::pi / kSides;
  const double a = std::fmod(alpha + 2.0 * std::numbers::pi, 2.0 * std::numbers::pi);
  const int j = static_cast<int>(std::floor(a / step)) % kSides;
  const double t0 = j * step, t1 = (j + 1) * step;
  const Eigen::Vector2d v0 = loss_factor(loss, t0) * Eigen::Vector2d(std::cos(t0), std::sin(t0));
  const Eigen::Vector2d v1 = loss_factor(loss, t1) * Eigen::Vector2d(std::cos(t1), std::sin(t1));
  // The ray (cos a, sin a)·r meets the chord v0 + s(v1 − v0).
  const Eigen::Vector2d u(std::cos(a), std::sin(a));
  const Eigen::Vector2d d = v1 - v0;
  const double det = u.x() * (-d.y()) - u.y() * (-d.x());
  return (v0.x() * (-d.y()) - v0.y() * (-d.x())) / det;
}

TEST(AzimuthRegion, TheLossFactorIsLinearRoundTheCircle) {
  const std::vector<LossPoint> loss{{0.0, 1.0}, {80.0, 1.0}, {90.0, 0.5}, {100.0, 1.0}};
  EXPECT_DOUBLE_EQ(loss_factor(loss, 85.0 * kDeg), 0.75);
  EXPECT_DOUBLE_EQ(loss_factor(loss, 90.0 * kDeg), 0.5);
  EXPECT_DOUBLE_EQ(loss_factor(loss, 200.0 * kDeg), 1.0);
  const std::vector<LossPoint> across{{10.0, 0.6}, {350.0, 1.0}};  // 350° → 10° across 0
  EXPECT_NEAR(loss_factor(across, 0.0), 0.8, 1e-12);
  EXPECT_DOUBLE_EQ(loss_factor({}, 1.0), 1.0);
}

TEST(AzimuthRegion, WithoutLossesThePiecesAreThePolygonOrItsArcs) {
  const auto whole = azimuth_pieces({}, {}, kSides);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_NEAR(whole[0].wedge.span_rad, 2.0 * std::numbers::pi, 1e-12);
  ASSERT_EQ(whole[0].distances.size(), static_cast<std::size_t>(kSides));
  for (const double d : whole[0].distances)
    EXPECT_NEAR(d, std::cos(std::numbers::pi / kSides), 1e-12);
  const auto cut = azimuth_pieces({}, {{75.0, 105.0}}, kSides);
  const auto arcs = allowed_arcs({{75.0, 105.0}});
  ASSERT_EQ(cut.size(), arcs.size());
}

TEST(AzimuthRegion, ADipSplitsThePolygonIntoConvexFansThatCoverIt) {
  const std::vector<LossPoint> loss{{0.0, 1.0}, {60.0, 1.0}, {90.0, 0.4}, {120.0, 1.0}};
  for (const auto& forbidden :
       {std::vector<AngleSector>{}, std::vector<AngleSector>{{250.0, 290.0}}}) {
    const auto pieces = azimuth_pieces(loss, forbidden, kSides);
    EXPECT_GE(pieces.size(), 2u);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi), u01(0.0, 1.0);
    for (int k = 0; k < 20000; ++k) {
      const double a = angle(rng);
      const double r = star_radius(loss, a);
      const Eigen::Vector2d dir(std::cos(a), std::sin(a));
      const bool allowed = !in_forbidden_sector(a, forbidden, 1e-9);
      bool inside = false, outside = false;
      for (const ConvexPiece& p : pieces) {
        inside |= in_piece(p, 0.999 * u01(rng) * r * dir);
        outside |= in_piece(p, (1.001 + u01(rng)) * r * dir);
      }
      // Every allowed point under the star polygon is in a piece; none beyond it is.
      if (allowed) {
        EXPECT_TRUE(inside) << a / kDeg;
      }
      EXPECT_FALSE(outside) << a / kDeg;
    }
    // Each piece is convex: a wedge of at most a half turn, cut by half-planes.
    for (const ConvexPiece& p : pieces) EXPECT_LE(p.wedge.span_rad, std::numbers::pi + 1e-12);
  }
}

}  // namespace
}  // namespace dynpos::model
