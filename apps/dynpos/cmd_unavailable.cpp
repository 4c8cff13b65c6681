// Subcommands of the CLI contract that later versions fill in. They parse nothing beyond
// --help, say what they will do, and exit with kExitUnavailable.

#include "commands.hpp"

namespace dynpos::cli {
namespace {

void add_planned(CLI::App& parent, const std::string& name, const std::string& description,
                 const std::string& planned) {
  CLI::App* sub = parent.add_subcommand(name, description);
  sub->allow_extras();
  sub->footer("Not available in this version. Planned: " + planned);
  sub->callback(
      [full = parent.get_name() == "dynpos" ? name : parent.get_name() + " " + name, planned] {
        throw Unavailable{full, planned};
      });
}

}  // namespace

void register_identify(CLI::App& app) {
  CLI::App* identify = app.add_subcommand(
      "identify", "Identify thruster and vessel dynamics from sea-trial logs (thesis ch. 3)");
  identify->require_subcommand(1, 1);
  add_planned(*identify, "step", "Step-test identification: FOPDT gain, time constant, dead time",
              "automatic step detection, Smith's two-point and least-squares FOPDT fits (3.7-3.9)");
  add_planned(*identify, "agility", "Thrust agility: response time per direction and thruster",
              "63.2 % response times per thruster and direction, polar plot (figs. 3.1-3.3)");
  add_planned(*identify, "four-corner", "DP 4-corner: legs, durations, thrust and energy",
              "leg segmentation, accumulated thrust [kNs] and energy [kJ] (table 3.6)");
  add_planned(*identify, "station-keeping",
              "Pure DP: position, heading, wind and thrust statistics",
              "stationkeeping statistics over a window (tables 3.11-3.22)");
}

void register_leverarm(CLI::App& app) {
  CLI::App* leverarm = app.add_subcommand(
      "leverarm", "Estimate GNSS antenna and MRU lever arms from vessel motion (thesis ch. 4)");
  leverarm->require_subcommand(1, 1);
  add_planned(*leverarm, "gnss", "GNSS antenna lever arms",
              "Luenberger (4.26) and adaptive (4.42, 4.48) observers, batch least squares, "
              "observability and persistence-of-excitation diagnostics");
  add_planned(*leverarm, "mru", "MRU lever arms",
              "MRU observer (4.80) with observability diagnostics (4.77)");
}

void register_compare(CLI::App& app) {
  add_planned(app, "compare", "Compare two results of the same analysis (A.json B.json)",
              "side-by-side tables with differences, e.g. before and after a retrofit");
}

}  // namespace dynpos::cli
