#include "dynpos/analysis/log_source.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/time_spacing.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/db3_reader.hpp"
#include "dynpos/io/mcap_reader.hpp"
#include "dynpos/io/roles.hpp"
#include "log_source_nmea.hpp"

namespace dynpos::analysis {

io::ColumnMap LogSource::base_map() const {
  io::ColumnMap map = map_file.empty() ? io::ColumnMap{} : io::load_column_map(map_file);
  io::apply_overrides(map, columns, units);
  for (const std::string& offset : clock_offsets) io::apply_clock_offset_override(map, offset);
  io::apply_time_overrides(map, time_format, date, time_order);
  const io::RoleColumn* sec = map.find("time.sec");
  if (map.find("time") == nullptr && (sec == nullptr || !sec->file.empty())) {
    map.set_column("time", "time");
  }
  return map;
}

namespace {

// Runs `read`, naming `source.log` (what the user gave) wherever the reader named the copy it
// read from (source.read_from): in its errors.
template <class Read>
auto naming_the_log(const LogSource& source, Read&& read) -> decltype(read()) {
  if (source.read_from.empty()) return read();
  const auto renamed = [&](core::InputLocation where) {
    if (where.file == source.read_from.string()) where.file = source.log.string();
    return where;
  };
  try {
    return read();
  } catch (const io::EmptyWindowError& e) {
    throw io::EmptyWindowError(
        core::InputError(renamed(e.where()), e.problem(), e.hint()),
        {.first_row_s = e.first_row_s, .last_row_read_s = e.last_row_read_s});
  } catch (const core::InputError& e) {
    if (!e.option().empty()) throw;
    throw core::InputError(renamed(e.where()), e.problem(), e.hint());
  }
}

// Whether the source is a ROS 2 bag: format "mcap" or "db3", or "auto" and io::looks_like_mcap
// or io::looks_like_db3.
bool reads_bag(const LogSource& source) {
  return source.format == "mcap" || source.format == "db3" ||
         (source.format == "auto" && source.memory == nullptr &&
          (io::looks_like_mcap(source.file()) || io::looks_like_db3(source.file())));
}

io::LogFileRead::Format bag_format(const LogSource& source) {
  if (source.format == "mcap") return io::LogFileRead::Format::kMcap;
  if (source.format == "db3") return io::LogFileRead::Format::kDb3;
  return io::LogFileRead::Format::kAuto;  // a bag, of the format its content shows
}

// LogSource::column_map without the renaming of errors.
io::ColumnMap column_map_of(const LogSource& source, const RoleFilter& wanted) {
  io::ColumnMap map = source.base_map();
  if (reads_bag(source)) return map;  // a bag's fields are named by the map only
  std::vector<std::string> mapped_columns;
  for (const auto& [role, entry] : map.roles()) {
    if (entry.file.empty()) mapped_columns.push_back(entry.column);
  }
  for (const std::string& cell : io::read_csv_header(source.file())) {
    const std::string name = io::split_header_cell(cell).name;
    if (map.find(name) != nullptr || !wanted(name) || !io::find_role(name)) continue;
    // A column the user mapped to another role is not taken a second time.
    if (std::find(mapped_columns.begin(), mapped_columns.end(), name) != mapped_columns.end()) {
      continue;
    }
    map.set_column(name, name);
  }
  return map;
}

}  // namespace

io::ColumnMap LogSource::column_map(const RoleFilter& wanted) const {
  return naming_the_log(*this, [&] { return column_map_of(*this, wanted); });
}

namespace {

// The rate [Hz] of a channel's valid samples, from their median spacing; nullopt with fewer
// than two. `all_valid_hz` is the rate of a channel without gaps (the log's own, computed once).
std::optional<double> median_rate_hz(const core::Log& log, const core::Channel& channel,
                                     std::size_t missing,
                                     std::optional<std::optional<double>>& all_valid_hz,
                                     unsigned jobs) {
  if (missing == 0 && all_valid_hz) return *all_valid_hz;
  if (missing == 0) {  // the log's own time axis, no copy of it
    all_valid_hz = log.size() < 2
                       ? std::nullopt
                       : std::optional<double>(1.0 / core::median_spacing_s(log.time(), jobs));
    return *all_valid_hz;
  }
  std::vector<double> valid_t;
  valid_t.reserve(log.size() - missing);
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (!core::is_missing(channel.values[i])) valid_t.push_back(log.time()[i]);
  }
  const std::optional<double> rate =
      valid_t.size() < 2 ? std::nullopt
                         : std::optional<double>(1.0 / core::median_spacing_s(valid_t, jobs));
  return rate;
}

}  // namespace

