#pragma once
// The options of a DP observer run over a log, shared by `estimate` and `consequence`: the log
// options, --vessel, --arm, --observer, --tp, --rate, --max-hold, --settle, --from, --to.

#include <CLI/CLI.hpp>
#include <vector>

#include "dynpos/analysis/estimate.hpp"
#include "dynpos/analysis/option_text.hpp"
#include "log_input.hpp"

namespace dynpos::cli {

struct EstimateCliOptions {
  std::vector<double> arm_m;  ///< X,Y[,Z] [m]
  analysis::EstimateRequest request;

  /// Adds the options to `sub` (cmd_estimate.cpp).
  void add(CLI::App& sub);
  /// The request with the arm filled in.
  analysis::EstimateRequest resolved() const;
};

}  // namespace dynpos::cli
