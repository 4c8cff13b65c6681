#include "dynpos/model/azimuth_region.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dynpos::model {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDeg = std::numbers::pi / 180.0;

double wrap(double a) { return std::fmod(std::fmod(a, kTwoPi) + kTwoPi, kTwoPi); }

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A fan from the origin through corners first..last (indices mod sides, last after first).
struct Fan {
  int first = 0;
  int last = 0;
};

// The edges of corners first..last: each side's outward normal and distance; a side through
// the origin (a corner of factor 0) is left to the wedge.
void add_edges(const std::vector<Eigen::Vector2d>& corners, const Fan& fan, ConvexPiece& piece) {
  const int sides = static_cast<int>(corners.size());
  for (int j = fan.first; j < fan.last; ++j) {
    const Eigen::Vector2d& a = corners[static_cast<std::size_t>(j % sides)];
    const Eigen::Vector2d& b = corners[static_cast<std::size_t>((j + 1) % sides)];
    const Eigen::Vector2d d = b - a;
    if (d.norm() <= 1e-15) continue;
    const Eigen::Vector2d n = Eigen::Vector2d(d.y(), -d.x()) / d.norm();
    const double distance = n.dot(a);
    if (distance <= 1e-12) continue;
    piece.normals.push_back(n);
    piece.distances.push_back(distance);
  }
}

// The fans between reflex corners, each at most a half turn: convex pieces of the polygon.
std::vector<Fan> convex_fans(const std::vector<Eigen::Vector2d>& corners) {
  const int sides = static_cast<int>(corners.size());
  std::vector<int> reflex;
  for (int j = 0; j < sides; ++j) {
    const Eigen::Vector2d& before = corners[static_cast<std::size_t>((j + sides - 1) % sides)];
    const Eigen::Vector2d& at = corners[static_cast<std::size_t>(j)];
    const Eigen::Vector2d& after = corners[static_cast<std::size_t>((j + 1) % sides)];
    if (cross(at - before, after - at) < -1e-12) reflex.push_back(j);
  }
  if (reflex.empty()) return {{0, sides}};  // the whole polygon, convex
  std::vector<Fan> fans;
  const int half = sides / 2;  // corners of a half turn
  for (std::size_t i = 0; i < reflex.size(); ++i) {
    const int from = reflex[i];
    const int to = i + 1 < reflex.size() ? reflex[i + 1] : reflex.front() + sides;
    for (int a = from; a < to; a += half) fans.push_back({a, std::min(a + half, to)});
  }
  return fans;
}

}  // namespace

double loss_factor(const std::vector<LossPoint>& loss, double alpha_rad) {
  if (loss.empty()) return 1.0;
  if (loss.size() == 1) return loss.front().factor;
  const double a = wrap(alpha_rad) / kDeg;
  // The point at or before a (the last one before the first wraps round), and the next.
  std::size_t i = loss.size() - 1;
  for (std::size_t k = 0; k < loss.size(); ++k) {
    if (loss[k].angle_deg <= a) i = k;
  }
  const LossPoint& p = loss[i];
  const LossPoint& q = loss[(i + 1) % loss.size()];
  const double span = std::fmod(q.angle_deg - p.angle_deg + 360.0, 360.0);
  const double into = std::fmod(a - p.angle_deg + 360.0, 360.0);
  if (span <= 0.0) return p.factor;
  return p.factor + (q.factor - p.factor) * into / span;
}

std::vector<ConvexPiece> azimuth_pieces(const std::vector<LossPoint>& loss,
                                        const std::vector<AngleSector>& forbidden_deg, int sides) {
  std::vector<Eigen::Vector2d> corners;
  for (int j = 0; j < sides; ++j) {
    const double theta = j * kTwoPi / sides;
    corners.push_back(loss_factor(loss, theta) * Eigen::Vector2d(std::cos(theta), std::sin(theta)));
  }
  std::vector<ConvexPiece> fans;
  for (const Fan& f : convex_fans(corners)) {
    ConvexPiece p;
    p.wedge = {wrap(f.first * kTwoPi / sides), (f.last - f.first) * kTwoPi / sides};
    add_edges(corners, f, p);
    fans.push_back(std::move(p));
  }
  std::vector<ConvexPiece> out;
  for (const AllowedArc& arc : allowed_arcs(forbidden_deg)) {
    for (const ConvexPiece& fan : fans) {
      if (arc.span_rad >= kTwoPi || fan.wedge.span_rad >= kTwoPi) {
        ConvexPiece p = fan;
        p.wedge = arc.span_rad >= kTwoPi ? fan.wedge : arc;
        out.push_back(std::move(p));
        continue;
      }
      // The overlap of two arcs of at most a half turn each is one arc or none; the fan's
      // start is d after the arc's, and may wrap past 2π.
      const double d = wrap(fan.wedge.from_rad - arc.from_rad);
      for (const double shift : {d, d - kTwoPi}) {
        const double lo = std::max(0.0, shift);
        const double hi = std::min(arc.span_rad, shift + fan.wedge.span_rad);
        if (hi - lo <= 1e-12) continue;
        ConvexPiece p = fan;
        p.wedge = {wrap(arc.from_rad + lo), hi - lo};
        out.push_back(std::move(p));
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const ConvexPiece& a, const ConvexPiece& b) {
    return a.wedge.from_rad < b.wedge.from_rad;
  });
  return out;
}

}  // namespace dynpos::model
