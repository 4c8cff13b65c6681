#include "dynpos/capability/time_domain.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <thread>
#include <utility>

#include "dynpos/capability/feasibility.hpp"
#include "dynpos/capability/thrust_region.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/model/environment.hpp"
#include "dynpos/model/sea_state.hpp"
#include "dynpos/scenario/runner.hpp"

namespace dynpos::capability {
namespace {

double wrap_deg(double deg) { return std::remainder(deg, 360.0); }

scenario::ScenarioSpec hold_spec(const Environment& e, double from_deg,
                                 const TimeDomainOptions& o) {
  scenario::ScenarioSpec spec;
  spec.name = fmt::format("capability-{:.0f}", from_deg);
  spec.description = "DP capability run: position hold at heading 0";
  spec.duration_s = o.settle_s + o.duration_s;
  spec.log_rate_hz = 1.0;
  spec.environment.wind_speed_mps = e.wind_mps;
  spec.environment.wind_from_deg = from_deg;
  spec.environment.current_speed_mps = e.current_mps;
  spec.environment.current_to_deg = wrap_deg(from_deg + 180.0);
  spec.environment.hs_m = e.hs_m;
  spec.environment.tp_s = e.hs_m > 0.0 ? e.tp_s : spec.environment.tp_s;
  spec.environment.wave_from_deg = from_deg;
  spec.setpoints.push_back({0.0, 0.0, 0.0, 0.0, "hold"});
  return spec;
}

// Whether the simulator takes this environment (its ranges of wind and waves).
bool simulable(const Environment& e) {
  return e.wind_mps <= model::kWindSpeedRange.hi && e.hs_m <= model::kSignificantWaveHeightRange.hi;
}

// The last row that holds, searched from `guess` (the quasi-static balance's row): up while
// the rows hold, or down until one does. A row that holds is taken to hold every row below it
// (the loads grow with the row), so a good guess costs two runs instead of one per row. The
// calm row holds by definition (no load). Returns the row and the failing run above it (none
// when the last row the simulator takes holds).
std::pair<std::size_t, std::optional<RunVerdict>> last_row_held(
    const std::function<RunVerdict(double)>& run, const std::vector<Environment>& rows,
    std::size_t guess) {
  std::size_t top = 0;
  while (top + 1 < rows.size() && simulable(rows[top + 1])) ++top;
  std::size_t row = std::min(std::max<std::size_t>(guess, 1), top);
  if (top == 0) return {0, std::nullopt};
  RunVerdict v = run(rows[row].wind_mps);
  if (v.holds) {
    while (row < top) {
      RunVerdict up = run(rows[row + 1].wind_mps);
      if (!up.holds) return {row, std::move(up)};
      ++row;
    }
    return {top, std::nullopt};
  }
  while (row > 1) {
    RunVerdict down = run(rows[row - 1].wind_mps);
    if (down.holds) return {row - 1, std::move(v)};
    v = std::move(down);
    --row;
  }
  return {0, std::move(v)};
}

CapabilityPoint search_direction(const scenario::VesselConfig& vessel,
                                 const std::vector<std::string>& failed, double from_deg,
                                 const TimeDomainOptions& o) {
  const auto& rows = o.environment.rows;
  CapabilityPoint p;
  p.direction_deg = from_deg;
  p.failure = failed.empty() ? "none" : failed.front();
  const std::function<RunVerdict(double)> run = [&](double w) {
    return time_domain_run(vessel, failed, o.environment.at(w), from_deg, o);
  };
  QuasiStaticOptions balance;  // the same mean load and thrust losses, without the reserve
  balance.level = 2;
  balance.environment = o.environment;
  balance.dynamic_allowance = 1.0;
  const std::size_t guess = static_cast<std::size_t>(
      quasi_static_point(vessel, failed, from_deg * std::numbers::pi / 180.0, balance).dp_number);
  const auto [held, fail_above] = last_row_held(run, rows, guess);
  p.dp_number = static_cast<int>(held);
  if (!fail_above) {  // the table's (or the simulator's) last row held
    p.max_wind_mps = rows[held].wind_mps;
    p.beyond_table = true;
    p.limiting = held + 1 == rows.size() ? "none" : "beyond the simulator's waves (Hs ≤ 8 m)";
    return p;
  }
  double lo = rows[held].wind_mps;
  double hi = rows[held + 1].wind_mps;
  std::string axis = fail_above->axis;
  for (int k = 0; bisect_further(lo, hi, o.wind_tolerance_mps, k); ++k) {
    const double mid = 0.5 * (lo + hi);
    const RunVerdict m = run(mid);
    if (m.holds) {
      lo = mid;
    } else {
      hi = mid;
      axis = m.axis;
    }
  }
  p.max_wind_mps = lo;
  p.limiting = axis;
  return p;
}

}  // namespace

void TimeDomainOptions::validate() const {
  environment.validate();
  const auto positive = [](double v, const char* key, const char* what) {
    if (!std::isfinite(v) || v <= 0.0) {
      throw core::InputError::for_option(key, fmt::format("{} must be > 0, got {}", what, v));
    }
  };
  positive(duration_s, "duration", "the judged run length [s]");
  positive(footprint_m, "footprint", "the position footprint [m]");
  positive(footprint_deg, "footprint_deg", "the heading footprint [deg]");
  check_wind_tolerance(wind_tolerance_mps);
  check_direction_step(direction_step_deg);
  if (!std::isfinite(settle_s) || settle_s < 0.0) {
    throw core::InputError::for_option("settle", fmt::format("must be ≥ 0 s, got {}", settle_s));
  }
  if (duration_s + settle_s > 6.0 * 3600.0) {
    throw core::InputError::for_option("duration", "a run longer than 6 h is not supported",
                                       "DNV-style runs are of the order of hours at most");
  }
}

RunVerdict time_domain_run(const scenario::VesselConfig& vessel,
                           const std::vector<std::string>& failed, const Environment& environment,
                           double from_rel_deg, const TimeDomainOptions& options) {
  scenario::VesselConfig v = vessel;
  if (vessel.thrusters.empty()) {
    v.allocation = with_failures(vessel.allocation, failed);
  } else {  // a layout's units and groups
    v.thruster_capacity.assign(vessel.thrusters.size(), 1.0);
    for (const std::string& name : failed) {
      const FailureCase c = failure_case(vessel.thrusters, name);
      for (std::size_t k = 0; k < c.capacity.size(); ++k) v.thruster_capacity[k] *= c.capacity[k];
    }
  }
  const scenario::ScenarioRun run =
      scenario::run_scenario(hold_spec(environment, from_rel_deg, options), v, options.seed);
  const core::Log& truth = run.truth_log;
  const auto& t = truth.time();
  const auto& north = truth.values("north");
  const auto& east = truth.values("east");
  const auto& heading = truth.values("heading");
  RunVerdict verdict;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < options.settle_s) continue;
    verdict.max_excursion_m = std::max(verdict.max_excursion_m, std::hypot(north[k], east[k]));
    verdict.max_heading_deg = std::max(
        verdict.max_heading_deg,
        std::abs(std::remainder(heading[k], 2.0 * std::numbers::pi)) * 180.0 / std::numbers::pi);
  }
  const bool position_ok = verdict.max_excursion_m <= options.footprint_m;
  const bool heading_ok = verdict.max_heading_deg <= options.footprint_deg;
  verdict.holds = position_ok && heading_ok;
  if (!verdict.holds) {
    // The axis further outside its footprint, relative to it.
    verdict.axis = verdict.max_excursion_m / options.footprint_m >=
                           verdict.max_heading_deg / options.footprint_deg
                       ? "position"
                       : "heading";
  }
  return verdict;
}

std::vector<CapabilityPoint> time_domain_rose(const scenario::VesselConfig& vessel,
                                              const std::vector<std::string>& failed,
                                              const TimeDomainOptions& options) {
  options.validate();
  const int n = static_cast<int>(std::lround(360.0 / options.direction_step_deg));
  std::vector<CapabilityPoint> rose(static_cast<std::size_t>(n));
  // Each direction's search is independent: the rose does not depend on the number of jobs.
  core::parallel_for(rose.size(), options.jobs, [&](std::size_t i) {
    rose[i] = search_direction(vessel, failed, static_cast<double>(i) * options.direction_step_deg,
                               options);
  });
  return rose;
}

}  // namespace dynpos::capability
