// read_log_files (analysis/log_source.hpp): a log spread over several files, aligned on the
// main log's clock.

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/core/log_align.hpp"
#include "dynpos/io/log_file.hpp"
#include "gps_week_rollover.hpp"
#include "log_files.hpp"

namespace dynpos::analysis {
namespace {

// Throws if `part` (on the main clock after `offset_s`) does not overlap `main`'s time range;
// notes a partial overlap in the part's report.
void check_overlap(const core::Log& main, io::FileLog& part, double offset_s) {
  const double main_from = main.time().front();
  const double main_to = main.time().back();
  const double from = part.log.time().front() + offset_s;
  const double to = part.log.time().back() + offset_s;
  if (to < main_from || from > main_to) {
    core::InputLocation where;
    where.file = part.report.path;
    throw core::InputError(
        where,
        fmt::format("its times span [{}, {}] s on the main log's clock (clock offset {} s), "
                    "outside the main log's [{}, {}] s",
                    from, to, offset_s, main_from, main_to),
        fmt::format("both files must count time from the same origin; set the offset with "
                    "--clock-offset {}=SECONDS or clock_offset in [files.\"{}\"] of the map",
                    part.report.path, part.report.path));
  }
  if (from > main_from || to < main_to) {
    part.report.notes.push_back(
        fmt::format("covers [{}, {}] s of the main log's [{}, {}] s; its roles are missing "
                    "outside",
                    std::max(from, main_from), std::min(to, main_to), main_from, main_to));
  }
}

// The offset [s] that puts `part`'s times on the main log's clock: the difference of their
// absolute origins when both files have absolute time stamps (`cycles` GPS week cycles added to
// the part's), plus the user's clock offset.
double clock_offset_s(std::optional<std::int64_t> main_origin_ns, io::FileLog& part,
                      double user_offset_s, int cycles) {
  if (main_origin_ns && part.origin_ns) {
    part.report.notes.push_back("aligned on the main log by its absolute time stamps");
    return detail::origin_offset_s(*main_origin_ns, *part.origin_ns, cycles) + user_offset_s;
  }
  if (main_origin_ns.has_value() != part.origin_ns.has_value()) {
    part.report.notes.push_back(fmt::format(
        "one of this file and the main log has absolute time stamps, the other relative "
        "seconds: aligned by the clock offset only{}",
        part.origin ? fmt::format(" (this file's t = 0 s is {})", *part.origin) : ""));
  }
  return user_offset_s;
}

// The GPS week cycles to add to `part`'s stamps (gps_week_rollover.hpp); 0 unless both files
// have absolute stamps.
int rollover_cycles(const core::Log& main, io::FileLog& part, std::optional<std::int64_t> main_ns,
                    double user_offset_s, bool strict) {
  if (!main_ns || !part.origin_ns) return 0;
  return detail::gps_week_rollover_cycles(main, *main_ns, part.log, *part.origin_ns, user_offset_s,
                                          strict, part.report);
}

// How a file other than the main log is read: detected by content, whole (a window is the
// main log's), strict and with threads as the main log.
io::LogFileRead other_file(const io::LogFileRead& how) {
  io::LogFileRead other;
  other.strict = how.strict;
  other.jobs = how.jobs;
  other.bag_time = how.bag_time;
  other.msg_path = how.msg_path;
  return other;
}

// Puts `part` (a file, or a topic of a bag) on out.log's time axis, `user_offset_s` added to
// its times, and adds its report and roles to out.input.
void add_part(LoadedLog& out, std::optional<std::int64_t> main_origin_ns, io::FileLog part,
              double user_offset_s, const core::ResampleOptions& options,
              const io::LogFileRead& how) {
  const int cycles = rollover_cycles(out.log, part, main_origin_ns, user_offset_s, how.strict);
  const double offset_s = clock_offset_s(main_origin_ns, part, user_offset_s, cycles);
  part.report.clock_offset_s = offset_s;
  check_overlap(out.log, part, offset_s);
  const std::size_t first_channel = out.log.channels().size();
  core::add_aligned(out.log, part.log, offset_s, options);
  for (std::size_t i = first_channel; i < out.log.channels().size(); ++i) {
    const core::Channel& c = out.log.channels()[i];
    if (std::all_of(c.values.begin(), c.values.end(), core::is_missing)) {
      part.report.notes.push_back(
          fmt::format("role '{}' has no sample on the main log's time axis (no valid value "
                      "inside it, or only gaps wider than the largest gap)",
                      c.name));
    }
  }
  // Rates on the file's own clock: a 1 Hz role stays 1 Hz on a 10 Hz main log.
  const std::string part_path = part.report.path;
  io::InputReport part_input =
      describe_input(part.log, part_path, std::move(part.report), how.jobs);
  out.input.files.push_back(std::move(part_input.files.front()));
  for (io::RoleOrigin& role : part_input.roles) out.input.roles.push_back(std::move(role));
}

}  // namespace

LoadedLog read_log_files(const std::filesystem::path& main_log, const io::ColumnMap& map,
                         const core::ResampleOptions& options, const io::LogFileRead& how) {
  map.validate();
  io::FileLog main = io::read_log_file(main_log, map.for_file(""), how);
  std::vector<io::FileLog> topics = std::move(main.more);
  LoadedLog out{std::move(main.log), {}, main.first_row_s, main.last_row_read_s};
  const std::string main_path = main.report.path;
  out.input = describe_input(out.log, main_path, std::move(main.report), how.jobs);
  out.input.origin = main.origin;
  out.input.origin_zone = main.origin_zone;
  // A bag's other topics: on the bag's clock, by their absolute time stamps.
  for (io::FileLog& topic : topics)
    add_part(out, main.origin_ns, std::move(topic), 0.0, options, how);
  add_log_files(out, main.origin_ns, map, options, how);
  return out;
}

void add_log_files(LoadedLog& out, std::optional<std::int64_t> main_origin_ns,
                   const io::ColumnMap& map, const core::ResampleOptions& options,
                   const io::LogFileRead& how) {
  for (const std::string& file : map.other_files()) {
    const io::LogFileOptions file_options = map.file_options(file);
    io::FileLog part = io::read_log_file(file, map.for_file(file), other_file(how));
    std::vector<io::FileLog> topics = std::move(part.more);
    add_part(out, main_origin_ns, std::move(part), file_options.clock_offset_s, options, how);
    for (io::FileLog& topic : topics) {
      add_part(out, main_origin_ns, std::move(topic), file_options.clock_offset_s, options, how);
    }
  }
}

}  // namespace dynpos::analysis
