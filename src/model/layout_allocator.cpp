#include "dynpos/model/layout_allocator.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "convex_qp.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/model/azimuth_region.hpp"
#include "dynpos/model/unit_drive.hpp"

namespace dynpos::model {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDemandWeight = 1e8;   // ρ: the demand over the effort
constexpr double kMetTolerance = 1e-6;  // of the force and moment scales
constexpr int kRelaxed = -1;            // region code: the unit's convex hull
constexpr double kLargestDemand = 1e6;  // of the scales (allocate())

// The rudder's largest side force [N] at capacity `cap` of its propeller: the cone's at full
// ahead thrust, within the rudder's own largest force.
double rudder_lift_max(const ThrusterUnit& u, double cap) {
  const double cone = u.rudder_lift_per_thrust * cap * u.max_thrust_N + u.rudder_lift_at_zero_N;
  return u.rudder_max_force_N > 0.0 ? std::min(cone, u.rudder_max_force_N) : cone;
}

int variable_count(UnitType type) {
  return type == UnitType::kAzimuth || type == UnitType::kPropellerRudder ? 2 : 1;
}

double wrap_2pi(double a) { return std::fmod(std::fmod(a, kTwoPi) + kTwoPi, kTwoPi); }

// Angle from arc start `from` to `a`, in [0, 2π).
double angle_after(double a, double from) { return wrap_2pi(a - from); }

// One row a·x ≤ b on the variables at `offset`.
struct Rows {
  std::vector<Eigen::Index> column;
  std::vector<bool> limit;  // a limit of the unit, not the split between a rudder's two signs
  std::vector<std::pair<Eigen::Vector2d, double>> rows;  // (coefficients of 1 or 2 vars, bound)
  std::vector<int> width;
  void add(Eigen::Index offset, int w, Eigen::Vector2d a, double b, bool is_limit = true) {
    column.push_back(offset);
    limit.push_back(is_limit);
    width.push_back(w);
    rows.emplace_back(a, b);
  }
};

}  // namespace

void LayoutAllocationOptions::validate() const {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(priority(i)) || priority(i) <= 0.0) {
      throw core::InputError::for_option("allocation.priority",
                                         "each priority must be finite and > 0");
    }
  }
  if (!std::isfinite(force_scale) || force_scale <= 0.0) {
    throw core::InputError::for_option("allocation.force_scale", "must be finite and > 0");
  }
  if (!std::isfinite(moment_scale) || moment_scale <= 0.0) {
    throw core::InputError::for_option("allocation.moment_scale", "must be finite and > 0");
  }
  if (polygon_sides < 8 || polygon_sides > 256) {
    throw core::InputError::for_option("allocation.polygon_sides",
                                       fmt::format("{} is not in 8…256", polygon_sides));
  }
  if (!std::isfinite(rudder_weight) || rudder_weight <= 0.0) {
    throw core::InputError::for_option("allocation.rudder_weight", "must be finite and > 0");
  }
  if (max_region_combinations < 1) {
    throw core::InputError::for_option("allocation.max_region_combinations", "must be ≥ 1");
  }
}

struct LayoutAllocator::Setup {
  detail::ConvexQp qp;
  Eigen::MatrixXd A;      // τ = A·x [N, N, N·m]
  Eigen::VectorXd scale;  // s per variable [N]
  std::vector<Eigen::Index> offset;
  std::vector<int> regions;           // per unit
  std::vector<std::size_t> row_unit;  // the unit of each row of G
  std::vector<bool> row_limit;        // whether the row is one of the unit's limits
  Eigen::MatrixXd At_qd2;  // Aᵀ·diag(Q·D²): the demand term c = −2ρ·At_qd2·τ_d
};

