// Identify the steps of a step test from a CSV log (thesis section 3.2): find every step of the
// input, then fit a first-order-plus-dead-time model (3.7) to the output's response to each.
//
//   identify_steps [LOG.csv]
//
// The log's first column is time [s], then the input (lever_pct) and the output (shaft_rpm).
// The default log, data/propeller_steps.csv, holds three steps of a propeller lever (0 → 40 →
// 80 → 20 %) with a shaft speed that follows with K = 1.5 rpm/%, T = 1.6, 2.4, 2.0 s and
// δ = 1.0, 1.2, 0.8 s, plus noise; the fits should come close to those.

#include <fmt/core.h>

#include <exception>
#include <filesystem>

#include "dynpos/core/log.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/step_detector.hpp"
#include "dynpos/io/csv_reader.hpp"

namespace {

void identify(const std::filesystem::path& csv) {
  using namespace dynpos;
  // Every numeric column becomes a channel named after its header. A unit in brackets
  // ("speed [kn]") would be converted to SI; plain names keep the numbers as logged.
  const core::Log log = io::read_csv_all(csv);
  const auto& t = log.time();
  const auto& lever = log.values("lever_pct");
  const auto& shaft = log.values("shaft_rpm");

  // Steps of at least 5 % of lever; each step's window runs until the next step.
  ident::StepDetectorOptions detect;
  detect.min_step = 5.0;
  const ident::StepDetection found = ident::detect_steps(t, lever, detect);
  fmt::print("{} steps found in {}\n", found.steps.size(), csv.filename().string());

  for (const ident::Step& step : found.steps) {
    // Least squares with the dead time estimated (the default method); bad data comes back as
    // a status and warnings, not as an exception.
    const ident::FopdtFitResult fit = ident::fit_fopdt(t, shaft, step);
    if (fit.status == ident::FitStatus::kFailed) {
      fmt::print("step at {:.1f} s: {}\n", step.t_step, fit.message);
      continue;
    }
    fmt::print(
        "step at {:5.1f} s, lever {:3.0f} -> {:3.0f} %: K = {:.2f} rpm/%, T = {:.2f} s, "
        "delay = {:.2f} s\n",
        step.t_step, *step.u_before, *step.u_after, fit.gain->value, fit.time_constant->value,
        fit.dead_time->value);
    for (const ident::FitWarning& w : fit.warnings) fmt::print("  warning: {}\n", w.message);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    identify(argc > 1 ? argv[1] : DYNPOS_EXAMPLE_DATA "/propeller_steps.csv");
    return 0;
  } catch (const std::exception& e) {  // bad input: core::InputError names file, line, column
    fmt::print(stderr, "identify_steps: {}\n", e.what());
    return 1;
  }
}
