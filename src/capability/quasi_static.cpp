#include "dynpos/capability/quasi_static.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "dynpos/capability/feasibility.hpp"
#include "dynpos/capability/thrust_region.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/model/environment.hpp"
#include "dynpos/model/hull.hpp"
#include "dynpos/model/sea_state.hpp"

namespace dynpos::capability {
namespace {

constexpr double kPi = std::numbers::pi;
// `limiting` where nothing but the calm (or not even the first row) holds.
constexpr const char* kNoThrustLeft = "no thrust left for the weather";

model::ThrustAllocator allocator_of(const scenario::VesselConfig& v,
                                    const std::vector<std::string>& failed) {
  return model::ThrustAllocator(
      model::Thruster(v.propeller), model::Rudder(v.rudder), model::TunnelThruster(v.tunnel),
      model::ThrustConfiguration(v.layout), with_failures(v.allocation, failed));
}

// Whether the thrusters hold the environment of one wind from one direction, and which
// actuators are at a limit when they do: the model's own units (thrust_region.hpp) or a
// [[thruster]] layout (model/layout_allocator.hpp).
class WindCheck {
 public:
  virtual ~WindCheck() = default;
  virtual bool holds(double wind_mps) const = 0;
  /// The actuators that limit the wind held, joined by '+'; "none" if none is at a limit.
  /// `held_mps` is the strongest wind held, `not_held_mps` the first not held above it, within
  /// the bisection's tolerance.
  virtual std::string limiting(double held_mps, double not_held_mps) const = 0;
};

std::string joined_or_none(const std::vector<std::string>& names) {
  return names.empty() ? "none" : fmt::format("{}", fmt::join(names, "+"));
}

// The mean load the thrusters must give at wind w: the reserve times the environment's, reversed.
Eigen::Vector3d demand_b(const scenario::VesselConfig& vessel, const QuasiStaticOptions& options,
                         const Environment& e, double from_rel_rad) {
  return -options.dynamic_allowance * mean_environment_load_b(vessel, e, from_rel_rad);
}

class ModelCheck final : public WindCheck {
 public:
  ModelCheck(const scenario::VesselConfig& vessel, const std::vector<std::string>& failed,
             double from_rel_rad, const QuasiStaticOptions& options)
      : vessel_(vessel),
        allocator_(allocator_of(vessel, failed)),
        from_(from_rel_rad),
        options_(options) {}
  bool holds(double wind_mps) const override { return attained(wind_mps).has_value(); }
  // The exact region's vertex at the wind held touches the limits that bind.
  std::string limiting(double held_mps, double /*not_held_mps*/) const override {
    const auto a = attained(held_mps);
    std::vector<std::string> names;
    for (std::size_t k = 0; a && k < a->at_limit.size(); ++k) {
      if (a->at_limit[k]) names.emplace_back(actuator_names()[k]);
    }
    return joined_or_none(names);
  }

 private:
  std::optional<Attainment> attained(double wind_mps) const {
    const Environment e = options_.environment.at(wind_mps);
    const double inflow = options_.level >= 2 ? current_inflow_mps(e.current_mps, from_) : 0.0;
    return attain(thrust_limits(allocator_, inflow, options_.level >= 2),
                  demand_b(vessel_, options_, e, from_));
  }
  const scenario::VesselConfig& vessel_;
  model::ThrustAllocator allocator_;
  double from_;
  const QuasiStaticOptions& options_;
};

// Every failure of `failed` at once: the product of their capacities.
std::vector<double> capacity_of(const std::vector<model::ThrusterUnit>& units,
                                const std::vector<std::string>& failed) {
  std::vector<double> capacity(units.size(), 1.0);
  for (const std::string& name : failed) {
    const FailureCase c = failure_case(units, name);
    for (std::size_t k = 0; k < units.size(); ++k) capacity[k] *= c.capacity[k];
  }
  return capacity;
}

// A [[thruster]] layout holds its units' ratings at every level: the units have no propeller
// model for the current's inflow (docs/vessel-file.md).
class LayoutCheck final : public WindCheck {
 public:
  LayoutCheck(const scenario::VesselConfig& vessel, const std::vector<std::string>& failed,
              double from_rel_rad, const QuasiStaticOptions& options)
      : vessel_(vessel),
        allocator_(vessel.thrusters),
        capacity_(capacity_of(vessel.thrusters, failed)),
        from_(from_rel_rad),
        options_(options) {}
  bool holds(double wind_mps) const override {
    return allocator_.attainable(demand(wind_mps), capacity_, &warm_);
  }
  // The allocation of the first wind not held, which leaves a part unmet: the units at a limit
  // there bind. At the wind held they can still be a tolerance's load short of their limits
  // (0.01 m/s of wind can be more than the allocator's 0.2 % band of a rating).
  std::string limiting(double /*held_mps*/, double not_held_mps) const override {
    const model::LayoutAllocation a = allocator_.allocate(demand(not_held_mps), capacity_);
    std::vector<std::string> names;
    for (std::size_t k = 0; k < a.units.size(); ++k) {
      if (a.units[k].at_limit) names.push_back(vessel_.thrusters[k].name);
    }
    return joined_or_none(names);
  }

