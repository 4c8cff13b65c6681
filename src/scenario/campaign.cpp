#include "dynpos/scenario/campaign.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/csv_writer.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/io/markup.hpp"
#include "dynpos/io/temporary_files.hpp"
#include "dynpos/scenario/device_files.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/sim/random.hpp"

namespace dynpos::scenario {
namespace {

RunSummary summarise(const ScenarioSpec& spec, const ScenarioRun& run, std::uint64_t seed) {
  RunSummary s;
  s.name = spec.name;
  s.description = spec.description;
  s.duration_s = spec.duration_s;
  s.rows = run.log.size();
  s.seed = seed;
  const core::Log& truth = run.truth_log;  // the summary describes what truly happened
  const auto& t = truth.time();
  const auto& u = truth.values("u");
  const auto& v = truth.values("v");
  const auto& r = truth.values("r");
  const auto& n = truth.values("north");
  const auto& e = truth.values("east");
  const auto& pp = truth.values("power.port");
  const auto& ps = truth.values("power.stb");
  const auto& pt = truth.values("power.tunnel");
  double energy_J = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    s.max_speed_mps = std::max(s.max_speed_mps, std::hypot(u[i], v[i]));
    s.max_yaw_rate_dps = std::max(s.max_yaw_rate_dps, std::abs(r[i]) * 180.0 / M_PI);
    if (i > 0) {
      const double dt = t[i] - t[i - 1];
      s.distance_m += std::hypot(n[i] - n[i - 1], e[i] - e[i - 1]);
      // Trapezoidal ∫P dt over the log samples.
      energy_J += 0.5 * dt * (pp[i] + ps[i] + pt[i] + pp[i - 1] + ps[i - 1] + pt[i - 1]);
    }
  }
  s.energy_kJ = energy_J / 1e3;
  return s;
}

// Writes DIR/<antenna>.nmea: the antenna's sentences, one a line, CR LF (gnss_sentences()).
void write_gnss_nmea(const ScenarioRun& run, const std::string& antenna,
                     const std::filesystem::path& path) {
  io::AtomicFile file(path);
  for (const TimedSentence& s : gnss_sentences(run, antenna)) file.stream() << s.text << "\r\n";
  file.commit();
}

}  // namespace

std::uint64_t campaign_seed(std::uint64_t master_seed, const std::string& scenario_name) {
  return sim::stream_seed(master_seed, scenario_name);
}

namespace {

void write_run_files(const ScenarioRun& run, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  io::write_csv(dir / "log.csv", run.log);
  io::write_csv(dir / "truth.csv", run.truth_log);
  write_trial_truth(run.truth, dir / "truth.json");
  for (const std::string& antenna : gnss_antennas(run.log)) {
    write_gnss_nmea(run, antenna, dir / (antenna + ".nmea"));
  }
  if (run.device_files) write_device_files(run, *run.device_files, dir / "devices");
}

// Renames every file under `from` to the same place under `to`, folders made as needed. Every
// place is checked first (a folder where a file goes, a file where a folder goes: an error
// naming it), so that the renames, each atomic, do not stop half-way for that.
void move_files_into(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> moves;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(from)) {
    if (entry.is_regular_file()) {
      moves.emplace_back(entry.path(), to / std::filesystem::relative(entry.path(), from));
    }
  }
  const auto refuse = [](const std::filesystem::path& at, const char* what) {
    throw core::InputError({at.string(), {}, {}, {}},
                           fmt::format("the run's files cannot be placed: it is {}", what),
                           "remove or rename it, or give another --out folder; nothing was "
                           "written");
  };
  for (const auto& [file, target] : moves) {
    if (std::filesystem::is_directory(target)) refuse(target, "a folder, where a file goes");
    for (auto up = target.parent_path(); up != to && up.has_relative_path();
         up = up.parent_path()) {
      if (std::filesystem::exists(up) && !std::filesystem::is_directory(up)) {
        refuse(up, "a file, where a folder goes");
      }
    }
  }
  for (const auto& [file, target] : moves) {
    std::filesystem::create_directories(target.parent_path());
    std::filesystem::rename(file, target);
  }
}

}  // namespace

void write_scenario_run(const ScenarioRun& run, const std::filesystem::path& dir) {
  // The run's files appear together or not at all (finding M4: a failed run left a new log.csv
  // beside the truth.json of another seed): written into a hidden folder in `dir`, then renamed
  // into place. A failure, or a signal (io/temporary_files.hpp), removes the folder and leaves
  // `dir` as it was.
  std::filesystem::create_directories(dir);
  const std::filesystem::path stage =
      dir / fmt::format(".run.tmp-{}-{:08x}", ::getpid(), std::random_device{}());
  std::error_code ignored;
  std::filesystem::remove_all(stage, ignored);
  io::temporary_files::add(stage);
  try {
    write_run_files(run, stage);
    move_files_into(stage, dir);
  } catch (...) {
    std::filesystem::remove_all(stage, ignored);
    io::temporary_files::drop(stage);
    throw;
  }
  std::filesystem::remove_all(stage, ignored);
  io::temporary_files::drop(stage);
}

std::vector<ScenarioSpec> load_campaign(const std::filesystem::path& scenario_dir) {
  std::vector<ScenarioSpec> specs;
  for (const std::string& name : list_scenarios(scenario_dir)) {
    specs.push_back(load_scenario(scenario_dir / (name + ".toml")));
  }
  if (specs.empty()) {
    throw core::InputError({scenario_dir.string(), {}, {}, {}}, "no scenario files found");
  }
  return specs;
}

std::vector<RunSummary> run_campaign(const std::vector<ScenarioSpec>& scenarios,
                                     const VesselConfig& vessel, std::uint64_t master_seed,
                                     const std::filesystem::path& out_dir, unsigned jobs) {
  std::vector<RunSummary> summaries(scenarios.size());
  // The longest runs first, so that a short one finishes the campaign, not a long one.
  std::vector<std::size_t> order(scenarios.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return scenarios[a].duration_s > scenarios[b].duration_s;
  });
  core::parallel_for(order.size(), jobs, [&](std::size_t k) {
    const ScenarioSpec& spec = scenarios[order[k]];
    const std::uint64_t seed = campaign_seed(master_seed, spec.name);
    const auto start = std::chrono::steady_clock::now();
    const ScenarioRun run = run_scenario(spec, vessel, seed);
    write_scenario_run(run, out_dir / spec.name);
    RunSummary s = summarise(spec, run, seed);
    s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summaries[order[k]] = std::move(s);
  });
  return summaries;
}

}  // namespace dynpos::scenario