LayoutAllocator::LayoutAllocator(std::vector<ThrusterUnit> units, LayoutAllocationOptions options)
    : units_(std::move(units)), options_(std::move(options)) {
  options_.validate();
  side_distance_ = std::cos(std::numbers::pi / options_.polygon_sides);
  for (int j = 0; j < options_.polygon_sides; ++j) {
    const double theta = (j + 0.5) * kTwoPi / options_.polygon_sides;
    side_normals_.emplace_back(std::cos(theta), std::sin(theta));
  }
  if (units_.empty()) throw core::InputError::for_option("thruster", "the layout has no unit");
  std::set<std::string> names;
  for (const ThrusterUnit& u : units_) {
    u.validate();
    if (!names.insert(u.name).second) {
      throw core::InputError::for_option("thruster.name",
                                         fmt::format("two units are named '{}'", u.name));
    }
    // An azimuth with a loss table: the convex pieces of its star-shaped polygon, whose wedges
    // stand for its arcs everywhere below; the relaxation is the polygon at its largest factor.
    pieces_.emplace_back();
    relaxed_radius_.push_back(1.0);
    if (u.type == UnitType::kAzimuth && !u.loss.empty()) {
      pieces_.back() = azimuth_pieces(u.loss, u.forbidden_deg, options_.polygon_sides);
      std::vector<AllowedArc> wedges;
      for (const ConvexPiece& p : pieces_.back()) wedges.push_back(p.wedge);
      arcs_.push_back(std::move(wedges));
      double largest = 0.0;
      for (const LossPoint& p : u.loss) largest = std::max(largest, p.factor);
      relaxed_radius_.back() = largest;
      continue;
    }
    arcs_.push_back(u.type == UnitType::kAzimuth ? allowed_arcs(u.forbidden_deg)
                                                 : std::vector<AllowedArc>{});
  }
}

// The sides of unit k's disc in `region`: the regular polygon (at the relaxation's largest
// factor for a loss table), or the edges of its convex piece.
void LayoutAllocator::for_each_side(
    std::size_t k, int region,
    const std::function<void(const Eigen::Vector2d&, double)>& side) const {
  if (pieces_[k].empty() || region == kRelaxed) {
    for (const Eigen::Vector2d& n : side_normals_) side(n, side_distance_ * relaxed_radius_[k]);
    return;
  }
  const ConvexPiece& p = pieces_[k][static_cast<std::size_t>(region)];
  for (std::size_t i = 0; i < p.normals.size(); ++i) side(p.normals[i], p.distances[i]);
}

int LayoutAllocator::region_count(std::size_t unit) const {
  switch (units_[unit].type) {
    case UnitType::kAzimuth:
      return static_cast<int>(arcs_[unit].size());
    case UnitType::kPropellerRudder:
      return 2;
    default:
      return 1;
  }
}

