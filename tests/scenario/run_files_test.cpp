// A run's files written block by block as it goes (run_files.hpp): the blocks join to the run
// held in memory, and the files do not depend on how the rows are split.
#include "dynpos/scenario/run_files.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <thread>

#include "../io/io_test_util.hpp"
#include "../source_dir.hpp"
#include "dynpos/io/temporary_files.hpp"
#include "dynpos/scenario/runner.hpp"

namespace dynpos::scenario {
namespace {

namespace fs = std::filesystem;
using io::testing::TempDir;

fs::path source(const std::string& relative) { return fs::path(DYNPOS_SOURCE_DIR) / relative; }

// 30 s of the surge step programme at 10 Hz (301 rows), with device files and three antennas.
ScenarioSpec short_trial() {
  ScenarioSpec spec = load_scenario(source("data/scenarios/surge-steps-forward.toml"));
  spec.set_duration(30.0);
  return spec;
}

VesselConfig gunnerus() { return load_vessel_config(source("data/vessels/gunnerus.toml")); }

// Every file under `dir` by its relative path, with its bytes.
std::map<std::string, std::string> files_under(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    out[fs::relative(entry.path(), dir).string()] = {std::istreambuf_iterator<char>(in), {}};
  }
  return out;
}

void append(core::Log& to, const core::Log& block) {
  if (to.channels().empty()) {
    for (const core::Channel& c : block.channels()) to.declare_channel(c.name, c.unit, c.interp);
  }
  std::vector<double> row(block.channels().size());
  for (std::size_t i = 0; i < block.size(); ++i) {
    for (std::size_t k = 0; k < row.size(); ++k) row[k] = block.channels()[k].values[i];
    to.append_row(block.time()[i], row);
  }
}

// Equal bit for bit, NaN (missing) included.
void expect_same(const core::Log& a, const core::Log& b) {
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.channel_names(), b.channel_names());
  EXPECT_EQ(0, std::memcmp(a.time().data(), b.time().data(), a.size() * sizeof(double)));
  for (std::size_t k = 0; k < a.channels().size(); ++k) {
    EXPECT_EQ(0, std::memcmp(a.channels()[k].values.data(), b.channels()[k].values.data(),
                             a.size() * sizeof(double)))
        << a.channels()[k].name;
  }
}

TEST(StreamScenario, BlocksJoinToTheRunHeldInMemory) {
  const ScenarioSpec spec = short_trial();
  const VesselConfig vessel = gunnerus();
  const ScenarioRun whole = run_scenario(spec, vessel, 5);
  core::Log log, truth;
  std::size_t blocks = 0;
  const ScenarioRun streamed = stream_scenario(
      spec, vessel, 5,
      [&](const core::Log& l, const core::Log& t) {
        EXPECT_LE(l.size(), 7u);
        EXPECT_EQ(l.time(), t.time());
        append(log, l);
        append(truth, t);
        ++blocks;
      },
      7);
  EXPECT_EQ(blocks, 43u);  // 301 rows in blocks of 7
  expect_same(log, whole.log);
  expect_same(truth, whole.truth_log);
  EXPECT_TRUE(streamed.log.empty());
  EXPECT_EQ(streamed.log.channel_names(), whole.log.channel_names());
  EXPECT_EQ(to_json(streamed.truth).dump(), to_json(whole.truth).dump());
  EXPECT_THROW(stream_scenario(spec, vessel, 5, {}), std::invalid_argument);
}

