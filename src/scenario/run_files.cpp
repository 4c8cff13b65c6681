#include "dynpos/scenario/run_files.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/csv_writer.hpp"
#include "dynpos/io/temporary_files.hpp"

namespace dynpos::scenario {
namespace {

std::vector<io::CsvColumn> csv_columns(const core::Log& log) {
  std::vector<io::CsvColumn> columns;
  for (const core::Channel& c : log.channels()) columns.push_back({c.name, c.unit});
  return columns;
}

void write_rows(const core::Log& block, io::CsvRowWriter& writer, std::vector<double>& row) {
  row.resize(block.channels().size());
  for (std::size_t i = 0; i < block.size(); ++i) {
    for (std::size_t c = 0; c < row.size(); ++c) row[c] = block.channels()[c].values[i];
    writer.write_row(block.time()[i], row);
  }
}

// DIR/<antenna>.nmea: the antenna's sentences, one a line, CR LF (GnssSentenceStream).
struct NmeaFile {
  GnssSentenceStream sentences;
  io::AtomicFile file;
  std::vector<TimedSentence> batch;

  NmeaFile(const core::Log& layout, const std::string& antenna, const RunFileContext& context,
           const std::filesystem::path& path)
      : sentences(layout, antenna, context), file(path) {}
  void write() {
    for (const TimedSentence& s : batch) file.stream() << s.text << "\r\n";
    batch.clear();
  }
};

}  // namespace

struct RunFileWriter::Files {
  io::CsvRowWriter log;
  io::CsvRowWriter truth;
  std::vector<std::unique_ptr<NmeaFile>> nmea;
  std::unique_ptr<DeviceFileWriter> devices;
  std::vector<double> row;
};

RunFileWriter::RunFileWriter(std::filesystem::path dir, RunFileContext context)
    : dir_(std::move(dir)), context_(std::move(context)) {}

RunFileWriter::~RunFileWriter() = default;

void RunFileWriter::add(const core::Log& log, const core::Log& truth_log) {
  if (!files_) {
    {
      const io::temporary_files::Hold hold;  // not after a signal's removal of the stage
      std::filesystem::create_directories(dir_);
    }
    // Files holds files that cannot move: made in place.
    files_.reset(new Files{io::CsvRowWriter(dir_ / "log.csv", csv_columns(log)),
                           io::CsvRowWriter(dir_ / "truth.csv", csv_columns(truth_log)),
                           {},
                           {},
                           {}});
    for (const std::string& antenna : gnss_antennas(log)) {
      files_->nmea.push_back(
          std::make_unique<NmeaFile>(log, antenna, context_, dir_ / (antenna + ".nmea")));
    }
    if (context_.device_files) {
      files_->devices = std::make_unique<DeviceFileWriter>(log, context_, dir_ / "devices");
    }
  }
  write_rows(log, files_->log, files_->row);
  write_rows(truth_log, files_->truth, files_->row);
  for (const auto& nmea : files_->nmea) {
    nmea->sentences.add(log, nmea->batch);
    nmea->write();
  }
  if (files_->devices) files_->devices->add(log);
}

void RunFileWriter::commit(const TrialTruth& truth) {
  if (!files_) throw std::logic_error("RunFileWriter::commit before any rows");
  files_->log.commit();
  files_->truth.commit();
  write_trial_truth(truth, dir_ / "truth.json");
  for (const auto& nmea : files_->nmea) {
    nmea->sentences.finish(nmea->batch);
    nmea->write();
    nmea->file.commit();
  }
  if (files_->devices) files_->devices->commit();
}

RunFileContext run_file_context(const ScenarioRun& run) {
  return {run.start_utc, run.geoid_separation_m, run.truth.seed, run.device_files};
}

namespace {

std::function<void()>& before_rename() {
  static std::function<void()> hook;
  return hook;
}

}  // namespace

void testing::set_before_rename(std::function<void()> hook) { before_rename() = std::move(hook); }

namespace {

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
    if (before_rename()) before_rename()();
    std::filesystem::create_directories(target.parent_path());
    std::filesystem::rename(file, target);
  }
}

