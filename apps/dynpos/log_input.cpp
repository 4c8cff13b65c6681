#include "log_input.hpp"

namespace dynpos::cli {

void LogInput::add_options(CLI::App& sub, const std::string& roles_help) {
  sub.add_option("log", log, "CSV log")->required()->check(CLI::ExistingFile);
  sub.add_option("--map", map_file, "Column map (TOML): roles → columns, units, scales")
      ->check(CLI::ExistingFile);
  sub.add_option("--col", columns, "ROLE=COLUMN (repeatable). Roles: " + roles_help);
  sub.add_option("--unit", units, "ROLE=UNIT (repeatable), e.g. thrust.port=kN");
}

}  // namespace dynpos::cli
