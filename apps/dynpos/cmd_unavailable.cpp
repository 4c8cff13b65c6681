// Subcommands of the CLI contract that later versions fill in. They parse nothing beyond
// --help, say what they will do, and exit with kExitUnavailable.

#include "commands.hpp"

namespace dynpos::cli {

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
