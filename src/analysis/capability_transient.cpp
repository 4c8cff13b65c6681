#include "dynpos/analysis/capability_transient.hpp"

#include <fmt/format.h>

#include <map>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/capability/quasi_static.hpp"
#include "dynpos/report/polar_plot.hpp"
#include "dynpos/report/table.hpp"
#include "dynpos/scenario/unit_failure.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {
namespace {

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json vector_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json run_json(const capability::TransientRun& r) {
  return {{"seed", r.seed},
          {"peak_excursion_m", r.peak_excursion_m},
          {"time_to_peak_s", r.time_to_peak_s},
          {"peak_heading_deg", r.peak_heading_deg},
          {"recovery_s", optional_json(r.recovery_s)},
          {"load_b", vector_json(r.load_b)},
          {"estimated_load_b", vector_json(r.estimated_load_b)}};
}

}  // namespace

capability::TransientOptions transient_options(const CapabilityRequest& q) {
  if (q.level != 3) {
    throw option_error("transient", "the failure as it happens is a level 3 run", "add --level 3");
  }
  if (q.failure == "none" || q.failure == "worst" || !q.worst_of.empty()) {
    throw option_error("failure",
                       fmt::format("--transient trips one named failure, not '{}'", q.failure),
                       "name the worst-case failure: a unit, group:NAME or an actuator of the "
                       "model (port, stb, tunnel, rudder.port, rudder.stb)");
  }
  const std::optional<control::ObserverKind> observer = control::parse_observer(q.observer);
  if (!observer) {
    throw option_error("observer", fmt::format("unknown observer '{}'", q.observer),
                       "use ideal, passive, ekf or raw");
  }
  capability::TransientOptions o;
  o.rows = q.rows;
  o.direction_step_deg = q.direction_step;
  o.settle_s = q.settle;
  o.after_s = q.after;
  o.footprint_m = q.footprint;
  o.footprint_deg = q.footprint_deg;
  o.seeds = q.seeds;
  o.seed = q.seed;
  o.observer = *observer;
  o.jobs = q.jobs;
  o.validate();
  return o;
}

void check_transient_options(const CapabilityRequest& q,
                             const std::function<bool(std::string_view)>& given) {
  if (q.transient) {
    for (const char* option : {"duration", "wind-tolerance"}) {
      if (given(option)) {
        throw option_error(option, fmt::format("--{} is not an option of --transient", option),
                           "--settle and --after set a transient run's length; it searches no "
                           "wind");
      }
    }
    return;
  }
  for (const char* option : {"rows", "after", "seeds", "observer"}) {
    if (given(option)) {
      throw option_error(option, fmt::format("--{} is an option of --transient", option),
                         "add --level 3 --transient --failure NAME");
    }
  }
}

TransientReport run_capability_transient(const CapabilityRequest& q) {
  q.validate();
  const capability::TransientOptions options = transient_options(q);
  const std::filesystem::path file = vessel_file_or_default(q.vessel);
  const scenario::VesselConfig vessel = scenario::load_vessel_config(file);
  (void)scenario::UnitFailure({options.settle_s, q.failure}, vessel);  // option "failure"
  TransientReport r;
  r.vessel = vessel.name;
  r.vessel_source = q.vessel.empty() ? "" : q.vessel.string();
  r.environment = options.environment.name;
  r.failure = q.failure;
  r.options = options;
  r.points = capability::transient_footprint(vessel, q.failure, options);
  return r;
}

