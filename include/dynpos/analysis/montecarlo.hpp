#pragma once
/// \file
/// Monte Carlo over noise seeds (`dynpos montecarlo`): how much a sea-trial result can be
/// trusted. One scenario of the virtual trial is run for every seed of a range, its logger files
/// are written and analysed as a user's would be, and the spread of every identified quantity is
/// summarised against the simulator's truth:
/// - step tests (truth.json propeller_steps, rudder_steps): K, T and δ of each step by Smith's
///   method (3.8)–(3.9), the method that defines the truth's T and δ, for each thruster's shaft
///   speed and thrust and for the yaw rate after rudder steps (truth: Nomoto's T);
/// - DP runs (truth.json setpoints, no step test): the stationkeeping standard deviations of the
/// last 300 s
///   (north, east, heading), no truth;
/// - the other runs: the GNSS lever arms by the least squares of the thesis (truth: the arms).
/// Seeds are split into shards (`--shard i/N`) for running on many machines; merge() joins the
/// shards' documents into the document one run of the whole range gives, byte for byte.
///
/// Request keys (option_error): "seeds", "shard", "jobs", "duration", "vessel", "measure".

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/outputs.hpp"
#include "dynpos/core/parallel_for.hpp"

namespace dynpos::analysis {

/// A range of seeds, both ends included.
struct SeedRange {
  std::uint64_t first = 1;
  std::uint64_t last = 20;
};

/// "A..B", or one seed "A", decimal 0 … 2⁶⁴−1; option_error("seeds") for other text.
SeedRange parse_seed_range(const std::string& text);

/// Part `index` of `count` contiguous parts of a seed range.
struct Shard {
  std::size_t index = 1;  ///< 1 … count
  std::size_t count = 1;
};

/// "i/N"; option_error("shard") for other text (the range 1 ≤ i ≤ N is validate()'s).
Shard parse_shard(const std::string& text);

/// What each seed's run is analysed for.
enum class MonteCarloMeasure {
  /// Steps for a step test (four or more commanded steps in truth.json), station keeping for
  /// a DP run (setpoints), else lever arms.
  kAuto,
  kSteps,           ///< "steps": K, T and δ of each step (Smith)
  kStationKeeping,  ///< "station-keeping": the stationkeeping standard deviations
  kLeverArms,       ///< "lever-arms": the GNSS lever arms (least squares)
};

/// "auto", "steps", "station-keeping" or "lever-arms".
std::string to_string(MonteCarloMeasure measure);

/// The measurement named `name`; option_error("measure") for another name.
MonteCarloMeasure montecarlo_measure_from_string(const std::string& name);

struct MonteCarloRequest {
  std::string scenario;               ///< a built-in name or a .toml file
  SeedRange seeds;                    ///< the seeds of the whole run
  Shard shard;                        ///< the part of `seeds` this run takes
  unsigned jobs = core::kEveryCore;   ///< seeds run at once, 0 = every core
  std::filesystem::path vessel_file;  ///< empty: the data folder's gunnerus.toml
  std::optional<double> duration_s;   ///< run length override [s]
  std::filesystem::path work_dir;     ///< where each seed's files go for the run; empty: temp
  MonteCarloMeasure measure = MonteCarloMeasure::kAuto;

  /// option_error for an empty range, more than 100 000 seeds, a shard outside 1 … N, a
  /// duration not > 0.
  void validate() const;
  /// The seeds of this shard: [first, last], or none (first > last) when N exceeds the seeds.
  std::pair<std::uint64_t, std::uint64_t> shard_seeds() const;
};

/// What one seed gave: each quantity's value and, where the simulator knows it, its truth.
struct MonteCarloSample {
  std::uint64_t seed = 0;
  std::map<std::string, double> values;
  std::map<std::string, double> truth;
  std::vector<std::string> notes;  ///< analyses that gave nothing for this seed, and why
};

/// The spread of one quantity over the seeds that gave it.
struct MonteCarloStats {
  std::size_t n = 0;
  double mean = 0.0, std = 0.0, min = 0.0, max = 0.0;  ///< std: sample (n − 1); 0 for n = 1
  std::optional<double> truth;                         ///< mean truth over those seeds
  std::optional<double> bias;                          ///< mean − truth
  std::optional<double> rms_error;                     ///< √mean((value − truth)²)
};

/// What defines a run besides its seeds, the same in every shard of it: merge() refuses shards
/// that differ in any item (a shard of an edited scenario is not a part of the run).
struct MonteCarloRunId {
  std::string scenario_fnv1a64;  ///< FNV-1a 64 of the scenario file's bytes, 16 hex digits
  std::string vessel_fnv1a64;    ///< FNV-1a 64 of the vessel file's bytes, 16 hex digits
  double duration_s = 0.0;       ///< the run length, after --duration [s]
  std::string measure;           ///< as requested: auto, steps, station-keeping, lever-arms
  std::string dynpos_version;    ///< of the program that ran the seeds
  bool operator==(const MonteCarloRunId&) const = default;
};

struct MonteCarloReport {
  std::string scenario;
  MonteCarloRunId run;
  std::uint64_t seed_first = 1, seed_last = 1;
  std::size_t shard_index = 1, shard_count = 1;
  std::vector<MonteCarloSample> samples;  ///< in seed order
  std::map<std::string, MonteCarloStats> summary;
};

/// Validates, runs the shard's seeds on `jobs` threads and summarises. The report does not
/// depend on `jobs`. Throws core::InputError for a scenario or vessel that cannot be read.
MonteCarloReport run_montecarlo(const MonteCarloRequest& request);

/// The summary of samples in seed order (how run_montecarlo and merge make it).
std::map<std::string, MonteCarloStats> summarise(const std::vector<MonteCarloSample>& samples);

/// Joins shard documents (to_json of each shard) of one scenario and seed range into the
/// report of the whole range: the same document one unsharded run gives. core::InputError
/// naming the file for a document that is not a Monte Carlo result, a shard that is not i/N
/// with 1 ≤ i ≤ N or not of the others' N, a different scenario or range, a different run
/// (MonteCarloRunId: the item and both files named), a seed given twice, or a seed of the
/// range missing.
MonteCarloReport merge_montecarlo(const std::vector<std::filesystem::path>& shard_files);

nlohmann::json to_json(const MonteCarloReport& report);
/// The table of the summary: quantity, n, mean, std, min, max, truth, bias, rms error.
std::string to_text(const MonteCarloReport& report);

/// The JSON (outputs.json: the samples and the summary); Monte Carlo draws no figure.
Written write_outputs(const MonteCarloReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
