#include "dynpos/analysis/montecarlo.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/leverarm_gnss.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/analysis/simulate.hpp"
#include "dynpos/analysis/station_keeping.hpp"
#include "dynpos/analysis/step.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/io/temporary_files.hpp"
#include "dynpos/report/table.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::analysis {
namespace {

constexpr std::uint64_t kMaxSeeds = 100'000;
constexpr double kStepMatch_s = 1.0;  // a fitted step is the truth's within this [s]

std::uint64_t parse_seed(const std::string& text, const std::string& whole) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
    throw option_error("seeds", fmt::format("'{}' is not a seed range", whole),
                       "give A..B with decimal seeds 0 … 2^64−1, e.g. --seeds 1..200");
  }
  return value;
}

// Runs the CLI's step analysis (Smith) on a response and records each step the truth knows.
void measure_steps(const std::filesystem::path& log, const std::string& input,
                   const std::string& output, const std::vector<std::pair<double, double>>& truth_T,
                   const std::vector<double>& truth_delay, MonteCarloSample& out) {
  StepRequest q;
  q.source.log = log;
  q.source.columns = {"input=" + input, "output=" + output};
  q.source.jobs = 1;
  q.method = StepMethod::kSmith;
  StepReport report;
  try {
    report = run_step(q);
  } catch (const core::InputError& e) {
    out.notes.push_back(fmt::format("{} from {}: {}", output, input, e.problem()));
    return;
  }
  for (const StepFit& fit : report.steps) {
    if (fit.status == core::Status::kFailed) continue;
    for (std::size_t k = 0; k < truth_T.size(); ++k) {
      const double t_truth = truth_T[k].first;
      if (std::abs(fit.step.t_step - t_truth) > kStepMatch_s) continue;
      const std::string key = fmt::format("{}@{:g}s", output, t_truth);
      if (fit.gain) out.values[key + ".K"] = *fit.gain;
      if (fit.time_constant_s) {
        out.values[key + ".T_s"] = *fit.time_constant_s;
        if (std::isfinite(truth_T[k].second)) out.truth[key + ".T_s"] = truth_T[k].second;
      }
      if (fit.dead_time_s) {
        out.values[key + ".delay_s"] = *fit.dead_time_s;
        if (std::isfinite(truth_delay[k])) out.truth[key + ".delay_s"] = truth_delay[k];
      }
    }
  }
}

void measure_propeller_steps(const std::filesystem::path& log, const scenario::TrialTruth& truth,
                             MonteCarloSample& out) {
  for (const std::string thruster : {"port", "stb"}) {
    for (const std::string quantity : {"rpm", "thrust"}) {
      std::vector<std::pair<double, double>> T;
      std::vector<double> delay;
      for (const scenario::PropellerStepTruth& s : truth.propeller_steps) {
        if (s.thruster != thruster) continue;
        const model::FopdtTruth& f = quantity == "rpm" ? s.shaft_speed : s.thrust;
        T.emplace_back(s.t_s, f.time_constant);
        delay.push_back(f.dead_time);
      }
      if (!T.empty()) {
        measure_steps(log, "command.rpm." + thruster, quantity + "." + thruster, T, delay, out);
      }
    }
  }
}

void measure_rudder_steps(const std::filesystem::path& log, const scenario::TrialTruth& truth,
                          MonteCarloSample& out) {
  std::vector<std::pair<double, double>> T;
  std::vector<double> delay;
  for (const scenario::RudderStepTruth& s : truth.rudder_steps) {
    T.emplace_back(s.t_s, s.nomoto ? s.nomoto->Tr_s : std::nan(""));
    delay.push_back(std::nan(""));  // the yaw rate's dead time has no single truth
  }
  if (!T.empty()) measure_steps(log, "command.rudder.stb", "mru1.r", T, delay, out);
}