nlohmann::json to_json(const TransientReport& r) {
  const capability::TransientOptions& o = r.options;
  nlohmann::json doc = {{"analysis", "capability-transient"},
                        {"vessel", r.vessel},
                        {"environment", r.environment},
                        {"failure", r.failure}};
  if (!r.vessel_source.empty()) doc["vessel_file"] = r.vessel_source;
  doc["options"] = {{"rows", o.rows},
                    {"direction_step_deg", o.direction_step_deg},
                    {"settle_s", o.settle_s},
                    {"after_s", o.after_s},
                    {"footprint_m", o.footprint_m},
                    {"footprint_deg", o.footprint_deg},
                    {"seeds", o.seeds},
                    {"seed", o.seed},
                    {"observer", control::observer_name(o.observer)}};
  nlohmann::json points = nlohmann::json::array();
  for (const capability::TransientPoint& p : r.points) {
    nlohmann::json runs = nlohmann::json::array();
    for (const capability::TransientRun& run : p.runs) runs.push_back(run_json(run));
    points.push_back({{"direction_deg", p.direction_deg},
                      {"dp_number", p.dp_number},
                      {"wind_mps", p.wind_mps},
                      {"failure", p.failure},
                      {"peak_excursion_m", p.peak_excursion_m},
                      {"time_to_peak_s", p.time_to_peak_s},
                      {"peak_heading_deg", p.peak_heading_deg},
                      {"holds", p.holds},
                      {"runs", runs}});
  }
  doc["points"] = points;
  return doc;
}

std::string to_text(const TransientReport& r) {
  const capability::TransientOptions& o = r.options;
  std::string out = fmt::format(
      "{}: failure '{}' as it happens after {:g} s of stationkeeping at heading 0, {:g} s "
      "after; {} ({} seed{} from {}); footprint {:g} m, {:g}°; observer {}\n",
      r.vessel, r.failure, o.settle_s, o.after_s, r.environment, o.seeds, o.seeds == 1 ? "" : "s",
      o.seed, o.footprint_m, o.footprint_deg, control::observer_name(o.observer));
  report::Table t;
  t.header = {"from [deg]"};
  for (const int row : o.rows) {
    t.header.push_back(fmt::format("DP {}: peak [m]", row));
    t.header.push_back("at [s]");
    t.header.push_back("heading [deg]");
  }
  std::map<double, std::vector<std::string>> rows;
  for (const capability::TransientPoint& p : r.points) {
    auto& row = rows[p.direction_deg];
    if (row.empty()) row.push_back(fmt::format("{:.0f}", p.direction_deg));
    row.push_back(fmt::format("{:.2f}{}", p.peak_excursion_m, p.holds ? "" : " !"));
    row.push_back(fmt::format("{:.0f}", p.time_to_peak_s));
    row.push_back(fmt::format("{:.1f}", p.peak_heading_deg));
  }
  for (auto& [direction, row] : rows) t.rows.push_back(std::move(row));
  return out + report::render_text(t) + "! outside the footprint\n";
}

void write_footprint(const TransientReport& r, const std::filesystem::path& svg) {
  report::PolarFigure fig;
  fig.title = fmt::format("{} — excursion after '{}' as it happens", r.vessel, r.failure);
  report::PolarPanel panel;
  panel.title = "Largest excursion from the pre-failure mean";
  panel.radial_label = "excursion";
  panel.radial_unit = "m";
  panel.angle_step_deg = 30.0;
  for (const int row : r.options.rows) {
    report::PolarSeries s;
    s.label = fmt::format("DP {}", row);
    for (const capability::TransientPoint& p : r.points) {
      if (p.dp_number != row) continue;
      s.angle_deg.push_back(p.direction_deg);
      s.radius.push_back(p.peak_excursion_m);
    }
    panel.series.push_back(std::move(s));
  }
  report::PolarSeries ring;
  ring.label = fmt::format("footprint {:g} m", r.options.footprint_m);
  ring.color = "#7f7f7f";
  ring.dashed = true;
  ring.markers = false;
  for (int a = 0; a < 360; a += 5) {
    ring.angle_deg.push_back(a);
    ring.radius.push_back(r.options.footprint_m);
  }
  panel.series.push_back(std::move(ring));
  fig.panels.push_back(std::move(panel));
  report::write_polar_svg(svg, fig);
}

Written write_outputs(const TransientReport& report, const Outputs& outputs) {
  Written written;
  if (!outputs.figures.empty()) {
    std::filesystem::create_directories(outputs.figures);
    written.push_back(outputs.figures / "footprint.svg");
    write_footprint(report, written.back());
  }
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
