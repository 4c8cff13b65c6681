// four-corner (placeholder until implemented).

#include "commands.hpp"

namespace dynpos::cli {

void add_identify_four_corner(CLI::App& identify) {
  add_planned(identify, "four-corner", "DP 4-corner: legs, durations, thrust and energy",
              "leg segmentation, accumulated thrust [kNs] and energy [kJ] (table 3.6)");
}

scenario::ReportSection four_corner_demo_section(const std::filesystem::path& /*campaign_dir*/) {
  return {};
}

}  // namespace dynpos::cli
