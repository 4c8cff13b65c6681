// The estimate's report: its JSON document, its text, the time series' CSV and the outputs.

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "dynpos/analysis/estimate.hpp"
#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/core/angle.hpp"
#include "dynpos/io/csv_writer.hpp"

namespace dynpos::analysis {
namespace {

nlohmann::json vec3_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json ned_load_json(const Eigen::Vector3d& b) {
  return {{"north_N", b.x()}, {"east_N", b.y()}, {"yaw_Nm", b.z()}};
}

nlohmann::json bias_json(const std::optional<BiasSummary>& s) {
  if (!s) return nullptr;
  return {{"from_s", s->from_s},
          {"to_s", s->to_s},
          {"samples", s->samples},
          {"mean", ned_load_json(s->mean_n)},
          {"std", ned_load_json(s->std_n)}};
}

nlohmann::json units_json(const std::vector<scenario::FeedbackChannel>& units) {
  nlohmann::json out = nlohmann::json::array();
  for (const scenario::FeedbackChannel& c : units) {
    out.push_back(
        {{"name", c.unit},
         {"thrust", c.thrust_role},
         {"angle", c.angle_role.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.angle_role)}});
  }
  return out;
}

// The largest position age of the track's estimates [s].
double longest_without_position_s(const control::ObserverTrack& track) {
  return *std::max_element(track.position_age_s.begin(), track.position_age_s.end());
}

std::string measurement_name(const control::ObserverRunOptions& run) {
  return run.holds_measurements() ? "held" : "fresh";
}

}  // namespace

core::Log estimate_log(const control::ObserverTrack& track) {
  core::Log log;
  const std::pair<const char*, const char*> columns[] = {
      {"lf.north", "m"},    {"lf.east", "m"},     {"lf.heading", "deg"}, {"lf.u", "m/s"},
      {"lf.v", "m/s"},      {"lf.r", "deg/s"},    {"bias.north", "kN"},  {"bias.east", "kN"},
      {"bias.yaw", "kN*m"}, {"position.age", "s"}};
  for (const auto& [name, unit] : columns) log.declare_channel(name, unit);
  log.reserve(track.t_s.size());
  for (std::size_t k = 0; k < track.t_s.size(); ++k) {
    const control::ObserverEstimate& e = track.estimate[k];
    const double row[] = {e.eta_n.x(),
                          e.eta_n.y(),
                          core::rad_to_deg(core::wrap_2pi(e.eta_n.z())),
                          e.nu_b.x(),
                          e.nu_b.y(),
                          core::rad_to_deg(e.nu_b.z()),
                          e.bias_n.x() * 1e-3,
                          e.bias_n.y() * 1e-3,
                          e.bias_n.z() * 1e-3,
                          track.position_age_s.at(k)};
    log.append_row(track.t_s[k], row);
  }
  return log;
}

nlohmann::json to_json(const EstimateReport& r) {
  nlohmann::json doc;
  doc["analysis"] = "estimate";
  doc["log"] = r.log.string();
  doc["input"] = io::to_json(r.input);
  doc["vessel"] = r.vessel;
  doc["vessel_file"] =
      r.vessel_source.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.vessel_source);
  doc["units"] = units_json(r.units);
  doc["position"] = r.position;
  doc["arm_m"] = r.arm_m ? vec3_json(*r.arm_m) : nlohmann::json(nullptr);
  doc["attitude"] = r.attitude;
  doc["observer"] = std::string(control::observer_name(r.observer));
  doc["tp_s"] = r.tp_s;
  doc["wave_peak_frequency_rad_s"] = vec3_json(r.wave_peak_frequency_rad_s);
  doc["rate_hz"] = r.run.rate_hz;
  doc["max_hold_s"] = r.run.max_hold_s;
  doc["measurement"] = measurement_name(r.run);
  doc["settle_s"] = r.settle_s;
  doc["start_s"] = r.track.start_s;
  doc["end_s"] = r.track.t_s.back();
  doc["steps"] = r.track.t_s.size();
  doc["position_steps"] = r.track.position_steps;
  doc["coasting_steps"] = r.track.coasting_steps;
  doc["stale_thrust_steps"] = r.track.stale_thrust_steps;
  doc["longest_without_position_s"] = longest_without_position_s(r.track);
  doc["bridge"] = r.bridge_mru.empty() ? nlohmann::json(nullptr)
                                       : nlohmann::json{{"mru", r.bridge_mru},
                                                        {"arm_m", vec3_json(r.bridge_arm_m)},
                                                        {"rows", r.bridged_rows},
                                                        {"longest_gap_s", r.longest_gap_bridged_s}};
  doc["csv"] = r.csv.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.csv.string());
  doc["bias"] = bias_json(r.bias);
  return doc;
}

std::string to_text(const EstimateReport& r) {
  const Eigen::Vector3d& w0 = r.wave_peak_frequency_rad_s;
  std::string units;
  for (const scenario::FeedbackChannel& c : r.units) units += (units.empty() ? "" : ", ") + c.unit;
  std::string text = fmt::format(
      "{}: {} observer at {:g} Hz, T_p {:g} s (wave model at {:.3f}, {:.3f}, {:.3f} rad/s), "
      "{} measurement\n",
      r.log.string(), control::observer_name(r.observer), r.run.rate_hz, r.tp_s, w0.x(), w0.y(),
      w0.z(), measurement_name(r.run));
  text += fmt::format("vessel {} (units {}); position {}", r.vessel, units, r.position);
  if (r.arm_m) {
    text +=
        fmt::format(" moved to the control origin by the arm {:g}, {:g}, {:g} m{}", r.arm_m->x(),
                    r.arm_m->y(), r.arm_m->z(), r.attitude ? " with roll and pitch" : "");
  }
  text += fmt::format(
      "\n{:.1f}–{:.1f} s: {} steps, {} with a position, {} coasting, {} on a "
      "stale thrust; at most {:.1f} s from a position\n",
      r.track.start_s, r.track.t_s.back(), r.track.t_s.size(), r.track.position_steps,
      r.track.coasting_steps, r.track.stale_thrust_steps, longest_without_position_s(r.track));
  if (!r.bridge_mru.empty()) {
    text += fmt::format(
        "GNSS gaps over {:g} s bridged on {} (arm {:g}, {:g}, {:g} m): {} rows, the longest gap "
        "{:.1f} s\n",
        r.run.max_hold_s, r.bridge_mru, r.bridge_arm_m.x(), r.bridge_arm_m.y(), r.bridge_arm_m.z(),
        r.bridged_rows, r.longest_gap_bridged_s);
  }
  if (r.bias) {
    const BiasSummary& b = *r.bias;
    text += fmt::format(
        "bias b̂ (NED) from {:.1f} s, mean ± std: north {:.2f} ± {:.2f} kN, east {:.2f} ± {:.2f} "
        "kN, yaw {:.2f} ± {:.2f} kN·m\n",
        b.from_s, b.mean_n.x() * 1e-3, b.std_n.x() * 1e-3, b.mean_n.y() * 1e-3, b.std_n.y() * 1e-3,
        b.mean_n.z() * 1e-3, b.std_n.z() * 1e-3);
  } else {
    text += fmt::format("bias: no sample after the settling time ({:g} s)\n", r.settle_s);
  }
  return text + io::to_text(r.input);
}

Written write_outputs(const EstimateReport& report, const Outputs& outputs) {
  Written written;
  if (!report.csv.empty()) {
    io::write_csv(report.csv, estimate_log(report.track));
    written.push_back(report.csv);
  }
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
