#pragma once
/// \file
/// A run's files: log.csv (the trial logger), truth.csv (the true motion), truth.json, for each
/// GNSS antenna K of the log gnssK.nmea (NMEA 0183 GGA, RMC, VTG, HDT at its fixes, UTC =
/// start_utc + t; docs/log-format.md) and, when the scenario asks, the device files
/// (device_files.hpp).
///
/// The files are written block by block as a run goes, so that a long run does not hold its
/// rows (finding M1 of the reliability review: about 850 B a row). They appear together or not
/// at all: written into a hidden folder in the output folder, then renamed into place; a
/// failure or a signal (io/temporary_files.hpp) leaves the output folder as it was.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>

#include "dynpos/core/log.hpp"
#include "dynpos/scenario/device_files.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/trial_truth.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {

/// Writes the files of one run into `dir`, a block of rows at a time; nothing appears at
/// their paths before commit(). The files do not depend on how the rows are split.
class RunFileWriter {
 public:
  RunFileWriter(std::filesystem::path dir, RunFileContext context);
  ~RunFileWriter();
  RunFileWriter(const RunFileWriter&) = delete;
  RunFileWriter& operator=(const RunFileWriter&) = delete;

  /// Writes the next rows: the trial logger's and the truth's of the same times. The first
  /// call creates the files (their headers from the blocks' channels). Throws
  /// std::runtime_error if a file cannot be created or written.
  void add(const core::Log& log, const core::Log& truth_log);
  /// Writes truth.json, finishes every file and renames it into place.
  void commit(const TrialTruth& truth);

 private:
  struct Files;
  std::filesystem::path dir_;
  RunFileContext context_;
  std::unique_ptr<Files> files_;
};

/// What the files of `run` need besides its rows.
RunFileContext run_file_context(const ScenarioRun& run);

/// Writes the files of a run held in memory into `dir` (created if needed).
void write_scenario_run(const ScenarioRun& run, const std::filesystem::path& dir);

/// Runs `spec` (stream_scenario) and writes its files into `dir` (created if needed) as it
/// goes, on a thread of its own (one core simulates, another writes); `also` (if set) sees
/// every block too, on that thread, in order. Returns the run with its truth and no rows.
/// The files are write_scenario_run()'s of run_scenario(), bit for bit.
ScenarioRun run_scenario_into(const ScenarioSpec& spec, const VesselConfig& vessel,
                              std::uint64_t seed, const std::filesystem::path& dir,
                              const RunBlockSink& also = {});

namespace testing {
/// Calls `hook` before each rename of a run's files into place (empty: none); for tests of a
/// signal between two renames.
void set_before_rename(std::function<void()> hook);
}  // namespace testing

}  // namespace dynpos::scenario
