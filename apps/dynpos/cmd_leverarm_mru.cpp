// mru (placeholder until implemented).

#include "commands.hpp"

namespace dynpos::cli {

void add_leverarm_mru(CLI::App& leverarm) {
  add_planned(leverarm, "mru", "MRU lever arms",
              "MRU observer (4.80) with observability diagnostics (4.77)");
}

scenario::ReportSection leverarm_mru_demo_section(const std::filesystem::path& /*campaign_dir*/) {
  return {};
}

}  // namespace dynpos::cli