void measure_station_keeping(const std::filesystem::path& log, MonteCarloSample& out) {
  StationKeepingRequest q;
  q.source.log = log;
  q.source.jobs = 1;
  q.source.columns = {"north=gnss1.north", "east=gnss1.east"};  // the first antenna's fixes
  try {
    const StationKeepingReport report = run_station_keeping(q);
    const ident::StationKeepingResult& w = report.windows.front();
    if (w.position_std_north_m) out.values["position_std_north_m"] = *w.position_std_north_m;
    if (w.position_std_east_m) out.values["position_std_east_m"] = *w.position_std_east_m;
    if (w.heading_rad.std)
      out.values["heading_std_deg"] = *w.heading_rad.std * 180.0 / std::numbers::pi;
  } catch (const core::InputError& e) {
    out.notes.push_back("station keeping: " + e.problem());
  }
}

void measure_lever_arms(const std::filesystem::path& log, const scenario::TrialTruth& truth,
                        MonteCarloSample& out) {
  LeverarmGnssRequest q;
  q.source.log = log;
  q.source.jobs = 1;
  q.method = LeverarmGnssMethod::kLsq;
  q.source.columns = {"roll=mru1.roll", "pitch=mru1.pitch", "p=mru1.p", "q=mru1.q", "r=mru1.r"};
  try {
    const LeverarmGnssReport report = run_leverarm_gnss(q);
    for (const calib::ArmEstimate& arm : report.result.arms) {
      const auto known = truth.lever_arms.find(arm.name);
      for (int axis = 0; axis < 3; ++axis) {
        const std::string key = fmt::format("{}.{}_m", arm.name, "xyz"[axis]);
        if (!std::isfinite(arm.l_b_m(axis))) continue;
        out.values[key] = arm.l_b_m(axis);
        if (known != truth.lever_arms.end()) out.truth[key] = known->second(axis);
      }
    }
  } catch (const core::InputError& e) {
    out.notes.push_back("GNSS lever arms: " + e.problem());
  }
}

// What "auto" measures in a run: a step test has at least kMinStepTest commanded steps (a
// manoeuvre such as the turning circle has a few), a DP run has setpoints.
constexpr std::size_t kMinStepTest = 4;

MonteCarloMeasure auto_measure(const scenario::TrialTruth& truth) {
  if (truth.propeller_steps.size() + truth.rudder_steps.size() >= kMinStepTest) {
    return MonteCarloMeasure::kSteps;
  }
  if (!truth.setpoints.empty()) return MonteCarloMeasure::kStationKeeping;
  return MonteCarloMeasure::kLeverArms;
}

// One seed: the run's files in their own folder, analysed as a user's logs, then removed.
MonteCarloSample run_seed(const scenario::ScenarioSpec& spec, const scenario::VesselConfig& vessel,
                          std::uint64_t seed, const std::filesystem::path& work_dir,
                          MonteCarloMeasure measure) {
  const std::filesystem::path dir = work_dir / fmt::format("seed-{}", seed);
  const scenario::ScenarioRun run = scenario::run_scenario_into(spec, vessel, seed, dir);
  MonteCarloSample out;
  out.seed = seed;
  const std::filesystem::path log = dir / "log.csv";
  const scenario::TrialTruth& truth = run.truth;
  // "auto" from the truth's commands, which do not depend on the seed.
  const MonteCarloMeasure what =
      measure == MonteCarloMeasure::kAuto ? auto_measure(truth) : measure;
  if (what == MonteCarloMeasure::kSteps) {
    measure_propeller_steps(log, truth, out);
    measure_rudder_steps(log, truth, out);
  } else if (what == MonteCarloMeasure::kStationKeeping) {
    measure_station_keeping(log, out);
  } else {
    measure_lever_arms(log, truth, out);
  }
  const io::temporary_files::Hold hold;  // not beside a signal's removal of the work folder
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
  return out;
}