io::InputReport describe_input(const core::Log& log, const std::string& file,
                               io::FileReport file_report, unsigned jobs) {
  io::InputReport input;
  file_report.path = file;
  file_report.records = log.size();
  input.files.push_back(std::move(file_report));
  const std::vector<core::Channel>& channels = log.channels();
  std::optional<std::optional<double>> all_valid_hz;
  for (const core::Channel& channel : channels) {
    const std::size_t missing = core::missing_count(channel.values, jobs);
    input.roles.push_back({channel.name, file,
                           median_rate_hz(log, channel, missing, all_valid_hz, jobs),
                           input.files.front().topic});
  }
  return input;
}

namespace {

// The channels of an in-memory log, each by its name or as ROLE=CHANNEL in `columns` renames
// it: channel → role.
std::map<std::string, std::string> memory_roles(const LogSource& source) {
  const core::Log& in = *source.memory;
  std::map<std::string, std::string> roles;
  for (const std::string& name : in.channel_names()) roles[name] = name;
  for (const std::string& c : source.columns) {
    const auto eq = c.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == c.size())
      throw option_error("col", "malformed argument '" + c + "': expected ROLE=CHANNEL");
    if (!in.has(c.substr(eq + 1)))
      throw option_error("col", "the log has no channel '" + c.substr(eq + 1) + "'",
                         "the channels are the log's names");
    roles[c.substr(eq + 1)] = c.substr(0, eq);
  }
  return roles;
}

// An in-memory log with its channels named by their roles (memory_roles).
LoadedLog load_memory(const LogSource& source) {
  const core::Log& in = *source.memory;
  const std::map<std::string, std::string> roles = memory_roles(source);
  LoadedLog out;
  out.log = core::Log(in.time());
  for (const core::Channel& ch : in.channels())
    out.log.add_channel(roles.at(ch.name), ch.unit, ch.values, ch.interp);
  const std::string name = source.log.empty() ? "<memory>" : source.log.string();
  io::FileReport file;
  file.format = "memory";
  file.time_format = "seconds";
  out.input = describe_input(out.log, name, std::move(file), source.jobs);
  if (!in.time().empty()) {
    out.log_start_s = in.time().front();
    out.log_end_s = in.time().back();
  }
  return out;
}

// --bag-time, checked.
io::BagTime bag_time_of(const LogSource& source) {
  const std::optional<io::BagTime> time = io::find_bag_time(source.bag_time);
  if (!time) {
    throw core::InputError::for_option(
        "bag_time", "unknown bag time '" + source.bag_time + "'",
        "use auto (header.stamp when the message has one, else the receive time), header or "
        "receive");
  }
  return *time;
}

// A log file (CSV, NMEA or a ROS 2 bag), with its other files, read from source.file().
LoadedLog load_file(const LogSource& source, const RoleFilter& wanted) {
  const io::BagTime bag_time = bag_time_of(source);
  const bool bag = reads_bag(source);
  if (!bag && reads_nmea(source)) return load_nmea(source, wanted);
  return read_log_files(source.file(), column_map_of(source, wanted), source.resample_options(),
                        {.format = bag ? bag_format(source) : io::LogFileRead::Format::kCsv,
                         .strict = source.strict,
                         .jobs = source.jobs,
                         .t_from_s = source.window_from_s,
                         .t_to_s = source.window_to_s,
                         .bag_time = bag_time,
                         .msg_path = source.msg_path});
}

}  // namespace

namespace {

// "the window 5 … 10 s", "the window from 5 s on", "the window up to 10 s": as it was given.
std::string window_text(const LogSource& source) {
  if (source.window_from_s && source.window_to_s) {
    return fmt::format("the window {:g} … {:g} s", *source.window_from_s, *source.window_to_s);
  }
  if (source.window_from_s) return fmt::format("the window from {:g} s on", *source.window_from_s);
  return fmt::format("the window up to {:g} s", source.window_to_s.value_or(0.0));
}

// The error of a window that holds no row of the log: the log's first row is at first_s, and
// last_s is its last row, or the first row after the window where reading stopped there.
core::InputError window_without_rows(const LogSource& source, double first_s, double last_s) {
  const std::string window = window_text(source);
  std::string problem;
  if (source.window_to_s && *source.window_to_s < first_s) {
    problem = fmt::format("{} ends before the log's first row at {:g} s", window, first_s);
  } else if (source.window_from_s && *source.window_from_s > last_s) {
    problem = fmt::format("{} starts after the log's last row at {:g} s", window, last_s);
  } else {
    problem =
        fmt::format("{} falls between two rows of the log (the next at {:g} s)", window, last_s);
  }
  return option_error_in_file(source.log, "from/to", problem,
                              "choose a window inside the logged time");
}

// `loaded` cut to the source's window: for a log read whole (an NMEA capture, a log in
// memory); a CSV log read within the window is left as it is.
void cut_to_window(const LogSource& source, LoadedLog& loaded) {
  const std::vector<double>& t = loaded.log.time();
  if (t.empty()) return;
  const double first = t.front(), last = t.back();
  const double from = source.window_from_s.value_or(first);
  const double to = source.window_to_s.value_or(last);
  if (from <= first && to >= last) return;
  if (from > last || to < first) throw window_without_rows(source, first, last);
  core::Log cut = loaded.log.window(from, to);
  if (cut.empty()) {  // between two rows: the next one after the window
    throw window_without_rows(source, first, *std::upper_bound(t.begin(), t.end(), to));
  }
  loaded.log = std::move(cut);
}

}  // namespace