LayoutAllocator::Setup LayoutAllocator::setup(const Eigen::Vector3d& tau_d_b,
                                              const std::vector<double>& capacity,
                                              const std::vector<int>& regions) const {
  Setup s;
  s.regions = regions;
  Eigen::Index n = 0;
  for (const ThrusterUnit& u : units_) {
    s.offset.push_back(n);
    n += variable_count(u.type);
  }
  s.A = Eigen::MatrixXd::Zero(3, n);
  s.scale = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(n);
  Rows rows;
  for (std::size_t k = 0; k < units_.size(); ++k) {
    const ThrusterUnit& u = units_[k];
    const Eigen::Index o = s.offset[k];
    const double cap = capacity.empty() ? 1.0 : capacity[k];
    const Eigen::Vector3d surge{1.0, 0.0, -u.y_m};  // B's column of a force along x at (x, y)
    const Eigen::Vector3d sway{0.0, 1.0, u.x_m};
    const double rated = std::max(u.max_thrust_N, u.max_reverse_thrust_N);
    const double ahead = u.max_thrust_N / rated;  // bounds of x over the larger rating
    const double astern = u.max_reverse_thrust_N / rated;
    const int region = regions[k];
    switch (u.type) {
      case UnitType::kAzimuth: {
        s.scale.segment(o, 2).setConstant(cap * u.max_thrust_N);
        s.A.col(o) = surge * s.scale(o);
        s.A.col(o + 1) = sway * s.scale(o + 1);
        weight.segment(o, 2).setConstant(u.weight);
        if (pieces_[k].empty()) {
          for (const Eigen::Vector2d& normal : side_normals_) {
            rows.add(o, 2, normal, side_distance_);
          }
        } else {
          for_each_side(k, region,
                        [&](const Eigen::Vector2d& n, double d) { rows.add(o, 2, n, d); });
        }
        if (region != kRelaxed && arcs_[k][region].span_rad < kTwoPi) {
          const double a = arcs_[k][region].from_rad;
          const double b = a + arcs_[k][region].span_rad;
          rows.add(o, 2, {std::sin(a), -std::cos(a)}, 0.0);  // not before the arc's start
          rows.add(o, 2, {-std::sin(b), std::cos(b)}, 0.0);  // not after its end
        }
        break;
      }
      case UnitType::kTunnel:
      case UnitType::kPropeller: {
        s.scale(o) = cap * rated;
        s.A.col(o) = (u.type == UnitType::kTunnel ? sway : surge) * s.scale(o);
        weight(o) = u.weight;
        rows.add(o, 1, {1.0, 0.0}, ahead);
        rows.add(o, 1, {-1.0, 0.0}, astern);
        break;
      }
      case UnitType::kPropellerRudder: {
        s.scale(o) = cap * rated;
        const double lift_max = rudder_lift_max(u, cap);
        s.scale(o + 1) = lift_max > 0.0 ? lift_max : 0.0;
        s.A.col(o) = surge * s.scale(o);
        s.A.col(o + 1) = Eigen::Vector3d{0.0, 1.0, u.rudder_x_m.value_or(u.x_m)} * s.scale(o + 1);
        weight(o) = u.weight;
        weight(o + 1) = u.weight * options_.rudder_weight;
        // In x: |Y|·lift_max ≤ κ·T·cap·rated + c, i.e. |y| ≤ a·t + b (y = 0 without lift).
        const double a = lift_max > 0.0 ? u.rudder_lift_per_thrust * cap * rated / lift_max : 0.0;
        const double b = lift_max > 0.0 ? u.rudder_lift_at_zero_N / lift_max : 0.0;
        if (region == 0) {  // ahead: the cone, within the rudder's largest force
          rows.add(o, 2, {1.0, 0.0}, ahead);
          rows.add(o, 2, {-1.0, 0.0}, 0.0, false);
          rows.add(o, 2, {-a, 1.0}, b);
          rows.add(o, 2, {-a, -1.0}, b);
          rows.add(o, 2, {0.0, 1.0}, lift_max > 0.0 ? 1.0 : 0.0);
          rows.add(o, 2, {0.0, -1.0}, lift_max > 0.0 ? 1.0 : 0.0);
        } else if (region == 1) {  // astern: no slipstream over the rudder
          rows.add(o, 2, {1.0, 0.0}, 0.0, false);
          rows.add(o, 2, {-1.0, 0.0}, astern);
          rows.add(o, 2, {0.0, 1.0}, std::min(b, 1.0));
          rows.add(o, 2, {0.0, -1.0}, std::min(b, 1.0));
        } else {  // the hull of both
          rows.add(o, 2, {1.0, 0.0}, ahead);
          rows.add(o, 2, {-1.0, 0.0}, astern);
          rows.add(o, 2, {0.0, 1.0}, lift_max > 0.0 ? 1.0 : 0.0);
          rows.add(o, 2, {0.0, -1.0}, lift_max > 0.0 ? 1.0 : 0.0);
        }
        break;
      }
    }
  }
  // min ρ‖Q^{½}D(A·x − τ_d)‖² + xᵀWx as ½xᵀHx + cᵀx.
  const Eigen::Vector3d d{1.0 / options_.force_scale, 1.0 / options_.force_scale,
                          1.0 / options_.moment_scale};
  const Eigen::Vector3d qd2 = options_.priority.cwiseProduct(d).cwiseProduct(d);
  s.At_qd2 = s.A.transpose() * qd2.asDiagonal();
  const Eigen::MatrixXd& At_qd2 = s.At_qd2;
  s.qp.H = 2.0 * kDemandWeight * At_qd2 * s.A;
  s.qp.H.diagonal() += 2.0 * weight;
  s.qp.c = -2.0 * kDemandWeight * At_qd2 * tau_d_b;
  const auto m = static_cast<Eigen::Index>(rows.rows.size());
  s.qp.G = Eigen::MatrixXd::Zero(m, n);
  s.qp.h.resize(m);
  for (std::size_t k = 0; k < units_.size(); ++k) {  // each unit's variables a block
    s.qp.block_start.push_back(s.offset[k]);
    s.qp.block_size.push_back(variable_count(units_[k].type));
  }
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto& [a, b] = rows.rows[static_cast<std::size_t>(i)];
    const Eigen::Index o = rows.column[static_cast<std::size_t>(i)];
    s.row_unit.push_back(static_cast<std::size_t>(
        std::upper_bound(s.offset.begin(), s.offset.end(), o) - s.offset.begin() - 1));
    s.row_limit.push_back(rows.limit[static_cast<std::size_t>(i)]);
    s.qp.row_block.push_back(static_cast<int>(s.row_unit.back()));
    s.qp.G(i, o) = a(0);
    if (rows.width[static_cast<std::size_t>(i)] == 2) s.qp.G(i, o + 1) = a(1);
    // Moved out by 10⁻⁹ of the rating, each by its own amount: the cone and wedge sides all
    // meet at the origin, where the active-set method could cycle among them (degeneracy);
    // solve() projects each unit back into its region exactly.
    s.qp.h(i) = b + 1e-9 * (1.0 + 0.1 * static_cast<double>(i % 10));
  }
  return s;
}