// A fresh folder for the seeds' files, removed with them on every exit, a signal's too: it is
// listed with the temporary files (io/temporary_files.hpp), not only the run being written.
struct WorkDir {
  std::filesystem::path path;
  explicit WorkDir(const std::filesystem::path& parent) {
    const std::filesystem::path base =
        parent.empty() ? std::filesystem::temp_directory_path() : parent;
    std::random_device entropy;
    path = base / fmt::format("dynpos-montecarlo-{}-{:08x}", ::getpid(), entropy());
    const io::temporary_files::Hold hold;  // made and listed as one step
    std::filesystem::create_directories(path);
    io::temporary_files::add(path);
  }
  ~WorkDir() {
    const io::temporary_files::Hold hold;
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
    io::temporary_files::drop(path);
  }
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
};

// FNV-1a 64 of a file's bytes as 16 hex digits; core::InputError naming it if unreadable.
std::string fnv1a64_of_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::uint64_t hash = 0xCBF29CE484222325ULL;
  std::vector<char> buffer(std::size_t{1} << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      hash ^= static_cast<unsigned char>(buffer[static_cast<std::size_t>(i)]);
      hash *= 0x100000001B3ULL;
    }
  }
  if (in.bad() || !in.eof()) {
    throw core::InputError({file.string(), {}, {}, {}}, "cannot read the file",
                           "check the path and its permissions");
  }
  return fmt::format("{:016x}", hash);
}

}  // namespace

SeedRange parse_seed_range(const std::string& text) {
  const auto dots = text.find("..");
  SeedRange r;
  r.first = parse_seed(text.substr(0, dots), text);
  r.last = dots == std::string::npos ? r.first : parse_seed(text.substr(dots + 2), text);
  return r;
}

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  std::size_t i = 0, n = 0;
  const char* end = text.data() + text.size();
  const bool ok = slash != std::string::npos &&
                  std::from_chars(text.data(), text.data() + slash, i).ptr == text.data() + slash &&
                  std::from_chars(text.data() + slash + 1, end, n).ptr == end && slash > 0 &&
                  slash + 1 < text.size();
  if (!ok) {
    throw option_error("shard", fmt::format("'{}' is not a shard", text),
                       "give i/N with 1 ≤ i ≤ N, e.g. --shard 3/8");
  }
  return {i, n};
}

std::string to_string(MonteCarloMeasure measure) {
  switch (measure) {
    case MonteCarloMeasure::kSteps:
      return "steps";
    case MonteCarloMeasure::kStationKeeping:
      return "station-keeping";
    case MonteCarloMeasure::kLeverArms:
      return "lever-arms";
    case MonteCarloMeasure::kAuto:
      break;
  }
  return "auto";
}

MonteCarloMeasure montecarlo_measure_from_string(const std::string& name) {
  for (const MonteCarloMeasure m :
       {MonteCarloMeasure::kAuto, MonteCarloMeasure::kSteps, MonteCarloMeasure::kStationKeeping,
        MonteCarloMeasure::kLeverArms}) {
    if (name == to_string(m)) return m;
  }
  throw option_error("measure", fmt::format("'{}' is not a measurement", name),
                     "give auto, steps, station-keeping or lever-arms");
}

void MonteCarloRequest::validate() const {
  if (scenario.empty()) throw option_error("scenario", "no scenario given");
  if (!work_dir.empty()) check_output_dir("work_dir", work_dir);
  if (seeds.last < seeds.first) {
    throw option_error("seeds", fmt::format("the range {}..{} is empty", seeds.first, seeds.last),
                       "the first seed must not be after the last");
  }
  if (seeds.last - seeds.first >= kMaxSeeds) {
    throw option_error(
        "seeds", fmt::format("{}..{} is more than {} seeds", seeds.first, seeds.last, kMaxSeeds),
        "split it into ranges and merge the results");
  }
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
    throw option_error("shard", fmt::format("shard {}/{} does not exist", shard.index, shard.count),
                       "give i/N with 1 ≤ i ≤ N");
  }
  if (duration_s && !(*duration_s > 0.0 && *duration_s <= 86'400.0)) {
    throw option_error("duration", fmt::format("{} s is not a run length", *duration_s),
                       "give a duration in (0, 86400] s");
  }
}