// Writes the blocks of a run on a thread of its own, so that one core simulates while another
// writes: the run fills its next block while this thread writes the last one, which it holds
// in a copy (the copy's memory reused from block to block). Blocks are written in order; an
// error of the writing is thrown to the run at its next block, or by finish(). When the system
// cannot start the thread (a memory or process limit), the run writes each block itself: the
// same files, one core.
class WritingThread {
 public:
  explicit WritingThread(RunBlockSink write)
      : write_(std::move(write)), thread_(core::try_start_thread([this] { loop(); })) {}
  ~WritingThread() { stop(); }
  WritingThread(const WritingThread&) = delete;
  WritingThread& operator=(const WritingThread&) = delete;

  // Waits until the last block is written, then hands this one over.
  void push(const core::Log& log, const core::Log& truth_log) {
    if (!thread_.joinable()) {
      write_(log, truth_log);
      return;
    }
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !full_ || error_; });
    if (error_) std::rethrow_exception(error_);
    log_ = log;
    truth_log_ = truth_log;
    full_ = true;
    changed_.notify_all();
  }
  // Waits until every block is written; throws the writing's error, if any.
  void finish() {
    stop();
    if (error_) std::rethrow_exception(error_);
  }

 private:
  void loop() {
    std::unique_lock lock(mutex_);
    for (;;) {
      changed_.wait(lock, [&] { return full_ || done_; });
      if (!full_) return;  // done, and nothing left
      lock.unlock();
      try {
        write_(log_, truth_log_);
      } catch (...) {
        lock.lock();
        error_ = std::current_exception();
        changed_.notify_all();
        return;
      }
      lock.lock();
      full_ = false;
      changed_.notify_all();
    }
  }
  void stop() {
    {
      const std::lock_guard lock(mutex_);
      done_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

  RunBlockSink write_;
  core::Log log_, truth_log_;  // the block being written
  std::mutex mutex_;
  std::condition_variable changed_;
  bool full_ = false, done_ = false;
  std::exception_ptr error_;
  std::jthread thread_;  // last: starts once the rest is made
};

// Removes the stage and takes it off the list, as one step.
void remove_stage(const std::filesystem::path& stage) {
  const io::temporary_files::Hold hold;
  std::error_code ignored;
  std::filesystem::remove_all(stage, ignored);
  io::temporary_files::drop(stage);
}

// Calls write(stage) with a hidden folder in `dir`, then renames what it wrote into `dir`
// (finding M4 of the reliability review: a failed run left a new log.csv beside the
// truth.json of another seed). A failure, or a signal while it writes, removes the folder. The
// renames are one step that a signal waits for (io::temporary_files::Hold): a run's files are
// placed together or not at all.
template <typename Write>
void write_staged(const std::filesystem::path& dir, const Write& write) {
  const std::filesystem::path stage =
      dir / fmt::format(".run.tmp-{}-{:08x}", ::getpid(), std::random_device{}());
  {
    const io::temporary_files::Hold hold;  // made and listed as one step
    std::filesystem::create_directories(dir);
    std::error_code ignored;
    std::filesystem::remove_all(stage, ignored);
    std::filesystem::create_directory(stage);
    io::temporary_files::add(stage);
  }
  try {
    write(stage);
    const io::temporary_files::Hold hold;
    move_files_into(stage, dir);
  } catch (...) {
    remove_stage(stage);
    throw;
  }
  remove_stage(stage);
}

}  // namespace

void write_scenario_run(const ScenarioRun& run, const std::filesystem::path& dir) {
  write_staged(dir, [&](const std::filesystem::path& stage) {
    RunFileWriter writer(stage, run_file_context(run));
    writer.add(run.log, run.truth_log);
    writer.commit(run.truth);
  });
}

ScenarioRun run_scenario_into(const ScenarioSpec& spec, const VesselConfig& vessel,
                              std::uint64_t seed, const std::filesystem::path& dir,
                              const RunBlockSink& also) {
  ScenarioRun run;
  write_staged(dir, [&](const std::filesystem::path& stage) {
    RunFileWriter writer(stage,
                         {spec.start_utc, vessel.sensors.origin.height_m, seed, spec.device_files});
    WritingThread writing([&](const core::Log& log, const core::Log& truth) {
      writer.add(log, truth);
      if (also) also(log, truth);
    });
    run = stream_scenario(spec, vessel, seed, [&](const core::Log& log, const core::Log& truth) {
      writing.push(log, truth);
    });
    writing.finish();
    writer.commit(run.truth);
  });
  return run;
}

}  // namespace dynpos::scenario
