// The outputs of identify vessel and compare-trial: the identified vessel file (the starting
// file's text with values substituted), JSON, the text tables, the report folder and its SVGs.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/vessel_id.hpp"
#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/io/markup.hpp"
#include "dynpos/report/decimate.hpp"
#include "dynpos/report/svg_plot.hpp"
#include "dynpos/report/table.hpp"
#include "toml_text_outline.hpp"

namespace dynpos::analysis {
namespace {

constexpr const char* kChannels[3] = {"u", "v", "r"};

nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// A TOML float with `digits` significant digits: a decimal point or an exponent always.
std::string toml_number(double v, int digits = 6) {
  std::string s = fmt::format("{:.{}g}", v, digits);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string percent_cell(double v) {
  return std::isfinite(v) ? fmt::format("{:.2f}", 100.0 * v) : std::string("—");
}

// "KEY = VALUE  # identified: …" for a determined parameter.
std::string value_line(const std::string& indent, const std::string& key,
                       const VesselParameter& p) {
  // At least 6 significant digits, and enough that the rounding is under a tenth of σ (a thrust
  // map the DP system's feedback gives to rounding).
  const double rel = p.sigma / std::abs(p.value);
  const int digits =
      rel > 0.0 ? std::clamp(static_cast<int>(std::ceil(-std::log10(rel))) + 2, 6, 17) : 6;
  return fmt::format("{}{} = {}  # {}: sigma {:.3g} ({:.1f} %), {}; start {}", indent, key,
                     toml_number(p.value, digits), p.determined ? "identified" : "fitted", p.sigma,
                     100.0 * p.sigma / std::abs(p.value), p.note, toml_number(p.start));
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

report::Table parameter_table(const VesselIdReport& r) {
  report::Table t;
  t.header = {"key", "start", "identified", "σ", "σ [%]", "determined"};
  for (const VesselParameter& p : r.parameters) {
    t.rows.push_back(
        {p.key, fmt::format("{:.6g}", p.start), fmt::format("{:.6g}", p.value),
         std::isfinite(p.sigma) ? fmt::format("{:.3g}", p.sigma) : "—",
         std::isfinite(p.sigma) ? fmt::format("{:.2f}", 100 * p.sigma / std::abs(p.value)) : "—",
         p.determined ? "yes" : "no"});
  }
  return t;
}

std::string cell(double v, const char* format_spec) {
  return std::isfinite(v) ? fmt::format(fmt::runtime(format_spec), v) : std::string("—");
}

// The units' measured dynamics against the starting file's model, and their thrust maps.
report::Table unit_table(const VesselIdReport& r) {
  report::Table t;
  t.header = {"unit",  "steps",      "T [s]",       "σ T [s]",     "T model [s]",
              "δ [s]", "σ δ [s]",    "δ model [s]", "c₊ [N/rps²]", "c₋ [N/rps²]",
              "turns", "slew [°/s]", "σ slew [°/s]"};
  for (const UnitIdentification& u : r.units) {
    t.rows.push_back({u.unit, std::to_string(u.steps), cell(u.time_constant_s, "{:.3f}"),
                      cell(u.time_constant_sigma_s, "{:.2g}"),
                      cell(u.model_time_constant_s, "{:.3f}"), cell(u.dead_time_s, "{:.3f}"),
                      cell(u.dead_time_sigma_s, "{:.2g}"), cell(u.model_dead_time_s, "{:.3f}"),
                      cell(u.c_forward, "{:.6g}"), cell(u.c_reverse, "{:.6g}"),
                      std::to_string(u.turns), cell(u.slew_rate_deg_per_s, "{:.3f}"),
                      cell(u.slew_rate_sigma_deg_per_s, "{:.2g}")});
  }
  return t;
}

nlohmann::json unit_json(const UnitIdentification& u) {
  return {{"unit", u.unit},
          {"steps", u.steps},
          {"time_constant_s", number(u.time_constant_s)},
          {"time_constant_sigma_s", number(u.time_constant_sigma_s)},
          {"dead_time_s", number(u.dead_time_s)},
          {"dead_time_sigma_s", number(u.dead_time_sigma_s)},
          {"model_time_constant_s", number(u.model_time_constant_s)},
          {"model_dead_time_s", number(u.model_dead_time_s)},
          {"c_forward_N_per_rps2", number(u.c_forward)},
          {"c_forward_sigma_N_per_rps2", number(u.c_forward_sigma)},
          {"c_reverse_N_per_rps2", number(u.c_reverse)},
          {"c_reverse_sigma_N_per_rps2", number(u.c_reverse_sigma)},
          {"turns", u.turns},
          {"slew_rate_deg_per_s", number(u.slew_rate_deg_per_s)},
          {"slew_rate_sigma_deg_per_s", number(u.slew_rate_sigma_deg_per_s)}};
}

report::Table nrmse_table(const std::vector<TestResponse>& tests) {
  report::Table t;
  t.header = {"test", "NRMSE u [%]", "NRMSE v [%]", "NRMSE r [%]", "NRMSE track [%]"};
  for (const TestResponse& r : tests) {
    t.rows.push_back({r.held_out ? r.name + " (held out)" : r.name, percent_cell(r.nrmse[0]),
                      percent_cell(r.nrmse[1]), percent_cell(r.nrmse[2]),
                      percent_cell(r.track_nrmse)});
  }
  return t;
}

nlohmann::json response_json(const TestResponse& r) {
  return {{"name", r.name},
          {"held_out", r.held_out},
          {"nrmse",
           {{"u", number(r.nrmse[0])},
            {"v", number(r.nrmse[1])},
            {"r", number(r.nrmse[2])},
            {"track", number(r.track_nrmse)}}},
          {"current_n_mps", {r.current_n.x(), r.current_n.y()}}};
}

// The points of (x, y) a figure 900 px wide can show (min and max per pixel column).
report::Series drawn(const std::string& label, const std::vector<double>& x,
                     const std::vector<double>& y, const char* color, double width) {
  report::Series out{label, {}, {}, color, width};
  if (x.size() < 2) return out;
  for (std::size_t i : report::minmax_decimate(x, y, x.front(), x.back(), 800)) {
    out.x.push_back(x[i]);
    out.y.push_back(y[i]);
  }
  return out;
}

// Measured dots and re-simulated line of u, v, r (deg/s), and the track when logged.
report::Figure response_figure(const TestResponse& r, const std::string& title) {
  report::Figure f;
  f.title = title;
  const char* labels[3] = {"surge speed u", "sway speed v", "yaw rate r"};
  const char* units[3] = {"m/s", "m/s", "deg/s"};
  for (std::size_t c = 0; c < 3; ++c) {
    const double k = c == 2 ? 180.0 / M_PI : 1.0;
    std::vector<double> tm, ym, ys(r.simulated[c].size());
    for (std::size_t i = 0; i < r.time_s.size(); ++i) {
      ys[i] = k * r.simulated[c][i];
      if (!std::isnan(r.measured[c][i])) {
        tm.push_back(r.time_s[i]);
        ym.push_back(k * r.measured[c][i]);
      }
    }
    report::Panel p;
    p.title = fmt::format("{} (NRMSE {} %)", labels[c], percent_cell(r.nrmse[c]));
    p.x_axis = {"Time", "s", {}, {}};
    p.y_axis = {kChannels[c], units[c], {}, {}};
    p.series.push_back(drawn("measured", tm, ym, "#999999", 1.0));
    p.series.push_back(drawn("re-simulated", r.time_s, ys, "#d62728", 1.5));
    f.panels.push_back(p);
  }
  if (!r.north_m.empty()) {
    report::Panel p;
    p.title = fmt::format("track (NRMSE {} %)", percent_cell(r.track_nrmse));
    p.x_axis = {"East", "m", {}, {}};
    p.y_axis = {"North", "m", {}, {}};
    p.series.push_back({"logged", r.east_m, r.north_m, "#999999", 1.0});
    p.series.push_back({"re-simulated", r.sim_east_m, r.sim_north_m, "#d62728", 1.5});
    f.panels.push_back(p);
  }
  return f;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  io::AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

std::string svg_name(std::size_t k) { return fmt::format("test-{}.svg", k + 1); }

// Where a parameter's key goes: a table of the outline and its key there.
struct Target {
  std::size_t table = 0;  // in the outline; none: a table the file lacks
  bool found = false;
  std::string table_name, key;
};

// "table.key" in its [table]; "array.NAME.key" in the [[array]] element named NAME (an error
// when the file has no such element: the parameters come from the file).
Target target(const std::vector<toml_text::TableLines>& tables, const std::string& key) {
  const std::size_t dot = key.find('.');
  const std::size_t last = key.rfind('.');
  Target t{0, false, key.substr(0, dot), key.substr(last + 1)};
  const std::string element = last > dot ? key.substr(dot + 1, last - dot - 1) : std::string();
  bool array = false;
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const toml_text::TableLines& table = tables[k];
    if (table.name != t.table_name) continue;
    array = array || table.array;
    if (table.array ? table.element == element : element.empty()) {
      t.table = k;
      t.found = true;
      return t;
    }
  }
  if (!element.empty()) {
    throw std::invalid_argument(fmt::format("the vessel file has no [[{}]] table named '{}' for {}",
                                            t.table_name, element, key));
  }
  if (array) {
    throw std::invalid_argument(fmt::format("{} names no element of [[{}]]", key, t.table_name));
  }
  return t;
}

}  // namespace

std::string identified_vessel_text(const VesselIdReport& report) {
  const std::vector<std::string> lines = split_lines(report.vessel_text);
  const std::vector<toml_text::TableLines> tables = toml_text::outline(lines);
  std::map<std::size_t, std::pair<std::size_t, std::string>> replace;  // first → (last, line)
  std::map<std::size_t, std::vector<std::string>> insert;              // after line → lines
  std::map<std::string, std::vector<std::string>> missing_tables;
  for (const VesselParameter& p : report.parameters) {
    if (!p.fitted) continue;
    const Target t = target(tables, p.key);
    if (!t.found) {
      missing_tables[t.table_name].push_back(value_line("", t.key, p));
      continue;
    }
    const toml_text::TableLines& table = tables[t.table];
    const auto k = std::find_if(table.keys.begin(), table.keys.end(),
                                [&](const toml_text::KeyLines& kl) { return kl.key == t.key; });
    if (k != table.keys.end()) {
      replace[k->first] = {k->last, value_line(k->indent, t.key, p)};
      continue;
    }
    // A key the table leaves at its default: after its last key (or its header).
    const std::size_t after =
        table.keys.empty() ? table.header.value_or(0) : table.keys.back().last;
    const std::string indent = table.keys.empty() ? std::string() : table.keys.front().indent;
    insert[after].push_back(value_line(indent, t.key, p));
  }
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto r = replace.find(i);
    if (r != replace.end()) {
      text += r->second.second + "\n";
      i = r->second.first;
    } else {
      text += lines[i] + "\n";
    }
    if (const auto in = insert.find(i); in != insert.end()) {
      for (const std::string& l : in->second) text += l + "\n";
    }
  }
  for (const auto& [table, add] : missing_tables) {
    text += "\n[" + table + "]\n";
    for (const std::string& l : add) text += l + "\n";
  }
  return text;
}

nlohmann::json to_json(const VesselIdReport& r) {
  nlohmann::json doc;
  doc["vessel_file"] = r.vessel_file.string();
  doc["parameters"] = nlohmann::json::array();
  for (const VesselParameter& p : r.parameters) {
    doc["parameters"].push_back({{"key", p.key},
                                 {"unit", p.unit},
                                 {"start", p.start},
                                 {"value", p.value},
                                 {"sigma", number(p.sigma)},
                                 {"determined", p.determined},
                                 {"fitted", p.fitted},
                                 {"note", p.note}});
  }
  doc["units"] = nlohmann::json::array();
  for (const UnitIdentification& u : r.units) doc["units"].push_back(unit_json(u));
  doc["tests"] = nlohmann::json::array();
  nlohmann::json cv = nullptr;
  for (const TestResponse& t : r.tests) {
    doc["tests"].push_back(response_json(t));
    if (t.held_out) cv = response_json(t);
  }
  doc["cross_validation"] = cv;
  doc["iterations"] = r.iterations;
  doc["solver_message"] = r.solver_message;
  doc["run_time_s"] = r.run_time_s;
  doc["inputs"] = nlohmann::json::array();
  for (const io::InputReport& in : r.inputs) doc["inputs"].push_back(io::to_json(in));
  return doc;
}

std::string to_text(const VesselIdReport& r) {
  std::size_t determined = 0;
  for (const VesselParameter& p : r.parameters) determined += p.determined ? 1 : 0;
  std::string text = fmt::format(
      "{} tests, {} of {} values determined ({} iterations, {:.1f} s){}\n\n",
      r.tests.size() - (r.held_out.empty() ? 0 : 1), determined, r.parameters.size(), r.iterations,
      r.run_time_s, r.solver_message.empty() ? "" : "; solver: " + r.solver_message);
  text += report::render_text(parameter_table(r)) + "\n";
  for (const VesselParameter& p : r.parameters) {
    if (!p.determined) text += fmt::format("  {}: not determined: {}\n", p.key, p.note);
  }
  if (!r.units.empty()) {
    text += "\nUnits: order → shaft speed steps (FOPDT), thrust maps and azimuth turns\n" +
            report::render_text(unit_table(r));
  }
  return text + "\n" + report::render_text(nrmse_table(r.tests));
}

void write_report(const VesselIdReport& r, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::string figures;
  for (std::size_t k = 0; k < r.tests.size(); ++k) {
    const TestResponse& t = r.tests[k];
    const std::string title = t.held_out ? t.name + " (held out)" : t.name;
    report::write_svg(dir / svg_name(k), response_figure(t, title));
    figures += fmt::format("<h3>{}</h3>\n<img src=\"{}\" alt=\"{}\">\n", io::escape_markup(title),
                           svg_name(k), io::escape_markup(title));
  }
  const std::string html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<title>dynpos identify vessel</title>\n<style>body{{font-family:sans-serif;margin:2em;"
      "max-width:70em}}table{{border-collapse:collapse}}td,th{{border:1px solid #ccc;"
      "padding:0.3em 0.6em;text-align:right}}td:first-child{{text-align:left}}</style></head>\n"
      "<body><h1>Vessel identification</h1>\n<p>Starting vessel file <code>{}</code>. "
      "Output-error fit of the hull model to the logged u, v, r (docs/theory.md).</p>\n"
      "<h2>Values</h2>\n{}\n<h2>Units</h2>\n<p>Order → shaft speed steps (FOPDT fits), "
      "thrust maps and azimuth turns, with the starting file's model at the same steps.</p>\n{}\n"
      "<h2>Measured and re-simulated</h2>\n{}\n{}</body></html>\n",
      io::escape_markup(r.vessel_file.string()), report::render_html(parameter_table(r)),
      report::render_html(unit_table(r)), report::render_html(nrmse_table(r.tests)), figures);
  write_text_file(dir / "index.html", html);
}

Written write_outputs(const VesselIdReport& report, const std::filesystem::path& vessel_out,
                      const Outputs& outputs) {
  Written written;
  if (!vessel_out.empty()) {
    write_text_file(vessel_out, identified_vessel_text(report));
    written.push_back(vessel_out);
  }
  if (!outputs.figures.empty()) {
    write_report(report, outputs.figures);
    written.push_back(outputs.figures / "index.html");
  }
  write_json_output(outputs, to_json(report), written);
  return written;
}

nlohmann::json to_json(const CompareTrialReport& r) {
  nlohmann::json doc = response_json(r.test);
  doc["vessel_file"] = r.vessel_file.string();
  doc["input"] = io::to_json(r.input);
  return doc;
}

std::string to_text(const CompareTrialReport& r) {
  return fmt::format("{} re-simulated with {}\n\n", r.test.name, r.vessel_file.string()) +
         report::render_text(nrmse_table({r.test}));
}

Written write_outputs(const CompareTrialReport& report, const Outputs& outputs) {
  Written written;
  if (!outputs.figures.empty()) {
    report::write_svg(outputs.figures, response_figure(report.test, report.test.name));
    written.push_back(outputs.figures);
  }
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
