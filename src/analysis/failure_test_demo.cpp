// The failure test section of the demo report: the thruster trip and the bus failure of the DP
// trials found in the logger's files, beside the simulator's own measure of the response.

#include <fmt/core.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/failure_test.hpp"
#include "dynpos/core/angle.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/table.hpp"
#include "dynpos/scenario/trial_truth.hpp"

namespace dynpos::analysis {
namespace {

// The campaign's scenarios with a failure, in the order of the section.
constexpr std::array<const char*, 2> kScenarios = {"dp-thruster-trip", "dp-bus-failure"};

std::optional<double> known(double v) {
  return std::isnan(v) ? std::nullopt : std::optional<double>(v);
}

std::string cell(const std::optional<double>& v, const char* format) {
  return v ? fmt::format(fmt::runtime(format), *v) : std::string("—");
}

std::string signed_cell(const std::optional<double>& found, const std::optional<double>& truth,
                        const char* format) {
  if (!found || !truth) return "—";
  return fmt::format(fmt::runtime(format), *found - *truth);
}

std::string units_cell(const std::string& unit, const std::vector<std::string>& units) {
  std::string out = unit;
  for (const std::string& u : units) {
    if (u != unit) out += "+" + u;
  }
  return out;
}

// The figures compared: the found event's or truth.json's.
struct Figures {
  std::string units;
  std::optional<double> time_s, peak_m, to_peak_s, recovery_s, heading_deg, footprint_m;
};

Figures found_figures(const ident::FailureEvent& e) {
  return {units_cell(e.unit, e.units),
          e.time_s,
          e.peak_excursion_m,
          e.time_to_peak_s,
          e.recovery_s,
          e.peak_heading_rad ? std::optional(core::rad_to_deg(*e.peak_heading_rad)) : std::nullopt,
          e.footprint_m};
}

Figures true_figures(const scenario::FailureTruth& f) {
  return {f.unit,
          f.time_s,
          known(f.peak_excursion_m),
          known(f.time_to_peak_s),
          f.recovery_s,
          known(f.peak_heading_deg),
          known(f.footprint_m)};
}

nlohmann::json failure_truth_json(const scenario::FailureTruth& f) {
  const auto number = [](double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); };
  return {{"time_s", f.time_s},
          {"unit", f.unit},
          {"units", f.units},
          {"footprint_m", number(f.footprint_m)},
          {"peak_excursion_m", number(f.peak_excursion_m)},
          {"time_to_peak_s", number(f.time_to_peak_s)},
          {"recovery_s", f.recovery_s ? nlohmann::json(*f.recovery_s) : nlohmann::json()},
          {"peak_heading_deg", number(f.peak_heading_deg)}};
}

// The event found nearest the true failure instant; none when no trip was found.
const ident::FailureEvent* nearest_event(const FailureTestReport& report, double t_s) {
  const ident::FailureEvent* best = nullptr;
  for (const ident::FailureEvent& e : report.result.events) {
    if (!best || std::abs(e.time_s - t_s) < std::abs(best->time_s - t_s)) best = &e;
  }
  return best;
}

// A scenario's rows: found, true and their difference; a found row that says so when no trip
// was found.
void add_rows(report::Table& table, const std::string& scenario, const ident::FailureEvent* e,
              const scenario::FailureTruth& truth) {
  const Figures t = true_figures(truth);
  if (e == nullptr) {
    table.rows.push_back({scenario, "found", "no trip found", "—", "—", "—", "—", "—", "—"});
  } else {
    const Figures f = found_figures(*e);
    table.rows.push_back({scenario, "found", f.units, cell(f.time_s, "{:.1f}"),
                          cell(f.peak_m, "{:.2f}"), cell(f.to_peak_s, "{:.1f}"),
                          f.recovery_s ? cell(f.recovery_s, "{:.1f}") : "never",
                          cell(f.heading_deg, "{:.2f}"), cell(f.footprint_m, "{:.2f}")});
  }
  table.rows.push_back({scenario, "true", t.units, cell(t.time_s, "{:.1f}"),
                        cell(t.peak_m, "{:.2f}"), cell(t.to_peak_s, "{:.1f}"),
                        t.recovery_s ? cell(t.recovery_s, "{:.1f}") : "never",
                        cell(t.heading_deg, "{:.2f}"), cell(t.footprint_m, "{:.2f}")});
  if (e == nullptr) return;
  const Figures f = found_figures(*e);
  table.rows.push_back({scenario, "found − true", "", signed_cell(f.time_s, t.time_s, "{:+.1f}"),
                        signed_cell(f.peak_m, t.peak_m, "{:+.2f}"),
                        signed_cell(f.to_peak_s, t.to_peak_s, "{:+.1f}"),
                        signed_cell(f.recovery_s, t.recovery_s, "{:+.1f}"),
                        signed_cell(f.heading_deg, t.heading_deg, "{:+.2f}"),
                        signed_cell(f.footprint_m, t.footprint_m, "{:+.2f}")});
}

}  // namespace

