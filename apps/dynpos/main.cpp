// dynpos: dynamic positioning toolkit — identification, lever-arm calibration, hybrid control
// and a virtual sea trial of R/V Gunnerus. This file only wires the subcommands together.

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <exception>

#include "commands.hpp"
#include "dynpos/analysis/option_spelling.hpp"
#include "dynpos/core/error.hpp"

int main(int argc, char** argv) {
  using namespace dynpos::cli;
  CLI::App app{
      "dynpos " DYNPOS_VERSION
      " — dynamic positioning toolkit: identify thruster and vessel dynamics from sea-trial\n"
      "logs, calibrate GNSS/MRU lever arms, verify hybrid integral action, and run a virtual\n"
      "sea trial of R/V Gunnerus with known truth.",
      "dynpos"};
  app.set_version_flag("--version", DYNPOS_VERSION);
  app.require_subcommand(1, 1);
  app.footer(
      "Run 'dynpos SUBCOMMAND --help' for the options of each subcommand.\n"
      "Exit codes: 0 success, 1 failure, 2 bad input or options, 3 not in this version.");

  register_simulate(app);
  register_identify(app);
  register_leverarm(app);
  register_hybrid(app);
  register_compare(app);
  register_capability(app);
  register_montecarlo(app);
  register_demo(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitInputError;
  } catch (const dynpos::core::InputError& e) {
    fmt::print(stderr, "dynpos: error: {}\n", dynpos::analysis::cli_message(e));
    return kExitInputError;
  } catch (const Unavailable& u) {
    fmt::print(stderr, "dynpos {}: not available in this version; planned: {}\n", u.command,
               u.planned);
    return kExitUnavailable;
  } catch (const std::exception& e) {
    fmt::print(stderr, "dynpos: error: {}\n", e.what());
    return kExitFailure;
  }
  return kExitOk;
}