TEST(RunFileWriter, FilesDoNotDependOnHowTheRowsAreSplit) {
  const ScenarioRun run = run_scenario(short_trial(), gunnerus(), 5);
  ASSERT_TRUE(run.device_files.has_value());
  TempDir whole;
  write_scenario_run(run, whole.path());
  const auto expected = files_under(whole.path());
  ASSERT_EQ(expected.size(), 12u);  // log, truth, truth.json, 3 NMEA; 3 captures, 3 CSVs
  EXPECT_TRUE(expected.count("devices/gnss2.nmea") && expected.count("devices/orders.csv"));
  // Blocks of one row, of 10 (the GNSS fix rate: a fix opens each block), and of 13.
  for (const std::size_t rows : {1u, 10u, 13u}) {
    TempDir split;
    RunFileWriter writer(split.path(), run_file_context(run));
    for (std::size_t i = 0; i < run.log.size(); i += rows) {
      const std::size_t last = std::min(i + rows, run.log.size()) - 1;
      const double from = run.log.time()[i], to = run.log.time()[last];
      writer.add(run.log.window(from, to), run.truth_log.window(from, to));
    }
    writer.commit(run.truth);
    const auto got = files_under(split.path());
    ASSERT_EQ(got.size(), expected.size()) << rows;
    for (const auto& [name, bytes] : expected)
      EXPECT_EQ(got.at(name), bytes) << name << ", blocks of " << rows;
  }
}

TEST(RunScenarioInto, WritesTheFilesOfTheRunHeldInMemory) {
  const ScenarioSpec spec = short_trial();
  const VesselConfig vessel = gunnerus();
  TempDir held, streamed;
  write_scenario_run(run_scenario(spec, vessel, 5), held.path());
  std::size_t rows = 0;
  const ScenarioRun run =
      run_scenario_into(spec, vessel, 5, streamed.path(),
                        [&](const core::Log& l, const core::Log&) { rows += l.size(); });
  EXPECT_EQ(rows, 301u);
  EXPECT_EQ(run.truth.seed, 5u);
  EXPECT_EQ(files_under(streamed.path()), files_under(held.path()));
}

TEST(RunScenarioInto, AFailedRunLeavesTheFolderAsItWas) {
  TempDir out;
  std::ofstream(out.path() / "log.csv") << "an older run\n";
  EXPECT_THROW(run_scenario_into(short_trial(), gunnerus(), 5, out.path(),
                                 [](const core::Log&, const core::Log&) {
                                   throw std::runtime_error("disk full");
                                 }),
               std::runtime_error);
  const auto left = files_under(out.path());
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left.at("log.csv"), "an older run\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(out.path()), fs::directory_iterator()), 1);
}

// A signal's removal of the temporary files (what the command line's signal thread does, on
// a thread of its own) before each rename of a run over another: the folder holds the files of
// one run, all old or all new, and no hidden stage. Before the fix a removal between two
// renames left the new log.csv beside the old truth.json.
TEST(RunScenarioInto, ASignalWhileTheFilesArePlacedLeavesOneRun) {
  const ScenarioSpec spec = short_trial();
  const VesselConfig vessel = gunnerus();
  const ScenarioRun first = run_scenario(spec, vessel, 1), second = run_scenario(spec, vessel, 2);
  TempDir old_run, new_run;
  write_scenario_run(first, old_run.path());
  write_scenario_run(second, new_run.path());
  const auto old_files = files_under(old_run.path());
  const auto new_files = files_under(new_run.path());
  ASSERT_NE(old_files.at("log.csv"), new_files.at("log.csv"));
  for (std::size_t at = 0; at < new_files.size(); ++at) {
    TempDir out;
    write_scenario_run(first, out.path());
    std::size_t renames = 0;
    std::thread signal;
    testing::set_before_rename([&] {
      if (renames++ != at) return;
      signal = std::thread([] { io::temporary_files::remove_all(); });
      // Time for the removal to run now, if nothing holds it off (it takes well under 1 ms).
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    });
    try {
      write_scenario_run(second, out.path());
    } catch (const std::exception&) {  // the files removed under it: a failed run
    }
    testing::set_before_rename({});
    if (signal.joinable()) signal.join();
    const auto left = files_under(out.path());
    EXPECT_TRUE(left == old_files || left == new_files)
        << "removal before rename " << at << ": the files of two runs";
    for (const auto& entry : fs::directory_iterator(out.path())) {
      EXPECT_NE(entry.path().filename().string().rfind(".run.tmp-", 0), 0u)
          << "removal before rename " << at << " left " << entry.path();
    }
  }
}

}  // namespace
}  // namespace dynpos::scenario
