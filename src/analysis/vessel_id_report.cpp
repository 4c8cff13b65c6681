// The outputs of identify vessel and compare-trial: the identified vessel file (the starting
// file's text with values substituted), JSON, the text tables, the report folder and its SVGs.

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
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
  t.header = {"unit",  "steps",   "T [s]",       "σ T [s]",     "T model [s]",
              "δ [s]", "σ δ [s]", "δ model [s]", "c₊ [N/rps²]", "c₋ [N/rps²]"};
  for (const UnitIdentification& u : r.units) {
    t.rows.push_back({u.unit, std::to_string(u.steps), cell(u.time_constant_s, "{:.3f}"),
                      cell(u.time_constant_sigma_s, "{:.2g}"),
                      cell(u.model_time_constant_s, "{:.3f}"), cell(u.dead_time_s, "{:.3f}"),
                      cell(u.dead_time_sigma_s, "{:.2g}"), cell(u.model_dead_time_s, "{:.3f}"),
                      cell(u.c_forward, "{:.6g}"), cell(u.c_reverse, "{:.6g}")});
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
          {"c_reverse_sigma_N_per_rps2", number(u.c_reverse_sigma)}};
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

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// A table header line ("[name]", a comment may follow): the table's name; an array of tables
// ("[[…") or a dotted name: empty (no key of it is written); any other line: nullopt.
std::optional<std::string> table_header(const std::string& line) {
  std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '[') return std::nullopt;
  if (line.compare(i, 2, "[[") == 0) return std::string();
  i = line.find_first_not_of(" \t", i + 1);
  const std::size_t begin = std::min(i, line.size());
  while (i < line.size() && is_name_char(line[i])) ++i;
  const std::string name = line.substr(begin, i - begin);
  i = line.find_first_not_of(" \t", i);
  if (name.empty() || i == std::string::npos || line[i] != ']') return std::string();
  i = line.find_first_not_of(" \t", i + 1);
  return (i == std::string::npos || line[i] == '#') ? name : std::string();
}

// A "key = value" line: its indent and key; nullopt for any other line.
std::optional<std::pair<std::string, std::string>> key_line(const std::string& line) {
  const std::size_t begin = std::min(line.find_first_not_of(" \t"), line.size());
  std::size_t i = begin;
  while (i < line.size() && is_name_char(line[i])) ++i;
  if (i == begin) return std::nullopt;
  const std::size_t eq = line.find_first_not_of(" \t", i);
  if (eq == std::string::npos || line[eq] != '=') return std::nullopt;
  return std::pair{line.substr(0, begin), line.substr(begin, i - begin)};
}

}  // namespace

std::string identified_vessel_text(const VesselIdReport& report) {
  std::map<std::string, const VesselParameter*> pending;  // determined, not yet written
  for (const VesselParameter& p : report.parameters) {
    if (p.fitted) pending[p.key] = &p;
  }
  std::vector<std::string> lines = split_lines(report.vessel_text), out;
  std::string section;
  std::size_t last_key = 0;  // where the section's missing keys go (index in out)
  auto flush = [&]() {       // the section's determined keys the file lacks
    std::vector<std::string> add;
    for (auto it = pending.begin(); it != pending.end();) {
      if (!section.empty() && it->first.rfind(section + ".", 0) == 0) {
        add.push_back(value_line("", it->first.substr(section.size() + 1), *it->second));
        it = pending.erase(it);
      } else {
        ++it;
      }
    }
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(last_key), add.begin(), add.end());
  };
  for (const std::string& line : lines) {
    if (const auto table = table_header(line)) {
      flush();
      section = *table;
      out.push_back(line);
      last_key = out.size();
      continue;
    }
    const auto key = section.empty() ? std::nullopt : key_line(line);
    if (key) {
      const auto it = pending.find(section + "." + key->second);
      out.push_back(it == pending.end() ? line : value_line(key->first, key->second, *it->second));
      if (it != pending.end()) pending.erase(it);
      last_key = out.size();
      continue;
    }
    out.push_back(line);
  }
  flush();
  std::string text;
  for (const std::string& line : out) text += line + "\n";
  std::map<std::string, std::vector<std::string>> missing_tables;
  for (const auto& [key, p] : pending) {
    const std::string table = key.substr(0, key.find('.'));
    missing_tables[table].push_back(value_line("", key.substr(table.size() + 1), *p));
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
    text += "\nUnits: order → shaft speed steps (FOPDT) and thrust maps\n" +
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
      "<h2>Values</h2>\n{}\n<h2>Units</h2>\n<p>Order → shaft speed steps (FOPDT fits) and "
      "thrust maps, with the starting file's model at the same steps.</p>\n{}\n"
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