core::InputError LogSource::in_log(const core::InputError& e) const {
  core::InputLocation where = e.where();
  if (where.file.empty() || (!read_from.empty() && where.file == read_from.string())) {
    where.file = log.empty() ? "<memory>" : log.string();
  }
  if (!e.option().empty())
    return core::InputError::for_option(e.option(), e.problem(), e.hint(), where.file);
  return core::InputError(where, e.problem(), e.hint());
}

core::InputError LogSource::error(const std::string& column, const std::string& problem,
                                  const std::string& hint) const {
  return core::InputError({log.empty() ? "<memory>" : log.string(), {}, {}, column}, problem, hint);
}

LoadedLog LogSource::load(const RoleFilter& wanted) const {
  if (window_from_s && window_to_s && !(*window_to_s > *window_from_s)) {
    throw option_error_in_file(
        log, "from/to",
        fmt::format("the window {:g} … {:g} s is empty", *window_from_s, *window_to_s),
        "give a start before the end");
  }
  if (memory) {
    LoadedLog out = load_memory(*this);
    if (has_window()) cut_to_window(*this, out);
    return out;
  }
  LoadedLog out;
  try {
    out = naming_the_log(*this, [&] { return load_file(*this, wanted); });
  } catch (const io::EmptyWindowError& e) {
    throw window_without_rows(*this, e.first_row_s, e.last_row_read_s);
  }
  if (has_window()) cut_to_window(*this, out);
  if (!read_from.empty()) {  // the report names the log as the user gave it
    for (io::FileReport& f : out.input.files) {
      if (f.path == read_from.string()) f.path = log.string();
    }
    for (io::RoleOrigin& r : out.input.roles) {
      if (r.file == read_from.string()) r.file = log.string();
    }
  }
  return out;
}

core::ResampleOptions LogSource::resample_options() const {
  if (!(max_gap_s >= 0.0)) {
    throw option_error("max_gap", fmt::format("the largest gap must be >= 0 s, got {}", max_gap_s),
                       "0 = automatic: 2.5 times each role's median spacing");
  }
  return core::ResampleOptions{.max_gap_s = max_gap_s};
}

core::Log LogSource::read(const RoleFilter& wanted) const { return load(wanted).log; }

bool LogSource::gives(const std::string& role, const RoleFilter& wanted) const {
  if (!memory) return column_map(wanted).find(role) != nullptr;
  for (const auto& [channel, r] : memory_roles(*this))
    if (r == role) return true;
  return false;
}

io::InputReport relative_to(io::InputReport input, const std::filesystem::path& base) {
  const auto relative = [&base](std::string& path) {
    const std::filesystem::path r = std::filesystem::path(path).lexically_relative(base);
    if (!r.empty() && *r.begin() != "..") path = r.generic_string();
  };
  for (io::FileReport& f : input.files) relative(f.path);
  for (io::RoleOrigin& r : input.roles) relative(r.file);
  return input;
}

std::vector<std::string> thruster_names(const core::Log& log, const std::string& prefix) {
  std::vector<std::string> names;
  const std::string head = prefix + ".";
  for (const core::Channel& c : log.channels()) {
    if (c.name.rfind(head, 0) != 0) continue;
    const std::string name = c.name.substr(head.size());
    if (name.find('.') != std::string::npos) continue;
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

std::vector<double> values_or_empty(const core::Log& log, const std::string& name) {
  return log.has(name) ? log.values(name) : std::vector<double>{};
}

std::optional<ident::LocalPositions> local_position(const core::Log& log) {
  if (log.has("north") && log.has("east")) {
    return ident::LocalPositions{log.values("north"), log.values("east")};
  }
  if (log.has("lat") && log.has("lon")) {
    return ident::local_north_east(log.values("lat"), log.values("lon"));
  }
  return std::nullopt;
}

std::vector<std::string> thrust_power_names(const core::Log& log) {
  std::vector<std::string> names = thruster_names(log, "thrust");
  for (const std::string& n : thruster_names(log, "power")) {
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  }
  return names;
}

std::vector<ident::ThrusterChannels> thrust_power_channels(const core::Log& log) {
  std::vector<ident::ThrusterChannels> out;
  for (const std::string& n : thrust_power_names(log)) {
    out.push_back({n, values_or_empty(log, "thrust." + n), values_or_empty(log, "power." + n)});
  }
  return out;
}

}  // namespace dynpos::analysis
