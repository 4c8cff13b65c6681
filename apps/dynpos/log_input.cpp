#include "log_input.hpp"

namespace dynpos::cli {

void LogInput::add_options(CLI::App& sub, const std::string& roles_help) {
  sub.add_option("log", log, "Log: CSV, or an NMEA 0183 capture (detected by content)")
      ->required()
      ->check(CLI::ExistingFile);
  sub.add_option("--map", map_file, "Column map (TOML): roles → columns, units, scales")
      ->check(CLI::ExistingFile);
  sub.add_option("--col", columns, "ROLE=COLUMN (repeatable). Roles: " + roles_help);
  sub.add_option("--unit", units, "ROLE=UNIT (repeatable), e.g. thrust.port=kN");
  sub.add_option("--format", format, "Log format: auto (by content), csv or nmea")
      ->default_str("auto");
  sub.add_flag("--strict", strict, "An NMEA line that cannot be used is an error (file:line)");
}

}  // namespace dynpos::cli
