#pragma once
// What the validations of `identify vessel` check of a written vessel file: it runs in
// `simulate` (20 s of `scenario`) and in `capability` (level 1, every 30°) without edits.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/analysis/capability.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::testing {

inline void expect_identified_file_runs(const std::filesystem::path& file,
                                        const std::string& scenario) {
  const scenario::VesselConfig identified = scenario::load_vessel_config(file);
  scenario::ScenarioSpec spec = scenario::load_scenario(
      std::filesystem::path(DYNPOS_SOURCE_DIR) / "data" / "scenarios" / (scenario + ".toml"));
  spec.set_duration(20.0);
  EXPECT_NO_THROW(scenario::run_scenario(spec, identified, 1));
  analysis::CapabilityRequest cap;
  cap.vessel = file;
  cap.failure = "none";
  cap.direction_step = 30.0;
  EXPECT_NO_THROW(analysis::run_capability(cap));
}

}  // namespace dynpos::testing
