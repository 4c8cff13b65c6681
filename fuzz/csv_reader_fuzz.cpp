// libFuzzer target: the CSV reader with a column map. An input is a TOML column map, a line
// "%%", then the CSV log (fuzz_input.hpp); without the marker the whole input is a log, read
// with every numeric column (read_csv_all) and by its header. With a map the log is read
// whole, within a window, and by block parsing on one and on two threads, which must give what
// the row reader gives when it reads the same bytes through a pipe (csv_blocks.hpp): the same
// channels, values and errors.

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <thread>

#include "dynpos/core/error.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "fuzz_input.hpp"

namespace {

using dynpos::core::InputError;
namespace io = dynpos::io;

// The log read with `options`, or the message of the InputError it gave.
struct Outcome {
  std::optional<dynpos::core::Log> log;
  std::string error;
};

// The error's text names the file as LOG, so that a file and a pipe of the same bytes compare.
Outcome read(const std::filesystem::path& path, const io::ColumnMap& map,
             const io::CsvReadOptions& options) {
  try {
    return {io::read_csv_log(path, map, options).log, {}};
  } catch (const InputError& e) {
    std::string error = e.what();
    for (std::size_t at; (at = error.find(path.string())) != std::string::npos;) {
      error.replace(at, path.string().size(), "LOG");
    }
    return {std::nullopt, error};
  }
}

// The same bytes through a FIFO, which the reader reads row by row. The writer waits for the
// reader's open without blocking, and gives up once the read is over (a read that failed before
// it opened the FIFO); a reader that stops early breaks the pipe, and the writer's write fails
// (SIGPIPE is ignored).
Outcome read_through_pipe(const std::filesystem::path& file, std::string_view bytes,
                          const io::ColumnMap& map, const io::CsvReadOptions& options) {
  const std::filesystem::path fifo = file.string() + ".fifo";
  std::error_code ec;
  std::filesystem::remove(fifo, ec);
  if (::mkfifo(fifo.c_str(), 0600) != 0) __builtin_trap();
  std::signal(SIGPIPE, SIG_IGN);
  std::atomic<bool> read_over{false};
  sigset_t alarm, before;
  sigemptyset(&alarm);
  sigaddset(&alarm, SIGALRM);
  pthread_sigmask(SIG_BLOCK, &alarm, &before);  // inherited by the two threads below
  std::thread writer([&] {
    int fd = -1;
    while ((fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK)) < 0) {
      if (errno != ENXIO || read_over.load()) return;
      std::this_thread::yield();
    }
    ::fcntl(fd, F_SETFL, 0);  // blocking writes from here on
    for (std::size_t at = 0; at < bytes.size();) {
      const ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      at += static_cast<std::size_t>(n);
    }
    ::close(fd);
  });
  // The pipe is read on a thread of its own with SIGALRM blocked: libFuzzer's timer would
  // otherwise interrupt a read that waits for the writer (EINTR), which a regular file never sees.
  Outcome out;
  std::thread reader([&] {
    out = read(fifo, map, options);
    read_over.store(true);
  });
  pthread_sigmask(SIG_SETMASK, &before, nullptr);
  reader.join();
  writer.join();
  std::filesystem::remove(fifo, ec);
  return out;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Two reads of one log: the reader promises the same result for any number of threads, and for
// a pipe.
void check_same(const Outcome& one, const Outcome& two) {
  if (one.error != two.error || one.log.has_value() != two.log.has_value()) __builtin_trap();
  if (!one.log) return;
  const auto& a = *one.log;
  const auto& b = *two.log;
  if (a.size() != b.size() || a.channel_names() != b.channel_names()) __builtin_trap();
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same_bits(a.time()[i], b.time()[i])) __builtin_trap();
  }
  for (const auto& name : a.channel_names()) {
    const auto& x = a.channel(name).values;
    const auto& y = b.channel(name).values;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (!same_bits(x[i], y[i])) __builtin_trap();
    }
  }
}

void read_with_map(const std::filesystem::path& path, std::string_view bytes,
                   std::string_view map_text) {
  io::ColumnMap map;
  try {
    map = io::parse_column_map(map_text, "map.toml");
  } catch (const InputError&) {
    return;
  }
  io::CsvReadOptions options;
  options.jobs = 1;
  const Outcome one = read(path, map, options);
  // Past the rows that fix the time format a regular file is parsed in blocks: those against the
  // row reader.
  if (static_cast<std::size_t>(std::count(bytes.begin(), bytes.end(), '\n')) >
      io::kTimeDetectionRows) {
    check_same(read_through_pipe(path, bytes, map, options), one);
  }
  options.jobs = 2;
  check_same(one, read(path, map, options));
  options.t_from_s = 0.5;
  options.t_to_s = 2.0;
  (void)read(path, map, options);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file("log.csv");
  const auto parts = dynpos::fuzz::split_at_marker(dynpos::fuzz::as_text(data, size));
  const auto& path = file.write(parts.second);
  if (!parts.first.empty()) {
    read_with_map(path, parts.second, parts.first);
    return 0;
  }
  try {
    (void)io::read_csv_header(path);
  } catch (const InputError&) {
  }
  try {
    io::CsvReadOptions options;
    options.jobs = 1;
    (void)io::read_csv_all(path, options);
  } catch (const InputError&) {
  }
  return 0;
}
