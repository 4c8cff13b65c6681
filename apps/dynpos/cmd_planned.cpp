// Subcommands of the CLI contract that a later version fills in. They parse nothing beyond
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

}  // namespace dynpos::cli
