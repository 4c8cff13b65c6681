// gnss (placeholder until implemented).

#include "commands.hpp"

namespace dynpos::cli {

void add_leverarm_gnss(CLI::App& leverarm) {
  add_planned(leverarm, "gnss", "GNSS antenna lever arms",
              "Luenberger (4.26) and adaptive (4.42, 4.48) observers, batch least squares, "
              "observability and persistence-of-excitation diagnostics");
}

scenario::ReportSection leverarm_gnss_demo_section(const std::filesystem::path& /*campaign_dir*/) {
  return {};
}

}  // namespace dynpos::cli
