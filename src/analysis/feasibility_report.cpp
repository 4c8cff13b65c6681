// The report of `capability --loads`: its JSON and table, and the files written
// (analysis/feasibility.hpp).

#include <fmt/format.h>

#include "dynpos/analysis/feasibility.hpp"

namespace dynpos::analysis {

nlohmann::json to_json(const FeasibilityReport& r) {
  nlohmann::json points = nlohmann::json::array();
  for (const capability::FeasibilityPoint& p : r.points) {
    points.push_back({{"direction_deg", p.direction_deg},
                      {"load_factor", p.load_factor},
                      {"capped", p.capped},
                      {"limiting", p.limiting},
                      {"failure", p.failure}});
  }
  nlohmann::json out{{"analysis", "capability-loads"},
                     {"vessel", r.vessel},
                     {"layout", r.layout},
                     {"units", r.units},
                     {"failure", r.failure},
                     {"points", points}};
  if (!r.vessel_source.empty()) out["vessel_file"] = r.vessel_source;
  return out;
}

std::string to_text(const FeasibilityReport& r) {
  std::string out = fmt::format(
      "{}: load factors ({} units from {}: {}), failure {}\n"
      "direction [deg]  load factor  case          limiting\n",
      r.vessel, r.units.size(), r.layout == "model" ? "the vessel model" : "[[thruster]]",
      fmt::join(r.units, ", "), r.failure);
  for (const capability::FeasibilityPoint& p : r.points) {
    out += fmt::format(
        "{:>15.1f}  {:>11}  {:<12}  {}\n", p.direction_deg,
        p.capped ? fmt::format("≥ {:.0f}", p.load_factor) : fmt::format("{:.4f}", p.load_factor),
        p.failure, p.limiting.empty() ? "none" : fmt::format("{}", fmt::join(p.limiting, "+")));
  }
  return out;
}

Written write_outputs(const FeasibilityReport& report, const Outputs& outputs) {
  Written written;
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