std::shared_ptr<const LayoutAllocator::Setup> LayoutAllocator::setup(
    const Eigen::Vector3d& tau_d_b, const std::vector<double>& capacity,
    const std::vector<int>& regions, AllocationWarmStart* warm) const {
  if (warm == nullptr) return std::make_shared<const Setup>(setup(tau_d_b, capacity, regions));
  std::shared_ptr<void>& cached = warm->setups_[regions];
  if (!cached) {
    cached = std::make_shared<Setup>(setup(tau_d_b, capacity, regions));
    return std::static_pointer_cast<const Setup>(cached);
  }
  const auto s = std::static_pointer_cast<Setup>(cached);
  s->qp.c = -2.0 * kDemandWeight * s->At_qd2 * tau_d_b;  // as setup() does
  return s;
}

void LayoutAllocator::project(const Setup& s, Eigen::VectorXd& x) const {
  for (std::size_t k = 0; k < units_.size(); ++k) {
    const ThrusterUnit& u = units_[k];
    const Eigen::Index o = s.offset[k];
    const int region = s.regions[k];
    const double rated = std::max(u.max_thrust_N, u.max_reverse_thrust_N);
    const double ahead = u.max_thrust_N / rated;
    const double astern = u.max_reverse_thrust_N / rated;
    if (u.type == UnitType::kTunnel || u.type == UnitType::kPropeller) {
      x(o) = std::clamp(x(o), -astern, ahead);
    } else if (u.type == UnitType::kPropellerRudder) {
      const double lift_max = s.scale(o + 1);
      const double a = lift_max > 0.0 ? u.rudder_lift_per_thrust * s.scale(o) / lift_max : 0.0;
      const double b = lift_max > 0.0 ? u.rudder_lift_at_zero_N / lift_max : 0.0;
      const double lo = region == 0 ? 0.0 : -astern;
      x(o) = std::clamp(x(o), lo, region == 1 ? 0.0 : ahead);
      const double y_max = std::min(region == kRelaxed ? 1.0 : (region == 0 ? a * x(o) + b : b),
                                    lift_max > 0.0 ? 1.0 : 0.0);
      x(o + 1) = std::clamp(x(o + 1), -y_max, y_max);
    } else {
      Eigen::Vector2d v = x.segment(o, 2);
      if (region != kRelaxed && arcs_[k][region].span_rad < kTwoPi) {
        // Onto the nearer edge ray of the arc when the direction left it.
        const AllowedArc& arc = arcs_[k][region];
        const double after = angle_after(std::atan2(v.y(), v.x()), arc.from_rad);
        if (after > arc.span_rad) {
          const double edge =
              after - arc.span_rad < kTwoPi - after ? arc.from_rad + arc.span_rad : arc.from_rad;
          const Eigen::Vector2d ray{std::cos(edge), std::sin(edge)};
          v = std::max(v.dot(ray), 0.0) * ray;
        }
      }
      double largest = 0.0;  // the polygon's most violated side, as n·v over its distance
      if (pieces_[k].empty()) {
        for (const Eigen::Vector2d& normal : side_normals_) {
          largest = std::max(largest, normal.dot(v) / side_distance_);
        }
      } else {
        for_each_side(k, region, [&](const Eigen::Vector2d& n, double d) {
          largest = std::max(largest, n.dot(v) / d);
        });
      }
      if (largest > 1.0) v /= largest;
      x.segment(o, 2) = v;
    }
  }
}