std::pair<std::uint64_t, std::uint64_t> MonteCarloRequest::shard_seeds() const {
  const std::uint64_t count = seeds.last - seeds.first + 1;
  const std::uint64_t begin = count * (shard.index - 1) / shard.count;
  const std::uint64_t end = count * shard.index / shard.count;
  return {seeds.first + begin, seeds.first + end - 1};  // first > last when empty
}

std::map<std::string, MonteCarloStats> summarise(const std::vector<MonteCarloSample>& samples) {
  std::map<std::string, std::vector<std::pair<double, std::optional<double>>>> by_key;
  for (const MonteCarloSample& s : samples) {
    for (const auto& [key, value] : s.values) {
      const auto t = s.truth.find(key);
      by_key[key].emplace_back(
          value, t == s.truth.end() ? std::nullopt : std::optional<double>(t->second));
    }
  }
  std::map<std::string, MonteCarloStats> out;
  for (const auto& [key, values] : by_key) {
    MonteCarloStats st;
    st.n = values.size();
    double sum = 0.0, truth_sum = 0.0, sq_error = 0.0;
    std::size_t with_truth = 0;
    st.min = st.max = values.front().first;
    for (const auto& [v, t] : values) {
      sum += v;
      st.min = std::min(st.min, v);
      st.max = std::max(st.max, v);
      if (t) {
        truth_sum += *t;
        sq_error += (v - *t) * (v - *t);
        ++with_truth;
      }
    }
    st.mean = sum / static_cast<double>(st.n);
    double sq = 0.0;
    for (const auto& [v, t] : values) sq += (v - st.mean) * (v - st.mean);
    st.std = st.n > 1 ? std::sqrt(sq / static_cast<double>(st.n - 1)) : 0.0;
    if (with_truth == st.n) {
      st.truth = truth_sum / static_cast<double>(st.n);
      st.bias = st.mean - *st.truth;
      st.rms_error = std::sqrt(sq_error / static_cast<double>(st.n));
    }
    out[key] = st;
  }
  return out;
}

MonteCarloReport run_montecarlo(const MonteCarloRequest& request) {
  request.validate();
  const std::filesystem::path data = find_data_dir();
  const std::filesystem::path scenario_file =
      scenario::resolve_scenario(request.scenario, data / "scenarios");
  scenario::ScenarioSpec spec = scenario::load_scenario(scenario_file);
  if (request.duration_s) spec.set_duration(*request.duration_s);  // commands after it dropped
  spec.validate();
  const std::filesystem::path vessel_file = vessel_file_or_default(request.vessel_file);
  const scenario::VesselConfig vessel = scenario::load_vessel_config(vessel_file);
  scenario::check_simulated(vessel, spec);
  MonteCarloReport report;
  report.scenario = spec.name;
  report.run = {fnv1a64_of_file(scenario_file), fnv1a64_of_file(vessel_file), spec.duration_s,
                to_string(request.measure), DYNPOS_VERSION};
  report.seed_first = request.seeds.first;
  report.seed_last = request.seeds.last;
  report.shard_index = request.shard.index;
  report.shard_count = request.shard.count;
  const auto [first, last] = request.shard_seeds();
  const std::size_t n = last >= first ? static_cast<std::size_t>(last - first + 1) : 0;
  report.samples.resize(n);
  const WorkDir work(request.work_dir);
  // The seeds at once each hold a run and its files (removed after the seed's analysis).
  const std::size_t at_once = core::job_count(request.jobs, std::max<std::size_t>(n, 1));
  check_simulation_resources(std::vector<scenario::ScenarioSpec>(at_once, spec), at_once,
                             work.path);
  core::parallel_for(n, request.jobs, [&](std::size_t i) {
    report.samples[i] = run_seed(spec, vessel, first + i, work.path, request.measure);
  });
  report.summary = summarise(report.samples);
  return report;
}

}  // namespace dynpos::analysis
