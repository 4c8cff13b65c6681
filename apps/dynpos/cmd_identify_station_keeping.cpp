// station-keeping (placeholder until implemented).

#include "commands.hpp"

namespace dynpos::cli {

void add_identify_station_keeping(CLI::App& identify) {
  add_planned(identify, "station-keeping", "Pure DP: position, heading, wind and thrust statistics",
              "stationkeeping statistics over a window (tables 3.11-3.22)");
}

scenario::ReportSection station_keeping_demo_section(
    const std::filesystem::path& /*campaign_dir*/) {
  return {};
}

}  // namespace dynpos::cli