LayoutAllocation LayoutAllocator::solve(const Setup& s, const Eigen::Vector3d& tau_d_b,
                                        bool least_effort, AllocationWarmStart* warm,
                                        const Eigen::VectorXd* x0) const {
  const AllocationWarmStart::Solution* start = nullptr;
  if (warm) {
    const auto it = warm->by_regions_.find(s.regions);
    if (it != warm->by_regions_.end() && it->second.x.size() == s.qp.c.size()) {
      start = &it->second;  // the same regions and capacity: the same constraints, so feasible
    }
  }
  detail::QpSolution q = start ? detail::solve_convex_qp(s.qp, start->x, start->working)
                         : x0  ? detail::solve_convex_qp(s.qp, *x0)
                              : detail::solve_convex_qp(s.qp, Eigen::VectorXd::Zero(s.qp.c.size()));
  if (warm) warm->by_regions_[s.regions] = {q.x, q.working};
  // The active-set iterates hold the constraints to round-off, which an ill-conditioned
  // demand term can grow to 10⁻⁵ of a rating: each unit is put back into its region exactly.
  project(s, q.x);
  int programmes = 1, iterations = q.iterations;
  const Eigen::Vector3d d{1.0 / options_.force_scale, 1.0 / options_.force_scale,
                          1.0 / options_.moment_scale};
  const Eigen::Vector3d unmet_n = d.cwiseProduct(tau_d_b - s.A * q.x);
  if (least_effort && unmet_n.cwiseAbs().maxCoeff() > kMetTolerance) {
    // Unmet, the effort ρ outweighs is lost in round-off of the demand term: hold what was
    // achieved (to 10⁻⁹ of the scales) and minimise the effort alone, from there.
    const Eigen::Index n = q.x.size(), m = s.qp.G.rows();
    detail::ConvexQp effort;
    effort.H = s.qp.H.diagonal().asDiagonal();
    effort.H.diagonal() -= (2.0 * kDemandWeight * s.A.transpose() *
                            (options_.priority.cwiseProduct(d).cwiseProduct(d)).asDiagonal() * s.A)
                               .diagonal();
    effort.c = Eigen::VectorXd::Zero(n);
    effort.G.resize(m + 6, n);
    effort.h.resize(m + 6);
    effort.G.topRows(m) = s.qp.G;
    effort.h.head(m) = s.qp.h;
    const Eigen::MatrixXd DA = d.asDiagonal() * s.A;
    const Eigen::Vector3d achieved = DA * q.x;
    effort.G.middleRows(m, 3) = DA;
    effort.G.bottomRows(3) = -DA;
    effort.h.segment(m, 3) = achieved.array() + 1e-9;
    effort.h.tail(3) = -achieved.array() + 1e-9;
    const detail::QpSolution e = detail::solve_convex_qp(effort, q.x);
    q.x = e.x;
    project(s, q.x);
    ++programmes;
    iterations += e.iterations;
  }
  LayoutAllocation out;
  out.programmes = programmes;
  out.iterations = iterations;
  const Eigen::VectorXd f = s.scale.cwiseProduct(q.x);
  for (std::size_t k = 0; k < units_.size(); ++k) {
    const ThrusterUnit& u = units_[k];
    const Eigen::Index o = s.offset[k];
    UnitCommand c;
    switch (u.type) {
      case UnitType::kAzimuth: {
        c.force_b = f.segment(o, 2);
        c.thrust_N = c.force_b.norm();
        const int region = s.regions[k];
        if (c.thrust_N > 1e-9 * std::max(s.scale(o), 1.0)) {
          c.angle_rad = wrap_2pi(std::atan2(c.force_b.y(), c.force_b.x()));
        } else {  // no thrust: point along the middle of the arc it was allocated in
          c.force_b.setZero();
          c.thrust_N = 0.0;
          c.angle_rad = region == kRelaxed
                            ? arcs_[k].front().from_rad
                            : wrap_2pi(arcs_[k][region].from_rad + 0.5 * arcs_[k][region].span_rad);
        }
        break;
      }
      case UnitType::kTunnel:
        c.thrust_N = f(o);
        c.force_b = {0.0, f(o)};
        break;
      case UnitType::kPropeller:
        c.thrust_N = f(o);
        c.force_b = {f(o), 0.0};
        break;
      case UnitType::kPropellerRudder:
        c.thrust_N = f(o);
        c.rudder_force_N = f(o + 1);
        c.force_b = {f(o), f(o + 1)};
        break;
    }
    out.units.push_back(c);
  }
  const Eigen::VectorXd gx = s.qp.G * q.x;  // one product, not a strided row at a time
  for (Eigen::Index i = 0; i < s.qp.G.rows(); ++i) {
    const std::size_t k = s.row_unit[static_cast<std::size_t>(i)];
    UnitCommand& c = out.units[k];
    const bool moving = c.force_b.norm() > 1e-9 * std::max(units_[k].max_thrust_N, 1.0);
    if (moving && s.row_limit[static_cast<std::size_t>(i)] && gx(i) >= s.qp.h(i) - 2e-3) {
      c.at_limit = true;
    }
  }
  out.tau_achieved_b = s.A * q.x;
  out.tau_unmet_b = tau_d_b - out.tau_achieved_b;
  const Eigen::Vector3d unmet{out.tau_unmet_b(0) / options_.force_scale,
                              out.tau_unmet_b(1) / options_.force_scale,
                              out.tau_unmet_b(2) / options_.moment_scale};
  out.met = unmet.cwiseAbs().maxCoeff() <= kMetTolerance;
  return out;
}

