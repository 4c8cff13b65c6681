#include "dynpos/analysis/demo.hpp"

#include "dynpos/analysis/campaign_report.hpp"
#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/analysis/simulate.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {

void DemoRequest::validate() const {
  if (out_dir.empty()) throw option_error("out", "no report folder given", "add --out DIR");
  check_output_dir("out", out_dir);
}

DemoReport run_demo(const DemoRequest& request) {
  request.validate();
  const std::filesystem::path data = request.data_dir ? *request.data_dir : find_data_dir();
  const std::vector<scenario::ScenarioSpec> specs = scenario::load_campaign(data / "scenarios");
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(data / "vessels" / "gunnerus.toml");
  const std::filesystem::path& dir = request.out_dir;
  // The disk and memory of the campaign's runs, refused before anything is written (the
  // analyses' files are small beside the logs).
  check_simulation_resources(specs, core::job_count(0, specs.size()), dir);
  std::filesystem::create_directories(dir);
  // A report of another seed loses its summary first: a demo stopped half-way leaves no
  // index.html, summary.md or summary.json that names runs of two seeds; the new ones are
  // written once the campaign's runs are all in place.
  for (const char* summary : {"index.html", "summary.md", "summary.json"}) {
    std::filesystem::remove(dir / summary);
  }
  DemoReport report{
      dir, request.seed, scenario::run_campaign(specs, vessel, request.seed, dir), {}};
  // The campaign's report first, so that the logs have one even if an analysis fails.
  write_campaign_report(report.runs, vessel, request.seed, dir, {});
  std::vector<ReportSection> sections;
  for (auto* section : {&step_demo_section, &agility_demo_section, &four_corner_demo_section,
                        &station_keeping_demo_section, &failure_test_demo_section,
                        &leverarm_gnss_demo_section, &leverarm_mru_demo_section}) {
    sections.push_back((*section)(dir));
  }
  sections.push_back(hybrid_vessel_demo_section(dir, request.seed));
  sections.push_back(capability_demo_section(dir, request.seed));
  for (const ReportSection& s : sections) {
    if (!s.title.empty()) report.section_titles.push_back(s.title);
  }
  write_campaign_report(report.runs, vessel, request.seed, dir, sections);
  return report;
}

std::string to_text(const DemoReport& report) { return campaign_text(report.runs, report.out_dir); }

}  // namespace dynpos::analysis
