// dynpos leverarm gnss|mru: thesis chapter 4. Each estimator has a file of its own.

#include "commands.hpp"

namespace dynpos::cli {

void register_leverarm(CLI::App& app) {
  CLI::App* leverarm = app.add_subcommand(
      "leverarm", "Estimate GNSS antenna and MRU lever arms from vessel motion (thesis ch. 4)");
  leverarm->require_subcommand(1, 1);
  add_leverarm_gnss(*leverarm);
  add_leverarm_mru(*leverarm);
}

}  // namespace dynpos::cli
