#include "dynpos/analysis/thrust_map.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <map>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"
#include "dynpos/model/unit_drive.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::analysis {
namespace {

bool is_rpm_or_thrust(const std::string& role) {
  return role.rfind("rpm.", 0) == 0 || role.rfind("thrust.", 0) == 0;
}

// The thrust maps of the vessel file (3.17), tables 3.1/3.2: c₊ and c₋ = −c(n < 0) of each
// thruster model, c = ρK_T·D⁴ for that sign.
// The vessel's thrust maps by thruster name: a [[thruster]] layout's units (each drive's
// ρK_T D⁴ ahead and astern, model/unit_drive.hpp), else the model's propellers and tunnel.
std::map<std::string, ident::ThrustMap> vessel_maps(const scenario::VesselConfig& v) {
  if (!v.thrusters.empty()) {
    std::map<std::string, ident::ThrustMap> maps;
    for (const model::ThrusterUnit& unit : v.thrusters) {
      const model::UnitDrive drive(unit);
      // T = c₊·n² ahead, c₋·n² astern with c₋ = thrust at n = −1 (negative).
      maps.emplace(unit.name, ident::ThrustMap{drive.thrust_N(1.0), drive.thrust_N(-1.0) + 0.0});
    }
    return maps;
  }
  const model::Thruster main(v.propeller);
  const ident::ThrustMap propeller{main.thrust_coefficient(1.0), -main.thrust_coefficient(-1.0)};
  const model::TunnelThruster bow(v.tunnel);
  const ident::ThrustMap tunnel{bow.thrust_coefficient(1.0), -bow.thrust_coefficient(-1.0)};
  return {{"port", propeller}, {"stb", propeller}, {"tunnel", tunnel}};
}

bool is_rpm(const std::string& role) { return role.rfind("rpm.", 0) == 0; }

std::vector<ThrusterMapFit> fit_maps(const ThrustMapRequest& request, const core::Log& log) {
  std::vector<ThrusterMapFit> fits;
  for (const std::string& name : thruster_names(log, "rpm")) {
    if (!log.has("thrust." + name)) continue;
    ident::ThrustMapFitOptions f;
    f.min_abs_shaft_speed_rps = request.min_speed_rpm / 60.0;
    f.shaft_speed_name = "rpm." + name;
    f.thrust_name = "thrust." + name;
    ThrusterMapFit fit{
        name, ident::fit_thrust_map(log.values("rpm." + name), log.values("thrust." + name), f),
        std::nullopt};
    if (fit.fit.c_forward && fit.fit.c_reverse) {
      fit.c_mean =
          ident::ThrustMap{fit.fit.c_forward->value, fit.fit.c_reverse->value}.mean_coefficient();
    }
    fits.push_back(std::move(fit));
  }
  if (fits.empty()) {
    throw request.source.error("thrust.NAME",
                               "no thruster with both shaft speed and thrust in the log",
                               "map them per thruster, e.g. --col rpm.port=RPM_P --col "
                               "thrust.port=THRUST_P (a dynpos log names them so already)");
  }
  return fits;
}

AppliedThrust apply_maps(const ThrustMapRequest& request, const core::Log& log) {
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(vessel_file_or_default(request.vessel));
  const auto maps = vessel_maps(vessel);
  AppliedThrust out{core::Log(log.time()), 0, vessel.source, request.abs_speed, request.out};
  for (const std::string& name : thruster_names(log, "rpm")) {
    const auto it = maps.find(name);
    if (it == maps.end()) {
      std::vector<std::string> names;
      for (const auto& [known, map] : maps) names.push_back(known);
      throw request.source.error("rpm." + name,
                                 "no thrust map for thruster '" + name + "' in the vessel file",
                                 fmt::format("the vessel file has {}", fmt::join(names, ", ")));
    }
    const std::vector<double>& n = log.values("rpm." + name);
    std::vector<double> thrust_kN =
        request.abs_speed ? ident::thrust_from_abs_speed(it->second.mean_coefficient(), n)
                          : it->second.thrust(n);
    for (double& t : thrust_kN) t /= 1000.0;
    std::vector<double> rpm(n.size());
    for (std::size_t i = 0; i < n.size(); ++i) rpm[i] = n[i] * 60.0;
    out.log.add_channel("rpm." + name, "rpm", std::move(rpm));
    out.log.add_channel("thrust." + name, "kN", std::move(thrust_kN));
    ++out.thrusters;
  }
  if (out.thrusters == 0) {
    throw request.source.error("rpm.NAME", "no shaft speed column in the log",
                               "map one per thruster, e.g. --col rpm.port=RPM_P");
  }
  return out;
}

}  // namespace

void ThrustMapRequest::validate() const {
  if (min_speed_rpm < 0.0) {
    throw option_error("min_speed", fmt::format("{} rpm is negative", min_speed_rpm),
                       "give the smallest |n| to fit, ≥ 0 rpm");
  }
  if (apply && out.empty()) {
    throw option_error("out", "--apply needs --out FILE.csv",
                       "name the CSV to write the computed thrust into");
  }
}

ThrustMapReport run_thrust_map(const ThrustMapRequest& request) {
  request.validate();
  ThrustMapReport report;
  report.log = request.source.log;
  report.min_speed_rpm = request.min_speed_rpm;
  LoadedLog loaded = request.source.load(request.apply ? RoleFilter(is_rpm) : is_rpm_or_thrust);
  report.input = std::move(loaded.input);
  if (request.apply) {
    report.applied = apply_maps(request, loaded.log);
  } else {
    report.thrusters = fit_maps(request, loaded.log);
  }
  return report;
}

}  // namespace dynpos::analysis
