#include "log_input.hpp"

namespace dynpos::cli {

void add_time_options(CLI::App& sub, analysis::LogSource& source) {
  sub.add_option("--time-format", source.time_format,
                 "Time stamps: auto (default), seconds, epoch-s|ms|us|ns, iso8601, time-of-day, "
                 "sec-nsec");
  sub.add_option("--date", source.date, "Date of time-of-day stamps, YYYY-MM-DD");
  sub.add_option("--time-order", source.time_order,
                 "Repeated or backward times: error (default), drop-duplicates, "
                 "drop-non-increasing");
}

void LogInput::add_options(CLI::App& sub, const std::string& roles_help) {
  sub.add_option("log", log, "CSV log")->required()->check(CLI::ExistingFile);
  sub.add_option("--map", map_file, "Column map (TOML): roles → columns, units, scales")
      ->check(CLI::ExistingFile);
  sub.add_option("--col", columns, "ROLE=COLUMN (repeatable). Roles: " + roles_help);
  sub.add_option("--unit", units, "ROLE=UNIT (repeatable), e.g. thrust.port=kN");
  add_time_options(sub, *this);
}

}  // namespace dynpos::cli