ReportSection failure_test_demo_section(const std::filesystem::path& campaign_dir) {
  report::Table table;
  table.header = {"scenario",     "",
                  "unit(s)",      "time [s]",
                  "peak [m]",     "to peak [s]",
                  "recovery [s]", "heading [deg]",
                  "footprint [m]"};
  std::vector<std::string> scenarios;
  const std::filesystem::path dir = campaign_dir / "analysis" / "failure-test";
  for (const char* name : kScenarios) {
    const std::filesystem::path log = campaign_dir / name / "log.csv";
    const std::filesystem::path truth_json = campaign_dir / name / "truth.json";
    if (!std::filesystem::exists(log) || !std::filesystem::exists(truth_json)) continue;
    const scenario::TrialTruth truth = scenario::read_trial_truth(truth_json);
    if (!truth.failure) continue;
    FailureTestRequest request;
    request.source.log = log;
    request.source.columns = {"north=gnss1.north", "east=gnss1.east"};
    // The antenna's surveyed lever arm (the vessel file's, which truth.json repeats), with the
    // MRU's roll and pitch for its height: the excursion of the control origin, as truth's.
    if (const auto arm = truth.lever_arms.find("gnss1"); arm != truth.lever_arms.end()) {
      request.arm_m = arm->second;
      request.source.columns.push_back("roll=mru1.roll");
      request.source.columns.push_back("pitch=mru1.pitch");
    }
    FailureTestReport report = run_failure_test(request);
    report.log = std::string(name) + "/log.csv";  // relative to the report: relocatable
    report.input = relative_to(std::move(report.input), campaign_dir);
    std::filesystem::create_directories(dir);
    nlohmann::json doc = to_json(report);
    doc["truth"] = failure_truth_json(*truth.failure);
    io::write_json(dir / (std::string(name) + ".json"), doc);
    add_rows(table, name, nearest_event(report, truth.failure->time_s), *truth.failure);
    scenarios.push_back(name);
  }
  if (scenarios.empty()) return {};
  std::string names;
  for (const std::string& n : scenarios) names += (names.empty() ? "`" : ", `") + n + "`";
  const std::string intro =
      "DP failure tests (" + names +
      "; IMCA M 190 annual trials, FMEA proving trials): `identify failure-test` on the "
      "logger's files — the trip found in the units' thrust feedback, the control origin from "
      "GNSS antenna 1 moved by its surveyed lever arm with the MRU's roll and pitch — against "
      "truth.json's `failure`, the simulator's measure of the same figures on the control "
      "origin's true motion: the failure instant, the peak excursion from the pre-failure mean "
      "and the time to it, the recovery (back within the pre-failure footprint for 10 s; never "
      "within the 300 s searched) and the peak heading change. The found event is the one "
      "nearest the true instant. JSON (with the truth): analysis/failure-test/<scenario>.json.";
  ReportSection s;
  s.title = "Failure test";
  s.markdown = intro + "\n\n" + report::render_markdown(table);
  s.html = "<p>" + intro + "</p>\n" + report::render_html(table);
  return s;
}

}  // namespace dynpos::analysis