 private:
  Eigen::Vector3d demand(double wind_mps) const {
    return demand_b(vessel_, options_, options_.environment.at(wind_mps), from_);
  }
  const scenario::VesselConfig& vessel_;
  model::LayoutAllocator allocator_;
  std::vector<double> capacity_;
  mutable model::AllocationWarmStart warm_;  // the bisection's questions are close together
  double from_;
  const QuasiStaticOptions& options_;
};

std::unique_ptr<WindCheck> wind_check(const scenario::VesselConfig& vessel,
                                      const std::vector<std::string>& failed, double from_rel_rad,
                                      const QuasiStaticOptions& options) {
  if (vessel.thrusters.empty()) {
    return std::make_unique<ModelCheck>(vessel, failed, from_rel_rad, options);
  }
  return std::make_unique<LayoutCheck>(vessel, failed, from_rel_rad, options);
}

}  // namespace

Eigen::Vector3d mean_environment_load_b(const scenario::VesselConfig& vessel,
                                        const Environment& environment, double from_rel_rad) {
  const Eigen::Vector3d wind = model::wind_force_b(vessel.wind, environment.wind_mps, from_rel_rad);
  // The waves travel towards from + π off the bow.
  const Eigen::Vector3d drift =
      model::drift_force_b(vessel.waves, environment.hs_m, from_rel_rad + kPi);
  // The water flows past the vessel at rest from the current's direction: ν_r = ν − ν_c.
  const Eigen::Vector3d nu_r(environment.current_mps * std::cos(from_rel_rad),
                             environment.current_mps * std::sin(from_rel_rad), 0.0);
  const Eigen::Vector3d current =
      model::Hull(vessel.hull).hydrodynamic_forces(Eigen::Vector3d::Zero(), nu_r);
  return wind + drift + current;
}

double current_inflow_mps(double current_mps, double from_rel_rad) {
  return current_mps * std::cos(from_rel_rad);
}

CapabilityPoint quasi_static_point(const scenario::VesselConfig& vessel,
                                   const std::vector<std::string>& failed, double from_rel_rad,
                                   const QuasiStaticOptions& options) {
  const std::unique_ptr<WindCheck> check = wind_check(vessel, failed, from_rel_rad, options);
  const auto& rows = options.environment.rows;
  CapabilityPoint p;
  p.direction_deg = from_rel_rad * 180.0 / kPi;
  p.failure = failed.empty() ? "none" : failed.front();
  // Step up the rows (DNV: every number below must hold too), then bisect between the last
  // row held and the first that is not.
  std::size_t held = 0;
  if (!check->holds(rows[0].wind_mps)) {  // even the first row (e.g. a site's current) is too much
    p.limiting = kNoThrustLeft;
    return p;
  }
  while (held + 1 < rows.size() && check->holds(rows[held + 1].wind_mps)) ++held;
  p.dp_number = static_cast<int>(held);
  if (held + 1 == rows.size()) {
    p.max_wind_mps = rows.back().wind_mps;
    p.beyond_table = true;
    p.limiting = "none";
    return p;
  }
  double lo = rows[held].wind_mps;
  double hi = rows[held + 1].wind_mps;
  for (int k = 0; bisect_further(lo, hi, options.wind_tolerance_mps, k); ++k) {
    const double mid = 0.5 * (lo + hi);
    (check->holds(mid) ? lo : hi) = mid;
  }
  p.max_wind_mps = lo;
  p.limiting = lo > 0.0 ? check->limiting(lo, hi) : kNoThrustLeft;
  return p;
}

void check_direction_step(double step_deg) {
  const double n = 360.0 / step_deg;
  if (!std::isfinite(step_deg) || !(step_deg > 0.0) || step_deg > 360.0 || !std::isfinite(n) ||
      std::abs(n - std::round(n)) > 1e-9 || n > 3600) {
    throw core::InputError::for_option(
        "direction_step",
        fmt::format("{} deg does not divide 360 (a step of 0.1 to 360 deg)", step_deg),
        "e.g. 5, 10, 15 or 30");
  }
}

void check_wind_tolerance(double tolerance_mps) {
  if (!(tolerance_mps >= kMinWindTolerance_mps && tolerance_mps <= kMaxWindTolerance_mps)) {
    throw core::InputError::for_option(
        "wind_tolerance",
        fmt::format("the wind tolerance must be from {:g} to {:g} m/s, got {}",
                    kMinWindTolerance_mps, kMaxWindTolerance_mps, tolerance_mps),
        "e.g. 0.01 (levels 1, 2) or 0.25 (level 3)");
  }
}

bool bisect_further(double lo, double hi, double tolerance, int halvings) {
  const double mid = 0.5 * (lo + hi);
  return hi - lo > tolerance && halvings < kMaxBisections && lo < mid && mid < hi;
}

void QuasiStaticOptions::validate() const {
  if (level != 1 && level != 2) {
    throw core::InputError::for_option("level", fmt::format("level {} is not quasi-static", level));
  }
  if (!(dynamic_allowance >= 1.0) || !std::isfinite(dynamic_allowance)) {
    throw core::InputError::for_option(
        "dynamic_allowance",
        fmt::format("the reserve factor must be ≥ 1, got {}", dynamic_allowance));
  }
  check_direction_step(direction_step_deg);
  check_wind_tolerance(wind_tolerance_mps);
  environment.validate();
}

std::vector<CapabilityPoint> quasi_static_rose(const scenario::VesselConfig& vessel,
                                               const std::vector<std::string>& failed,
                                               const QuasiStaticOptions& options) {
  options.validate();
  std::vector<CapabilityPoint> rose;
  const int n = static_cast<int>(std::lround(360.0 / options.direction_step_deg));
  for (int i = 0; i < n; ++i) {
    const double deg = i * options.direction_step_deg;
    rose.push_back(quasi_static_point(vessel, failed, deg * kPi / 180.0, options));
    rose.back().direction_deg = deg;
  }
  return rose;
}

std::vector<std::string> single_failures(const scenario::VesselConfig& vessel) {
  if (vessel.thrusters.empty()) {
    const auto& names = actuator_names();
    return {names.begin(), names.end()};
  }
  const std::vector<FailureCase> cases = failure_cases(vessel.thrusters);
  std::vector<std::string> out;
  for (auto c = cases.begin() + 1; c != cases.end(); ++c) out.push_back(c->name);  // not intact
  return out;
}

void check_failure(const scenario::VesselConfig& vessel, const std::string& name, const char* key) {
  const std::vector<std::string> names = single_failures(vessel);
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  const std::string what =
      vessel.thrusters.empty()
          ? fmt::format("unknown actuator '{}'", name)
          : fmt::format("no unit or group '{}' in the layout of {}", name, vessel.source);
  throw core::InputError::for_option(key, what, fmt::format("one of {}", fmt::join(names, ", ")));
}

std::vector<CapabilityPoint> worst_case(const std::vector<std::vector<CapabilityPoint>>& roses) {
  std::vector<CapabilityPoint> worst = roses.at(0);
  for (const auto& rose : roses) {
    for (std::size_t i = 0; i < rose.size(); ++i) {
      if (rose[i].max_wind_mps < worst[i].max_wind_mps) worst[i] = rose[i];
    }
  }
  return worst;
}

}  // namespace dynpos::capability
