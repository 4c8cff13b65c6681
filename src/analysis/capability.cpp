#include "dynpos/analysis/capability.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/capability/thrust_region.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::analysis {
namespace {

void check_finite_at_least(double v, double lo, bool open, const char* key, const char* what) {
  if (!std::isfinite(v) || v < lo || (open && v == lo)) {
    throw option_error(key, fmt::format("{} must be {} {}, got {}", what, open ? ">" : "≥", lo, v));
  }
}

// The environment of the request: the DNV table, a site table, with any fixed values.
capability::EnvironmentTable environment_of(const CapabilityRequest& q) {
  capability::EnvironmentTable t = q.site.empty() ? capability::dnv_level1_table()
                                                  : capability::read_site_table(q.site.string());
  if (q.hs || q.tp || q.current) {
    t.name += " with fixed";
    for (auto& row : t.rows) {
      if (q.hs) row.hs_m = *q.hs;
      if (q.tp) row.tp_s = *q.tp;
      if (q.current) row.current_mps = *q.current;
    }
    if (q.hs) t.name += fmt::format(" Hs {} m", *q.hs);
    if (q.tp) t.name += fmt::format(" Tp {} s", *q.tp);
    if (q.current) t.name += fmt::format(" current {} m/s", *q.current);
  }
  return t;
}

capability::TimeDomainOptions time_domain_options(const CapabilityRequest& q,
                                                  const capability::EnvironmentTable& table) {
  capability::TimeDomainOptions o;
  o.environment = table;
  o.direction_step_deg = q.direction_step;
  o.duration_s = q.duration;
  o.settle_s = q.settle;
  o.footprint_m = q.footprint;
  o.footprint_deg = q.footprint_deg;
  o.wind_tolerance_mps = q.wind_tolerance.value_or(0.25);
  o.seed = q.seed;
  o.jobs = q.jobs;
  return o;
}

std::vector<capability::CapabilityPoint> rose(const CapabilityRequest& q,
                                              const scenario::VesselConfig& vessel,
                                              const capability::EnvironmentTable& table,
                                              const std::vector<std::string>& failed) {
  if (q.level == 3) {
    return capability::time_domain_rose(vessel, failed, time_domain_options(q, table));
  }
  capability::QuasiStaticOptions o;
  o.level = q.level;
  o.environment = table;
  o.direction_step_deg = q.direction_step;
  o.wind_tolerance_mps = q.wind_tolerance.value_or(0.01);
  return capability::quasi_static_rose(vessel, failed, o);
}

}  // namespace

void CapabilityRequest::validate() const {
  if (level < 1 || level > 3) {
    throw option_error("level", fmt::format("unknown level {}", level),
                       "1 (DNV table, rated thrust), 2 (thrust losses, site) or 3 (time domain)");
  }
  if (!worst_of.empty() && failure != "worst") {
    throw option_error("worst_of", "the failures of the worst case need failure \"worst\"");
  }
  if (level != 2 && (!site.empty() || hs || tp || current)) {
    throw option_error("site/hs/tp/current", "a site environment is for level 2",
                       "add --level 2, or leave the site out");
  }
  if (!site.empty() && !std::filesystem::is_regular_file(site)) {
    throw option_error("site", "'" + site.string() + "' is not a file", "give a site TOML file");
  }
  if (hs) check_finite_at_least(*hs, 0.0, false, "hs", "Hs [m]");
  if (tp) check_finite_at_least(*tp, 0.0, true, "tp", "Tp [s]");
  if (current) check_finite_at_least(*current, 0.0, false, "current", "the current [m/s]");
  capability::check_direction_step(direction_step);
  if (wind_tolerance) capability::check_wind_tolerance(*wind_tolerance);
  if (!vessel.empty() && !std::filesystem::is_regular_file(vessel)) {
    throw option_error("vessel", "'" + vessel.string() + "' is not a file",
                       "give a vessel TOML file (docs/vessel-file.md)");
  }
  if (level == 3 && !transient) {
    time_domain_options(*this, capability::dnv_level1_table()).validate();
  }
}

const CapabilityCase& CapabilityReport::headline() const {
  if (worst) return *worst;
  if (!failures.empty()) return failures.front();
  return intact;
}

CapabilityReport run_capability(const CapabilityRequest& q) {
  q.validate();
  const std::filesystem::path file = vessel_file_or_default(q.vessel);
  const scenario::VesselConfig vessel = scenario::load_vessel_config(file);
  // The cases are the vessel's: the model's actuators, or a layout's units and groups.
  if (q.failure != "none" && q.failure != "worst") {
    capability::check_failure(vessel, q.failure, "failure");
  }
  for (const std::string& f : q.worst_of) capability::check_failure(vessel, f, "worst_of");
  const capability::EnvironmentTable table = environment_of(q);
  CapabilityReport r;
  r.level = q.level;
  r.vessel = vessel.name;
  r.vessel_source = q.vessel.empty() ? "" : q.vessel.string();
  r.layout = vessel.thrusters.empty() ? "model" : "[[thruster]]";
  r.environment = table.name;
  r.failure = q.failure;
  r.dynamic_allowance = q.level == 3 ? 1.0 : capability::kDynamicAllowance;
  r.intact = {"none", rose(q, vessel, table, {})};
  if (q.failure == "worst") {
    std::vector<std::vector<capability::CapabilityPoint>> all;
    for (const std::string& f :
         q.worst_of.empty() ? capability::single_failures(vessel) : q.worst_of) {
      r.failures.push_back({f, rose(q, vessel, table, {f})});
      all.push_back(r.failures.back().points);
    }
    r.worst = CapabilityCase{"worst", capability::worst_case(all)};
  } else if (q.failure != "none") {
    r.failures.push_back({q.failure, rose(q, vessel, table, {q.failure})});
  }
  if (q.level == 3) r.time_domain = time_domain_options(q, table);
  return r;
}

std::array<std::optional<int>, 4> capability_notation(const CapabilityReport& report) {
  const auto lowest = [](const std::vector<capability::CapabilityPoint>& points, bool bow) {
    int n = 99;
    for (const auto& p : points) {
      const double off = std::abs(std::remainder(p.direction_deg, 360.0));
      if (!bow || off <= 30.0 + 1e-9) n = std::min(n, p.dp_number);
    }
    return n;
  };
  std::array<std::optional<int>, 4> out{
      lowest(report.intact.points, true), lowest(report.intact.points, false), {}, {}};
  if (!report.failures.empty()) {
    out[2] = lowest(report.headline().points, true);
    out[3] = lowest(report.headline().points, false);
  }
  return out;
}

}  // namespace dynpos::analysis