std::vector<int> LayoutAllocator::nearest_regions(const LayoutAllocation& relaxed) const {
  std::vector<int> regions(units_.size(), 0);
  for (std::size_t k = 0; k < units_.size(); ++k) {
    const UnitCommand& c = relaxed.units[k];
    if (units_[k].type == UnitType::kPropellerRudder) {
      regions[k] = c.thrust_N >= 0.0 ? 0 : 1;
    } else if (units_[k].type == UnitType::kAzimuth && arcs_[k].size() > 1) {
      // The arc holding the relaxed direction, else the one whose edge is nearest to it.
      double best = kTwoPi;
      for (std::size_t j = 0; j < arcs_[k].size(); ++j) {
        const AllowedArc& arc = arcs_[k][j];
        const double after = angle_after(c.angle_rad, arc.from_rad);
        const double distance =
            after <= arc.span_rad ? 0.0 : std::min(after - arc.span_rad, kTwoPi - after);
        if (distance < best) {
          best = distance;
          regions[k] = static_cast<int>(j);
        }
      }
    }
  }
  return regions;
}

namespace {

// Whether a relaxed command lies in the unit's true region (to 10⁻⁹ of its rating), a loss
// table's pieces aside (LayoutAllocator::in_region).
bool in_basic_region(const ThrusterUnit& u, const UnitCommand& c) {
  const double tol = 1e-9 * std::max(u.max_thrust_N, 1.0);
  if (u.type == UnitType::kAzimuth) {
    return c.thrust_N <= tol || !in_forbidden_sector(c.angle_rad, u.forbidden_deg);
  }
  if (u.type == UnitType::kPropellerRudder) {
    double lift = c.thrust_N >= 0.0
                      ? u.rudder_lift_per_thrust * c.thrust_N + u.rudder_lift_at_zero_N
                      : u.rudder_lift_at_zero_N;
    if (u.rudder_max_force_N > 0.0) lift = std::min(lift, u.rudder_max_force_N);
    return std::abs(c.rudder_force_N) <= lift + tol;
  }
  return true;
}

}  // namespace

bool LayoutAllocator::in_region(std::size_t k, const UnitCommand& c) const {
  const ThrusterUnit& u = units_[k];
  if (!in_basic_region(u, c)) return false;
  if (pieces_[k].empty()) return true;
  // In some piece: its wedge holds the direction and its edges the force (over the rating).
  const double tol = 1e-9;
  const Eigen::Vector2d v = c.force_b / std::max(u.max_thrust_N, 1.0);
  if (v.norm() <= tol) return true;
  for (const ConvexPiece& p : pieces_[k]) {
    const double after = angle_after(c.angle_rad, p.wedge.from_rad);
    if (p.wedge.span_rad < kTwoPi && after > p.wedge.span_rad + tol) continue;
    bool inside = true;
    for (std::size_t i = 0; i < p.normals.size() && inside; ++i) {
      inside = p.normals[i].dot(v) <= p.distances[i] + tol;
    }
    if (inside) return true;
  }
  return false;
}

