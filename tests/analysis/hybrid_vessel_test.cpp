#include "dynpos/analysis/hybrid_vessel.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::analysis {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::filesystem::path kScenarios =
    std::filesystem::path(DYNPOS_SOURCE_DIR) / "data" / "scenarios";

TEST(HybridVesselRequest, UnknownLoadCaseIsNamedWithWhatEachCaseIs) {
  try {
    (void)hybrid_load_from_string("ice2");
    FAIL() << "an unknown load case was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "scenario");
    EXPECT_EQ(e.problem(), "unknown load scenario 'ice2'");
    // The hint is generated from the scenario files' first load.
    EXPECT_EQ(e.hint(),
              "choose ice (a 20 kN ice load sets in) or mooring (a mooring line holding 20 kN "
              "snaps)");
  }
}

TEST(HybridVesselRequest, WithinMustBePositive) {
  for (const double within : {0.0, -1.0}) {
    HybridVesselRequest r{HybridLoad::kMooring, 1, within};
    try {
      r.validate();
      FAIL() << "within " << within << " was accepted";
    } catch (const core::InputError& e) {
      EXPECT_EQ(e.option(), "within");
    }
  }
  EXPECT_NO_THROW((HybridVesselRequest{HybridLoad::kIce, 1, 0.5}.validate()));
}

TEST(HybridVessel, LoadCasesNameTheirScenarioFiles) {
  EXPECT_EQ(hybrid_load_from_string("ice"), HybridLoad::kIce);
  EXPECT_EQ(hybrid_load_from_string("mooring"), HybridLoad::kMooring);
  EXPECT_STREQ(load_case(HybridLoad::kIce).scenario_file, "dp-ice-load");
  EXPECT_STREQ(load_case(HybridLoad::kMooring).scenario_file, "dp-mooring-snap");
  EXPECT_EQ(to_string(HybridLoad::kMooring), "mooring");
  for (const LoadCase& c : kHybridVesselLoadCases) {
    EXPECT_TRUE(std::filesystem::exists(kScenarios / (std::string(c.scenario_file) + ".toml")))
        << c.scenario_file;
  }
}

TEST(HybridVessel, LoadPhraseFollowsTheScenariosFirstLoad) {
  const LoadCase ice = kHybridVesselLoadCases[0];
  const LoadCase mooring = kHybridVesselLoadCases[1];
  scenario::ScenarioSpec spec;
  spec.loads.push_back({120.0, 1e300, 3000.0, -4000.0, 0.0});  // 5 kN, sets in at 120 s
  EXPECT_EQ(load_case_phrase(ice, spec), "a 5 kN ice load sets in");
  spec.loads.front().t_on_s = 0.0;  // on from the start: released later
  spec.loads.front().t_off_s = 200.0;
  EXPECT_EQ(load_case_phrase(mooring, spec), "a mooring line holding 5 kN snaps");
  spec.loads.clear();
  EXPECT_EQ(load_case_phrase(ice, spec), "ice load");
}

// Both designs on the 900 s ice scenario: about a second of simulation, run once.
const HybridVesselReport& ice_report() {
  static const HybridVesselReport r = run_hybrid_vessel({HybridLoad::kIce, 1});
  return r;
}

TEST(HybridVessel, HybridIntegralActionRecoversFasterFromTheIceLoad) {
  const HybridVesselReport& r = ice_report();
  EXPECT_EQ(r.scenario_name, "dp-ice-load");
  EXPECT_EQ(r.comparison.t_load_s, 300.0);
  const scenario::LoadResponse& c = r.comparison.conventional.response;
  const scenario::LoadResponse& h = r.comparison.hybrid.response;
  EXPECT_EQ(r.comparison.conventional.jumps, 0u);
  EXPECT_GT(r.comparison.hybrid.jumps, 0u);
  EXPECT_LT(h.peak_offset_m, c.peak_offset_m);
  ASSERT_TRUE(c.back_within_s && h.back_within_s);
  EXPECT_LT(*h.back_within_s, *c.back_within_s);
  EXPECT_LT(h.iae_m_s, c.iae_m_s);
}

TEST(HybridVessel, AdaptersShowTheSameFigures) {
  const HybridVesselReport& r = ice_report();
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["case"], "vessel");
  EXPECT_EQ(j["scenario"], "ice");
  EXPECT_EQ(j["scenario_file"], "dp-ice-load");
  EXPECT_EQ(j["load_time_s"], 300.0);
  EXPECT_EQ(j["within_m"], 1.0);
  EXPECT_EQ(j["hybrid"]["jumps"], r.comparison.hybrid.jumps);
  EXPECT_EQ(j["hybrid_parameters"]["dwell_s"], r.jump_params.dwell_s);
  EXPECT_FALSE(j.contains("plots"));
  EXPECT_EQ(to_json(r, {"x.svg"})["plots"], nlohmann::json::array({"x.svg"}));

  EXPECT_THAT(to_text(r), StartsWith("dp-ice-load (seed 1), load change at 300 s:\n"));
  EXPECT_THAT(to_text(r), HasSubstr("time back within 1 m [s]"));
  EXPECT_THAT(to_markdown(r),
              StartsWith("| after the load | conventional | hybrid |\n|---|---:|---:|\n"));
  EXPECT_THAT(to_html(r), StartsWith("<table>\n<tr><th>after the load</th>"));

  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("dynpos_hybrid_vessel_test-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const auto written = write_figures(r, dir);
  ASSERT_EQ(written.size(), 3u);
  EXPECT_EQ(written[0].filename(), "hybrid_vessel_ice_position.svg");
  EXPECT_EQ(written[2].filename(), "hybrid_vessel_ice_power.svg");
  for (const auto& p : written) EXPECT_GT(std::filesystem::file_size(p), 1000u) << p;
  std::filesystem::remove_all(dir);

  // write_outputs: the plots, then the JSON listing them (the --json document).
  const Written all = write_outputs(r, {(dir / "r.json").string(), dir});
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all.back(), dir / "r.json");
  std::ifstream in(dir / "r.json");
  EXPECT_EQ(nlohmann::json::parse(in), to_json(r, Written(all.begin(), all.end() - 1)));
  EXPECT_TRUE(write_outputs(r, Outputs{}).empty());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dynpos::analysis
