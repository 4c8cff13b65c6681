#include "dynpos/capability/environment_table.hpp"

#include <fmt/core.h>

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <fstream>

#include "dynpos/core/error.hpp"
#include "dynpos/io/text_file.hpp"

namespace dynpos::capability {

Environment EnvironmentTable::at(double wind_mps) const {
  if (wind_mps <= rows.front().wind_mps)
    return {wind_mps, rows.front().hs_m, rows.front().tp_s, rows.front().current_mps};
  if (wind_mps >= rows.back().wind_mps)
    return {wind_mps, rows.back().hs_m, rows.back().tp_s, rows.back().current_mps};
  const auto hi = std::upper_bound(rows.begin(), rows.end(), wind_mps,
                                   [](double w, const Environment& e) { return w < e.wind_mps; });
  const Environment& b = *hi;
  const Environment& a = *(hi - 1);
  const double s = (wind_mps - a.wind_mps) / (b.wind_mps - a.wind_mps);
  const auto lerp = [s](double x, double y) { return x + s * (y - x); };
  // A calm row has no period: the first waves take the next row's.
  const double tp_a = a.tp_s > 0.0 ? a.tp_s : b.tp_s;
  return {wind_mps, lerp(a.hs_m, b.hs_m), lerp(tp_a, b.tp_s), lerp(a.current_mps, b.current_mps)};
}

void EnvironmentTable::validate() const {
  if (rows.size() < 2) {
    throw core::InputError({name, {}, {}, {}}, "an environment table needs at least 2 rows",
                           "give rows of increasing wind speed");
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Environment& e = rows[i];
    for (const double v : {e.wind_mps, e.hs_m, e.tp_s, e.current_mps}) {
      if (!std::isfinite(v) || v < 0.0) {
        throw core::InputError({name, {}, {}, {}},
                               fmt::format("row {}: values must be finite and ≥ 0", i + 1));
      }
    }
    if (i > 0 && e.wind_mps <= rows[i - 1].wind_mps) {
      throw core::InputError({name, {}, {}, {}},
                             fmt::format("row {}: wind {} m/s is not above the row before's {}",
                                         i + 1, e.wind_mps, rows[i - 1].wind_mps),
                             "order the rows by increasing wind speed");
    }
  }
}

const EnvironmentTable& dnv_level1_table() {
  static const EnvironmentTable table{"DNV-ST-0111 Level 1",
                                      {{0.0, 0.0, 0.0, 0.0},
                                       {1.5, 0.1, 3.5, 0.25},
                                       {3.4, 0.4, 4.5, 0.50},
                                       {5.4, 0.8, 5.5, 0.75},
                                       {7.9, 1.3, 6.5, 0.75},
                                       {10.7, 2.1, 7.5, 0.75},
                                       {13.8, 3.1, 8.5, 0.75},
                                       {17.1, 4.2, 9.0, 0.75},
                                       {20.7, 5.7, 10.0, 0.75},
                                       {24.4, 7.4, 10.5, 0.75},
                                       {28.4, 9.5, 11.5, 0.75},
                                       {32.6, 12.1, 12.0, 0.75}}};
  return table;
}

int dp_number_for_wind(double wind_mps) {
  const auto& rows = dnv_level1_table().rows;
  int n = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i].wind_mps <= wind_mps) n = static_cast<int>(i);
  }
  return n;
}

EnvironmentTable read_site_table(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw core::InputError({path, {}, {}, {}}, "cannot open the site table",
                           "check the path and its permissions");
  }
  const std::string text =
      io::read_capped(in, path, io::kMaxTomlBytes, "a site table is a few kB of TOML");
  toml::table doc;
  try {
    doc = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw core::InputError({path, where.line, where.column, {}}, std::string(e.description()),
                           "fix the TOML syntax");
  }
  EnvironmentTable table{path, {}};
  const toml::array* rows = doc["environment"].as_array();
  if (rows == nullptr) {
    throw core::InputError({path, {}, {}, "environment"}, "no [[environment]] rows",
                           "give rows with wind_mps, hs_m, tp_s and current_mps");
  }
  for (const toml::node& node : *rows) {
    const toml::table* row = node.as_table();
    const auto line = node.source().begin.line;
    Environment e;
    for (const auto& [key, field] : {std::pair{"wind_mps", &e.wind_mps},
                                     {"hs_m", &e.hs_m},
                                     {"tp_s", &e.tp_s},
                                     {"current_mps", &e.current_mps}}) {
      const auto value = row ? (*row)[key].value<double>() : std::nullopt;
      if (!value) {
        throw core::InputError({path, line, {}, key}, std::string("missing or not a number"),
                               "each row needs wind_mps, hs_m, tp_s and current_mps");
      }
      *field = *value;
    }
    if (row != nullptr) {
      for (const auto& [key, unused] : *row) {
        const std::string k(key.str());
        if (k != "wind_mps" && k != "hs_m" && k != "tp_s" && k != "current_mps") {
          throw core::InputError({path, key.source().begin.line, key.source().begin.column, k},
                                 "unknown key", "the keys are wind_mps, hs_m, tp_s, current_mps");
        }
      }
    }
    table.rows.push_back(e);
  }
  table.validate();
  return table;
}

}  // namespace dynpos::capability