LayoutAllocation LayoutAllocator::allocate(const Eigen::Vector3d& tau_d_b,
                                           const std::vector<double>& capacity) const {
  // A demand beyond 10⁶ times the scales (10¹¹ N by default) is no physical one, and its square
  // in the programme would overflow: it is allocated at that size, in its direction.
  const double size = std::max({std::abs(tau_d_b(0)) / options_.force_scale,
                                std::abs(tau_d_b(1)) / options_.force_scale,
                                std::abs(tau_d_b(2)) / options_.moment_scale});
  if (std::isfinite(size) && size > kLargestDemand) {
    LayoutAllocation a = allocate(tau_d_b * (kLargestDemand / size), capacity);
    a.tau_unmet_b = tau_d_b - a.tau_achieved_b;
    a.met = false;
    return a;
  }
  const bool capacity_ok =
      (capacity.empty() || capacity.size() == units_.size()) &&
      std::all_of(capacity.begin(), capacity.end(), [](double c) { return c >= 0.0 && c <= 1.0; });
  if (!tau_d_b.allFinite() || !capacity_ok) {
    LayoutAllocation zero;
    zero.met = false;
    zero.units.resize(units_.size());
    zero.tau_unmet_b = tau_d_b;
    return zero;
  }
  LayoutAllocation relaxed =
      solve(setup(tau_d_b, capacity, std::vector<int>(units_.size(), kRelaxed)), tau_d_b);
  bool feasible = true;
  for (std::size_t k = 0; k < units_.size() && feasible; ++k) {
    feasible = in_region(k, relaxed.units[k]);
  }
  if (feasible && relaxed.met) return relaxed;  // the relaxation's optimum is the problem's
  if (feasible) {  // unmet: the least effort in the regions the relaxed commands lie in
    LayoutAllocation least =
        solve(setup(tau_d_b, capacity, nearest_regions(relaxed)), tau_d_b, true);
    least.programmes += relaxed.programmes;
    least.iterations += relaxed.iterations;
    return least;
  }

  int programmes = relaxed.programmes, iterations = relaxed.iterations;
  const std::vector<int> guess = nearest_regions(relaxed);
  std::vector<int> best_regions = guess;
  LayoutAllocation best = solve(setup(tau_d_b, capacity, guess), tau_d_b);
  programmes += best.programmes;
  iterations += best.iterations;
  if (!best.met) {
    // Every combination of regions, in order, up to the cap: the least weighted unmet part.
    const auto unmet_of = [&](const LayoutAllocation& a) {
      const Eigen::Vector3d d{a.tau_unmet_b(0) / options_.force_scale,
                              a.tau_unmet_b(1) / options_.force_scale,
                              a.tau_unmet_b(2) / options_.moment_scale};
      return d.cwiseProduct(d).dot(options_.priority);
    };
    std::vector<int> regions(units_.size(), 0);
    for (int tried = 0; tried < options_.max_region_combinations; ++tried) {
      if (regions != guess) {
        LayoutAllocation a = solve(setup(tau_d_b, capacity, regions), tau_d_b);
        programmes += a.programmes;
        iterations += a.iterations;
        if (unmet_of(a) < unmet_of(best) * (1.0 - 1e-9) - 1e-18) {
          best = std::move(a);
          best_regions = regions;
        }
      }
      std::size_t k = 0;  // the next combination, as an odometer
      for (; k < units_.size(); ++k) {
        if (++regions[k] < region_count(k)) break;
        regions[k] = 0;
      }
      if (k == units_.size()) break;
    }
  }
  if (!best.met) {  // the least effort for the least unmet part
    best = solve(setup(tau_d_b, capacity, best_regions), tau_d_b, true);
    programmes += best.programmes;
    iterations += best.iterations;
  }
  best.programmes = programmes;
  best.iterations = iterations;
  return best;
}

LayoutAllocation LayoutAllocator::allocate(const Eigen::Vector3d& tau_d_b,
                                           const std::vector<double>& capacity,
                                           const AllocationRates& rates) const {
  LayoutAllocation free = allocate(tau_d_b, capacity);
  // allocate()'s own answers to a demand or capacity it does not solve stand as they are.
  const double size = std::max({std::abs(tau_d_b(0)) / options_.force_scale,
                                std::abs(tau_d_b(1)) / options_.force_scale,
                                std::abs(tau_d_b(2)) / options_.moment_scale});
  const bool capacity_ok =
      (capacity.empty() || capacity.size() == units_.size()) &&
      std::all_of(capacity.begin(), capacity.end(), [](double c) { return c >= 0.0 && c <= 1.0; });
  if (!tau_d_b.allFinite() || !(size <= kLargestDemand) || !capacity_ok ||
      rates.previous == nullptr || rates.previous->units.size() != units_.size() ||
      !(rates.dt_s > 0.0)) {
    return free;
  }
  Setup s = setup(tau_d_b, capacity, nearest_regions(free));
  // The previous forces over this allocation's scales: the start, inside every rate box.
  const Eigen::Index n = s.qp.c.size();
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(n);
  const auto over = [&](double f, Eigen::Index j) {
    return s.scale(j) > 0.0 ? f / s.scale(j) : 0.0;
  };
  for (std::size_t k = 0; k < units_.size(); ++k) {
    const UnitCommand& c = rates.previous->units[k];
    const Eigen::Index o = s.offset[k];
    if (units_[k].type == UnitType::kAzimuth) {
      x0(o) = over(c.force_b.x(), o);
      x0(o + 1) = over(c.force_b.y(), o + 1);
    } else {
      x0(o) = over(c.thrust_N, o);
      if (units_[k].type == UnitType::kPropellerRudder) x0(o + 1) = over(c.rudder_force_N, o + 1);
    }
  }
  const Eigen::VectorXd gx = s.qp.G * x0;
  for (Eigen::Index i = 0; i < gx.size(); ++i) {
    if (gx(i) > s.qp.h(i) + 1e-9 * (1.0 + std::abs(s.qp.h(i)))) return free;  // another region
  }
  // Two rows per variable: |x_j − x0_j| ≤ rate·dt/s_j, on the variable's block.
  const Eigen::Index m = s.qp.G.rows();
  s.qp.G.conservativeResize(m + 2 * n, Eigen::NoChange);
  s.qp.h.conservativeResize(m + 2 * n);
  s.qp.G.bottomRows(2 * n).setZero();
  for (std::size_t k = 0; k < units_.size(); ++k) {
    const double rate = units_[k].thrust_rate_N_per_s.value_or(
        std::max(units_[k].max_thrust_N, units_[k].max_reverse_thrust_N) /
        (4.0 * drive_params(units_[k]).time_constant_s));
    for (int v = 0; v < s.qp.block_size[k]; ++v) {
      const Eigen::Index j = s.offset[k] + v;
      const double step = s.scale(j) > 0.0 ? rate * rates.dt_s / s.scale(j) : 0.0;
      const Eigen::Index up = m + 2 * j, down = up + 1;
      s.qp.G(up, j) = 1.0;
      s.qp.h(up) = x0(j) + step;
      s.qp.G(down, j) = -1.0;
      s.qp.h(down) = -x0(j) + step;
      s.qp.row_block.push_back(static_cast<int>(k));
      s.qp.row_block.push_back(static_cast<int>(k));
      s.row_unit.push_back(k);
      s.row_unit.push_back(k);
      s.row_limit.push_back(false);
      s.row_limit.push_back(false);
    }
  }
  LayoutAllocation rated = solve(s, tau_d_b, false, nullptr, &x0);
  rated.programmes += free.programmes;
  rated.iterations += free.iterations;
  return rated;
}

