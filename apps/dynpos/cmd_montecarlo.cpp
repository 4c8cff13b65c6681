// dynpos montecarlo SCENARIO --seeds A..B [--jobs N] [--shard i/N] [--json FILE]: the spread of
// every identified quantity over noise seeds, against truth; and `dynpos montecarlo merge
// SHARD.json...` (analysis/montecarlo.hpp).

#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/montecarlo.hpp"

namespace dynpos::cli {
namespace {

// The request, with its text options as given (parsed when the command runs, defaults from the
// request), and the outputs of the run and of `merge`.
struct MonteCarloOptions {
  analysis::MonteCarloRequest request;
  std::string seeds = fmt::format("{}..{}", request.seeds.first, request.seeds.last);
  std::string shard = fmt::format("{}/{}", request.shard.index, request.shard.count);
  std::string measure = analysis::to_string(request.measure);
  analysis::Outputs outputs;
  std::vector<std::filesystem::path> shard_files;
  analysis::Outputs merged;
};

}  // namespace

void register_montecarlo(CLI::App& app) {
  auto opt = std::make_shared<MonteCarloOptions>();
  analysis::MonteCarloRequest& r = opt->request;
  CLI::App* sub = app.add_subcommand(
      "montecarlo",
      "Run a scenario for many noise seeds and summarise the spread of every identified "
      "quantity against truth");
  sub->add_option("scenario", r.scenario,
                  "Scenario name in data/scenarios (e.g. surge-steps-forward) or a .toml file");
  sub->add_option("--seeds", opt->seeds, "Seed range A..B (inclusive), decimal")
      ->capture_default_str();
  sub->add_option("--shard", opt->shard,
                  "Run shard i of N (1 <= i <= N) of the seed range: contiguous parts, for "
                  "running on several machines; join them with `montecarlo merge`")
      ->capture_default_str();
  sub->add_option("--jobs", r.jobs, "Seeds run at once (default 0: every core)")
      ->check(CLI::Range(0u, 256u));
  sub->add_option("--vessel", r.vessel_file, "Vessel file (default: data/vessels/gunnerus.toml)");
  sub->add_option("--duration", r.duration_s, "Override the run length [s]")
      ->type_name("FLOAT:POSITIVE");
  sub->add_option("--measure", opt->measure,
                  "What to identify: auto (steps for a step test, stationkeeping for a DP run, "
                  "else the GNSS lever arms), steps, station-keeping or lever-arms")
      ->capture_default_str();
  output_folder(
      sub->add_option("--work-dir", r.work_dir,
                      "Folder for each seed's files while it is analysed (default: the temporary "
                      "folder); removed afterwards"));
  add_json_option(*sub, opt->outputs.json,
                  "Write the samples and the summary as JSON to FILE, or '-'");
  sub->footer(
      "Quantities: step tests give K, T and delay per step (Smith's method, the one that defines "
      "the truth), DP runs the stationkeeping standard deviations, other runs the GNSS lever "
      "arms. The output is the same for any --jobs, and `montecarlo merge` of the shards gives "
      "the document of one run of the whole range. Example: dynpos montecarlo "
      "surge-steps-forward --seeds 1..100 --json mc.json");

  CLI::App* merge = sub->add_subcommand(
      "merge", "Join the JSON documents of the shards of one run into the whole run's");
  merge->add_option("files", opt->shard_files, "The shards' JSON documents")
      ->required()
      ->check(CLI::ExistingFile);
  add_json_option(*merge, opt->merged.json, "Write the merged document to FILE, or '-'");
  merge->callback(
      [opt] { write_and_print(analysis::merge_montecarlo(opt->shard_files), opt->merged); });

  sub->callback([opt, sub] {
    if (sub->got_subcommand("merge")) return;
    analysis::MonteCarloRequest& q = opt->request;
    q.seeds = analysis::parse_seed_range(opt->seeds);
    q.shard = analysis::parse_shard(opt->shard);
    q.measure = analysis::montecarlo_measure_from_string(opt->measure);
    write_and_print(analysis::run_montecarlo(q), opt->outputs);
  });
}

}  // namespace dynpos::cli
