// agility (placeholder until implemented).

#include "commands.hpp"

namespace dynpos::cli {

void add_identify_agility(CLI::App& identify) {
  add_planned(identify, "agility", "Thrust agility: response time per direction and thruster",
              "63.2 % response times per thruster and direction, polar plot (figs. 3.1-3.3)");
}

scenario::ReportSection agility_demo_section(const std::filesystem::path& /*campaign_dir*/) {
  return {};
}

}  // namespace dynpos::cli
