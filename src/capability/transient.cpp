#include "dynpos/capability/transient.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "dynpos/capability/quasi_static.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/scenario/runner.hpp"

namespace dynpos::capability {
namespace {

constexpr double kPreWindow_s = 60.0;  // the pre-failure minute of the loads (FailureTruth's)

scenario::ScenarioSpec transient_spec(const Environment& e, double from_deg,
                                      const std::string& failure, const TransientOptions& o) {
  scenario::ScenarioSpec spec;
  spec.name = fmt::format("transient-{:.0f}", from_deg);
  spec.description = "DP capability run: a failure as it happens at heading 0";
  spec.duration_s = o.settle_s + o.after_s;
  spec.log_rate_hz = 2.0;
  spec.environment.wind_speed_mps = e.wind_mps;
  spec.environment.wind_from_deg = from_deg;
  spec.environment.current_speed_mps = e.current_mps;
  spec.environment.current_to_deg = std::remainder(from_deg + 180.0, 360.0);
  spec.environment.hs_m = e.hs_m;
  spec.environment.tp_s = e.hs_m > 0.0 ? e.tp_s : spec.environment.tp_s;
  spec.environment.wave_from_deg = from_deg;
  spec.setpoints.push_back({0.0, 0.0, 0.0, 0.0, "hold"});
  spec.observer = o.observer;
  spec.failure = scenario::FailureEvent{o.settle_s, failure};
  return spec;
}

// The mean over [from, to) of the NED channels NAME.north|east|yaw turned into BODY.
Eigen::Vector3d mean_body(const core::Log& log, const std::string& name, double from, double to) {
  const auto& t = log.time();
  const auto& n = log.values(name + ".north");
  const auto& e = log.values(name + ".east");
  const auto& yaw = log.values(name + ".yaw");
  const auto& psi = log.values("heading");
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < from || t[i] >= to) continue;
    const double c = std::cos(psi[i]), s = std::sin(psi[i]);
    sum += Eigen::Vector3d(c * n[i] + s * e[i], -s * n[i] + c * e[i], yaw[i]);
    ++count;
  }
  return count > 0 ? Eigen::Vector3d(sum / count) : Eigen::Vector3d::Constant(core::kMissing);
}

TransientRun run_one(const scenario::VesselConfig& vessel, const scenario::ScenarioSpec& spec,
                     std::uint64_t seed) {
  const scenario::ScenarioRun run = scenario::run_scenario(spec, vessel, seed);
  const scenario::FailureTruth& f = *run.truth.failure;
  TransientRun r;
  r.seed = seed;
  r.peak_excursion_m = f.peak_excursion_m;
  r.time_to_peak_s = f.time_to_peak_s;
  r.peak_heading_deg = f.peak_heading_deg;
  r.recovery_s = f.recovery_s;
  const double to = spec.failure->t_s, from = to - kPreWindow_s;
  r.load_b = mean_body(run.truth_log, "env_load", from, to);
  r.estimated_load_b = run.truth_log.has("observer.bias.north")
                           ? mean_body(run.truth_log, "observer.bias", from, to)
                           : r.load_b;
  return r;
}

}  // namespace

void TransientOptions::validate() const {
  environment.validate();
  const auto positive = [](double v, const char* key, const char* what) {
    if (!std::isfinite(v) || v <= 0.0) {
      throw core::InputError::for_option(key, fmt::format("{} must be > 0, got {}", what, v));
    }
  };
  positive(after_s, "after", "the run after the failure [s]");
  positive(footprint_m, "footprint", "the position footprint [m]");
  positive(footprint_deg, "footprint_deg", "the heading footprint [deg]");
  check_direction_step(direction_step_deg);
  if (!std::isfinite(settle_s) || settle_s < kPreWindow_s) {
    throw core::InputError::for_option(
        "settle", fmt::format("must be ≥ {} s before the failure, got {}", kPreWindow_s, settle_s),
        "the pre-failure mean and footprint are taken over the minute before it");
  }
  if (settle_s + after_s > 6.0 * 3600.0) {
    throw core::InputError::for_option("after", "a run longer than 6 h is not supported");
  }
  if (seeds < 1 || seeds > 1000) {
    throw core::InputError::for_option("seeds", fmt::format("must be 1 … 1000, got {}", seeds));
  }
  if (rows.empty()) throw core::InputError::for_option("rows", "no weather row given");
  for (const int row : rows) {
    if (row < 1 || row >= static_cast<int>(environment.rows.size())) {
      throw core::InputError::for_option(
          "rows", fmt::format("no row {} in {} (1 … {})", row, environment.name,
                              environment.rows.size() - 1));
    }
  }
}

std::vector<TransientPoint> transient_footprint(const scenario::VesselConfig& vessel,
                                                const std::string& failure,
                                                const TransientOptions& o) {
  o.validate();
  const int directions = static_cast<int>(std::lround(360.0 / o.direction_step_deg));
  std::vector<TransientPoint> points;
  for (int d = 0; d < directions; ++d) {
    for (const int row : o.rows) {
      TransientPoint p;
      p.direction_deg = d * o.direction_step_deg;
      p.dp_number = row;
      p.wind_mps = o.environment.rows[static_cast<std::size_t>(row)].wind_mps;
      p.failure = failure;
      p.runs.resize(o.seeds);
      points.push_back(std::move(p));
    }
  }
  core::parallel_for(points.size() * o.seeds, o.jobs, [&](std::size_t job) {
    TransientPoint& p = points[job / o.seeds];
    const std::size_t k = job % o.seeds;
    const scenario::ScenarioSpec spec = transient_spec(
        o.environment.rows[static_cast<std::size_t>(p.dp_number)], p.direction_deg, failure, o);
    p.runs[k] = run_one(vessel, spec, o.seed + k);
  });
  for (TransientPoint& p : points) {
    p.holds = true;
    for (const TransientRun& r : p.runs) {
      if (r.peak_excursion_m >= p.peak_excursion_m) {
        p.peak_excursion_m = r.peak_excursion_m;
        p.time_to_peak_s = r.time_to_peak_s;
      }
      p.peak_heading_deg = std::max(p.peak_heading_deg, r.peak_heading_deg);
      p.holds =
          p.holds && r.peak_excursion_m <= o.footprint_m && r.peak_heading_deg <= o.footprint_deg;
    }
  }
  return points;
}

}  // namespace dynpos::capability