bool LayoutAllocator::attainable(const Eigen::Vector3d& tau_d_b,
                                 const std::vector<double>& capacity,
                                 AllocationWarmStart* warm) const {
  const double size = std::max({std::abs(tau_d_b(0)) / options_.force_scale,
                                std::abs(tau_d_b(1)) / options_.force_scale,
                                std::abs(tau_d_b(2)) / options_.moment_scale});
  if (!std::isfinite(size) || size > kLargestDemand) return allocate(tau_d_b, capacity).met;
  const bool capacity_ok =
      (capacity.empty() || capacity.size() == units_.size()) &&
      std::all_of(capacity.begin(), capacity.end(), [](double c) { return c >= 0.0 && c <= 1.0; });
  if (!tau_d_b.allFinite() || !capacity_ok) return false;
  if (warm && (warm->owner_ != this || warm->capacity_ != capacity)) {
    warm->owner_ = this;
    warm->capacity_ = capacity;
    warm->by_regions_.clear();
    warm->setups_.clear();
  }
  // The relaxation's regions hold the true ones: what it misses, they miss too.
  const LayoutAllocation relaxed =
      solve(*setup(tau_d_b, capacity, std::vector<int>(units_.size(), kRelaxed), warm), tau_d_b,
            false, warm);
  if (!relaxed.met) return false;
  bool feasible = true;
  for (std::size_t k = 0; k < units_.size() && feasible; ++k) {
    feasible = in_region(k, relaxed.units[k]);
  }
  if (feasible) return true;
  const std::vector<int> guess = nearest_regions(relaxed);
  if (solve(*setup(tau_d_b, capacity, guess, warm), tau_d_b, false, warm).met) return true;
  // The units of one region are in it from the start: an azimuth with one allowed arc has its
  // arc there, its relaxation being the whole polygon.
  std::vector<int> regions(units_.size(), kRelaxed);
  for (std::size_t k = 0; k < units_.size(); ++k) {
    if (region_count(k) == 1) regions[k] = 0;
  }
  int budget = 2 * options_.max_region_combinations;
  return search_regions({tau_d_b, capacity, warm}, regions, 0, budget);
}

bool LayoutAllocator::search_regions(const Question& q, std::vector<int>& regions, std::size_t from,
                                     int& budget) const {
  std::size_t k = from;  // the next unit with more than one region
  while (k < units_.size() && region_count(k) <= 1) ++k;
  if (k == units_.size()) return false;
  for (int r = 0; r < region_count(k) && budget > 0; ++r, --budget) {
    regions[k] = r;
    const LayoutAllocation a =
        solve(*setup(q.tau_d_b, q.capacity, regions, q.warm), q.tau_d_b, false, q.warm);
    if (!a.met) continue;  // the units after k relaxed miss it: so does every choice of theirs
    bool feasible = true;
    for (std::size_t j = k + 1; j < units_.size() && feasible; ++j) {
      feasible = in_region(j, a.units[j]);
    }
    if (feasible || search_regions(q, regions, k + 1, budget)) return true;
  }
  regions[k] = kRelaxed;
  return false;
}

}  // namespace dynpos::model
