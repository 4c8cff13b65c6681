#include "dynpos/io/column_map.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include <toml++/toml.h>

#include "dynpos/io/text_file.hpp"
#include "text_util.hpp"

namespace dynpos::io {
namespace {

using core::InputError;
using core::InputLocation;

RoleSpec require_role(std::string_view role, const InputLocation& where) {
  if (auto spec = find_role(role)) return *spec;
  std::string hint;
  if (const std::string near = closest_role(role); !near.empty()) {
    hint = fmt::format("did you mean '{}'? ", near);
  }
  hint += "the roles are listed in docs/log-format.md";
  throw InputError(where, fmt::format("unknown role '{}'", role), hint);
}

InputLocation at(const std::string& file, const toml::source_region& region) {
  InputLocation where;
  where.file = file;
  if (region.begin.line > 0) where.line = region.begin.line;
  if (region.begin.column > 0) where.column = region.begin.column;
  return where;
}

InputLocation command_line(std::string_view option) {
  InputLocation where;
  where.column_name = std::string(option);
  return where;
}

// Splits "ROLE=VALUE" at the first '='; both sides trimmed and non-empty.
std::pair<std::string, std::string> split_assignment(std::string_view argument,
                                                     std::string_view option,
                                                     std::string_view value_name,
                                                     std::string_view example) {
  const auto eq = argument.find('=');
  const std::string_view role = detail::trim(argument.substr(0, eq));
  const std::string_view value =
      eq == std::string_view::npos ? std::string_view{} : detail::trim(argument.substr(eq + 1));
  if (eq == std::string_view::npos || role.empty() || value.empty()) {
    throw InputError(command_line(option),
                     fmt::format("malformed argument '{}': expected ROLE={}", argument, value_name),
                     fmt::format("for example {} {}", option, example));
  }
  return {std::string(role), std::string(value)};
}

// A file named in the map: relative to the folder of the map file `source_name`.
std::string resolve_file(std::string_view text, const std::string& source_name) {
  const std::filesystem::path path(text);
  const std::filesystem::path folder = std::filesystem::path(source_name).parent_path();
  if (path.is_absolute() || folder.empty()) return path.lexically_normal().string();
  return (folder / path).lexically_normal().string();
}

std::string file_name(const toml::node& node, const std::string& source_name) {
  const auto text = node.value<std::string>();
  if (!text || text->empty()) {
    throw InputError(at(source_name, node.source()), "file must be a non-empty string",
                     "for example file = \"nav.csv\" (relative to the map file's folder)");
  }
  return resolve_file(*text, source_name);
}

// [files."nav.csv"]: time = "t", clock_offset = 0.25.
void read_files_table(const toml::table& table, ColumnMap& map, const std::string& source_name) {
  for (auto&& [key, node] : table) {
    const std::string file = resolve_file(key.str(), source_name);
    const toml::table* options = node.as_table();
    if (options == nullptr || key.str().empty()) {
      throw InputError(at(source_name, key.source()),
                       fmt::format("files.\"{}\" must be a table", key.str()),
                       "for example [files.\"nav.csv\"] with time and clock_offset");
    }
    for (auto&& [name, value] : *options) {
      const InputLocation where = at(source_name, value.source());
      if (name.str() == "time") {
        const auto column = value.value<std::string>();
        if (!column || !value.is_string()) throw InputError(where, "time must be a column name");
        map.set_time_column({.file = file, .column = *column}, where);
      } else if (name.str() == "clock_offset") {
        const auto offset = value.value<double>();
        if (!offset) throw InputError(where, "clock_offset must be a number of seconds");
        map.set_clock_offset(file, *offset, where);
      } else {
        throw InputError(at(source_name, name.source()),
                         fmt::format("unknown key '{}' in [files.\"{}\"]", name.str(), key.str()),
                         "the keys are time and clock_offset");
      }
    }
  }
}

char parse_delimiter(const toml::node& node, const std::string& file) {
  const auto text = node.value<std::string>();
  if (text) {
    if (*text == "," || *text == ";" || *text == "\t") return (*text)[0];
    if (*text == "tab") return '\t';
  }
  throw InputError(at(file, node.source()),
                   "csv.delimiter must be \"auto\", \",\", \";\", \"\\t\" or \"tab\"");
}

// [time]: format, date and order of the time stamps (time_stamp.hpp).
void read_time_table(const toml::table& table, TimeStampOptions& time, const std::string& file) {
  for (auto&& [key, node] : table) {
    const std::string_view name = key.str();
    const std::optional<std::string> text = node.value<std::string>();
    const InputLocation where = at(file, node.source());
    if (name != "format" && name != "date" && name != "order") {
      throw InputError(at(file, key.source()), fmt::format("unknown key '{}' in [time]", name),
                       "the keys are format, date and order");
    }
    if (!text) throw InputError(where, fmt::format("time.{} must be a string", name));
    if (name == "format") {
      const std::optional<TimeFormat> format = find_time_format(*text);
      if (!format) {
        throw InputError(where, fmt::format("unknown time format '{}'", *text),
                         fmt::format("the formats are: {}", time_format_names()));
      }
      time.format = *format;
    } else if (name == "date") {
      if (!parse_date_days(*text)) {
        throw InputError(where, fmt::format("'{}' is not a date", *text),
                         "write it as \"YYYY-MM-DD\"");
      }
      time.date = *text;
    } else {
      const std::optional<TimeOrder> order = find_time_order(*text);
      if (!order) {
        throw InputError(where, fmt::format("unknown time order '{}'", *text),
                         "the policies are: error, drop-duplicates, drop-non-increasing");
      }
      time.order = *order;
    }
  }
}

void read_csv_table(const toml::table& table, CsvFormat& format, const std::string& file) {
  for (auto&& [key, node] : table) {
    const std::string_view name = key.str();
    if (name == "delimiter") {
      if (node.value<std::string>() == std::optional<std::string>("auto")) {
        format.delimiter.reset();
      } else {
        format.delimiter = parse_delimiter(node, file);
      }
    } else if (name == "comment") {
      const auto text = node.value<std::string>();
      if (!text) throw InputError(at(file, node.source()), "csv.comment must be a string");
      format.comment_prefix = *text;
    } else if (name == "missing") {
      const toml::array* items = node.as_array();
      if (items == nullptr) {
        throw InputError(at(file, node.source()), "csv.missing must be an array of strings",
                         "for example missing = [\"NA\", \"NaN\"]");
      }
      format.missing_tokens.clear();
      for (const toml::node& item : *items) {
        const auto text = item.value<std::string>();
        if (!text) {
          throw InputError(at(file, item.source()), "csv.missing must be an array of strings");
        }
        format.missing_tokens.push_back(*text);
      }
    } else {
      throw InputError(at(file, key.source()), fmt::format("unknown key '{}' in [csv]", name),
                       "the keys are delimiter, comment and missing");
    }
  }
  try {
    format.validate();
  } catch (const InputError& e) {
    throw InputError(at(file, table.source()), e.problem(), e.hint());
  }
}

void read_role_table(const std::string& role, const toml::table& table, ColumnMap& map,
                     const std::string& file, const toml::source_region& where) {
  const toml::node* column = table.get("column");
  if (column == nullptr || !column->is_string()) {
    throw InputError(at(file, where), fmt::format("role '{}' needs column = \"NAME\"", role),
                     fmt::format("for example {} = {{ column = \"HDG\", unit = \"deg\" }}", role));
  }
  const toml::node* in_file = table.get("file");
  if (role == "time" && in_file != nullptr) {
    // The time column of another file: that file's, not the main log's.
    if (table.size() > 2) {
      throw InputError(at(file, where), "the time of another file takes only column and file",
                       "a time unit comes from the header, e.g. \"t [ms]\"");
    }
    map.set_time_column(
        {.file = file_name(*in_file, file), .column = *column->value<std::string>()},
        at(file, column->source()));
    return;
  }
  map.set_column(role, *column->value<std::string>(), at(file, column->source()));
  for (auto&& [key, node] : table) {
    const std::string_view name = key.str();
    if (name == "column") continue;
    if (name == "file") {
      map.set_file(role, file_name(node, file), at(file, node.source()));
      continue;
    }
    if (name == "unit") {
      const auto unit = node.value<std::string>();
      if (!unit) throw InputError(at(file, node.source()), "unit must be a string");
      map.set_unit({.role = role, .unit = *unit}, at(file, node.source()));
    } else if (name == "scale") {
      const auto scale = node.value<double>();
      if (!scale) throw InputError(at(file, node.source()), "scale must be a number");
      map.set_scale(role, *scale, at(file, node.source()));
    } else {
      throw InputError(at(file, key.source()),
                       fmt::format("unknown key '{}' for role '{}'", name, role),
                       "the keys are column, unit, scale and file");
    }
  }
}

// Walks [roles]; dotted keys (thrust.port = "X", [roles.gnss1]) are joined back into role names.
void read_roles_table(const std::string& prefix, const toml::table& table, ColumnMap& map,
                      const std::string& file) {
  for (auto&& [key, node] : table) {
    const std::string role =
        prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (const auto column = node.value<std::string>(); column && node.is_string()) {
      require_role(role, at(file, key.source()));
      map.set_column(role, *column, at(file, node.source()));
    } else if (const toml::table* sub = node.as_table()) {
      if (sub->contains("column") || find_role(role)) {
        require_role(role, at(file, key.source()));
        read_role_table(role, *sub, map, file, key.source());
      } else {
        read_roles_table(role, *sub, map, file);
      }
    } else {
      throw InputError(at(file, node.source()),
                       fmt::format("role '{}' must be a column name or a table", role),
                       fmt::format("for example {} = \"Column name\"", role));
    }
  }
}

}  // namespace

void CsvFormat::validate() const {
  if (delimiter && *delimiter != ',' && *delimiter != ';' && *delimiter != '\t') {
    throw InputError({}, fmt::format("unsupported delimiter '{}'", *delimiter),
                     "use ',', ';' or a tab");
  }
  if (comment_prefix.find_first_of(",;\t\"") != std::string::npos) {
    throw InputError(
        {}, fmt::format("comment prefix '{}' contains a delimiter or quote", comment_prefix));
  }
}

core::Unit unit_for_role(const RoleSpec& role, std::string_view spelling,
                         const InputLocation& where) {
  const auto unit = core::find_unit(spelling);
  if (!unit) {
    const std::string hint =
        role.quantity
            ? fmt::format("accepted spellings for {} ({}): {}", core::quantity_name(*role.quantity),
                          role.name, detail::join(core::unit_spellings(*role.quantity)))
            : std::string("the accepted spellings are listed in docs/log-format.md");
    throw InputError(where, fmt::format("unknown unit '{}' for role '{}'", spelling, role.name),
                     hint);
  }
  if (role.quantity && unit->quantity != *role.quantity) {
    throw InputError(
        where,
        fmt::format("unit '{}' measures {}, but role '{}' is {}", spelling,
                    core::quantity_name(unit->quantity), role.name,
                    core::quantity_name(*role.quantity)),
        fmt::format("use one of: {}", detail::join(core::unit_spellings(*role.quantity))));
  }
  return *unit;
}

RoleColumn& ColumnMap::entry(std::string_view role, const InputLocation& where) {
  require_role(role, where);
  auto it = roles_.find(role);
  if (it == roles_.end()) it = roles_.emplace(std::string(role), RoleColumn{}).first;
  return it->second;
}

// Public API (role first, as everywhere in ColumnMap) with some 30 callers outside the io
// module (analysis, tests, benchmarks), each naming both arguments: a struct argument would
// change them all for no safety they lack.
// NOLINTNEXTLINE(bugprone-easily-swappable-parameters)
void ColumnMap::set_column(std::string_view role, std::string_view column, InputLocation where) {
  RoleColumn& e = entry(role, where);
  const std::string_view name = detail::trim(column);
  if (name.empty()) {
    throw InputError(where, fmt::format("empty column name for role '{}'", role));
  }
  e.column = std::string(name);
  e.source = std::move(where);
}

void ColumnMap::replace_column(std::string_view role, std::string_view column,
                               InputLocation where) {
  set_column(role, column, std::move(where));
  RoleColumn& e = roles_.find(role)->second;
  e.unit.reset();
  e.scale = 1.0;
}

void ColumnMap::set_unit(RoleUnit role_unit, InputLocation where) {
  const auto [role, unit] = role_unit;
  const RoleSpec spec = require_role(role, where);
  unit_for_role(spec, unit, where);
  RoleColumn& e = entry(role, where);
  e.unit = std::string(detail::trim(unit));
  if (e.source.file.empty() && e.source.column_name.empty()) e.source = std::move(where);
}

void ColumnMap::set_scale(std::string_view role, double scale, InputLocation where) {
  RoleColumn& e = entry(role, where);
  if (!std::isfinite(scale) || scale == 0.0) {
    throw InputError(
        where, fmt::format("scale {} for role '{}' must be finite and non-zero", scale, role));
  }
  e.scale = scale;
}

LogFileOptions& ColumnMap::file_entry(std::string_view file, const InputLocation& where) {
  if (detail::trim(file).empty()) throw InputError(where, "empty file name");
  auto it = files_.find(file);
  if (it == files_.end()) {
    it = files_.emplace(std::string(file), LogFileOptions{}).first;
    it->second.source = where;
  }
  return it->second;
}

void ColumnMap::set_file(std::string_view role, std::string_view file, InputLocation where) {
  if (role == "time" && !file.empty()) {
    throw InputError(
        where, "the main log's time cannot come from another file",
        fmt::format("to name the time column of {} write --col time=COLUMN@{}", file, file));
  }
  if (!file.empty() && detail::trim(file).empty()) throw InputError(where, "empty file name");
  entry(role, where).file = std::string(file);
}

void ColumnMap::set_time_column(FileTimeColumn time, InputLocation where) {
  const auto [file, column] = time;
  const std::string_view name = detail::trim(column);
  if (name.empty()) throw InputError(where, fmt::format("empty time column for file '{}'", file));
  file_entry(file, where).time_column = std::string(name);
}

void ColumnMap::set_clock_offset(std::string_view file, double offset_s, InputLocation where) {
  if (!std::isfinite(offset_s)) {
    throw InputError(where,
                     fmt::format("clock offset {} s for '{}' is not finite", offset_s, file));
  }
  file_entry(file, where).clock_offset_s = offset_s;
}

ColumnMap ColumnMap::for_file(std::string_view file) const {
  ColumnMap out;
  out.format_ = format_;
  // The date and the order rule hold for every file; a forced form is the main log's, and
  // each further file's form is detected from its own cells.
  out.time_ = time_;
  if (!file.empty()) out.time_.format = TimeFormat::kAuto;
  for (const auto& [role, e] : roles_) {
    if (e.file != file || (role == "time" && !file.empty())) continue;
    RoleColumn copy = e;
    copy.file.clear();
    out.roles_.emplace(role, std::move(copy));
  }
  const bool two_column = out.find("time.sec") != nullptr || out.find("time.nsec") != nullptr;
  if (!file.empty() && !two_column) {
    const LogFileOptions options = file_options(file);
    RoleColumn time;
    time.column = options.time_column;
    time.source = options.source;
    out.roles_.insert_or_assign("time", std::move(time));
  }
  return out;
}

std::vector<std::string> ColumnMap::other_files() const {
  std::vector<std::string> files;
  for (const auto& [role, e] : roles_) {
    if (!e.file.empty() && std::find(files.begin(), files.end(), e.file) == files.end()) {
      files.push_back(e.file);
    }
  }
  return files;
}

LogFileOptions ColumnMap::file_options(std::string_view file) const {
  const auto it = files_.find(file);
  return it == files_.end() ? LogFileOptions{} : it->second;
}

const RoleColumn* ColumnMap::find(std::string_view role) const {
  const auto it = roles_.find(role);
  return it == roles_.end() ? nullptr : &it->second;
}

namespace {

// A problem found by validate() at `where`: an error of the option it was given with when it
// came from the command line ("--unit u=kn": option key unit, as the override's own errors), so
// each front end spells it its own way; else of the map file.
InputError deferred_error(const InputLocation& where, const std::string& problem,
                          const std::string& hint) {
  static constexpr std::pair<std::string_view, std::string_view> kKeys[] = {
      {"--col ", "col"}, {"--unit ", "unit"}, {"--clock-offset ", "clock_offset"}};
  if (where.file.empty()) {
    for (const auto& [flag, key] : kKeys) {
      if (where.column_name.rfind(flag, 0) != 0) continue;
      const std::string argument = where.column_name.substr(flag.size());
      return InputError::for_option(std::string(key), fmt::format("'{}': {}", argument, problem),
                                    hint);
    }
  }
  return InputError(where, problem, hint);
}

}  // namespace

void ColumnMap::validate() const {
  format_.validate();
  for (const auto& [role, e] : roles_) {
    if (e.column.empty()) {
      throw deferred_error(
          e.source, fmt::format("role '{}' has a unit or scale but no column", role),
          fmt::format("map it with --col {}=COLUMN or in [roles] of the map file", role));
    }
  }
  for (const auto& [file, options] : files_) {
    const bool used = std::any_of(roles_.begin(), roles_.end(), [&file = file](const auto& role) {
      return role.second.file == file;
    });
    if (!used) {
      throw deferred_error(options.source, fmt::format("no role is read from '{}'", file),
                           fmt::format("map a role with --col ROLE=COLUMN@{} or file = \"...\" in "
                                       "[roles], or check the file name",
                                       file));
    }
  }
  // Each file has one time axis: the main log its `time` column or time.sec with time.nsec;
  // a further file its time column (set_time_column) or time.sec with time.nsec of its own.
  const RoleColumn* sec = find("time.sec");
  const RoleColumn* nsec = find("time.nsec");
  if ((sec == nullptr) != (nsec == nullptr) || (sec != nullptr && sec->file != nsec->file)) {
    throw InputError({}, "time.sec and time.nsec go together",
                     "map both, from the same file: --col time.sec=COLUMN --col time.nsec=COLUMN");
  }
  const bool main_two_column = sec != nullptr && sec->file.empty();
  if (find("time") == nullptr && !main_two_column) {
    throw InputError({}, "the column map has no 'time' column",
                     "map it with --col time=COLUMN or time = \"COLUMN\" in [roles]");
  }
  if (main_two_column && find("time") != nullptr) {
    throw InputError({}, "both 'time' and time.sec/time.nsec are mapped",
                     "map either one time column or the two-column form");
  }
}

ColumnMap parse_column_map(std::string_view toml_text, const std::string& source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    throw InputError(at(source_name, e.source()),
                     fmt::format("TOML syntax error: {}", e.description()));
  }
  ColumnMap map;
  for (auto&& [key, node] : root) {
    const std::string_view name = key.str();
    const toml::table* table = node.as_table();
    if ((name == "csv" || name == "roles" || name == "files" || name == "time") &&
        table == nullptr) {
      throw InputError(at(source_name, key.source()), fmt::format("'{}' must be a table", name),
                       fmt::format("write it as [{}]", name));
    }
    if (name == "csv") {
      read_csv_table(*table, map.format(), source_name);
    } else if (name == "roles") {
      read_roles_table("", *table, map, source_name);
    } else if (name == "files") {
      read_files_table(*table, map, source_name);
    } else if (name == "time") {
      read_time_table(*table, map.time(), source_name);
    } else {
      throw InputError(at(source_name, key.source()),
                       fmt::format("unknown table or key '{}' in the column map", name),
                       "the tables are [csv], [roles], [files] and [time]");
    }
  }
  return map;
}

ColumnMap load_column_map(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    InputLocation where;
    where.file = path.string();
    throw InputError(where, "cannot open the column map file", "check the path");
  }
  const std::string text = read_capped(
      in, path, kMaxTomlBytes,
      "a column map is a few lines of TOML (docs/log-format.md); is this the right file?");
  return parse_column_map(text, path.string());
}

namespace {

// `e`, raised by the argument `argument` of the option `key` ("col", "unit", "clock_offset"), as
// an error of that option: the library names the option by its key and each front end spells
// it (--col on the command line, col= in Python); the argument is quoted in the problem.
InputError override_error(std::string_view key, std::string_view argument, const InputError& e) {
  std::string problem = e.problem();
  if (problem.find(argument) == std::string::npos) {
    problem = fmt::format("'{}': {}", argument, problem);
  }
  return InputError::for_option(std::string(key), problem, e.hint());
}

// Runs `apply`, turning its errors into errors of the option `key` (override_error).
template <class Apply>
void as_option(std::string_view key, std::string_view argument, Apply&& apply) {
  try {
    apply();
  } catch (const InputError& e) {
    throw override_error(key, argument, e);
  }
}

void apply_column_override_at(ColumnMap& map, std::string_view argument);
void apply_clock_offset_override_at(ColumnMap& map, std::string_view argument);

}  // namespace

void apply_column_override(ColumnMap& map, std::string_view argument) {
  as_option("col", argument, [&] { apply_column_override_at(map, argument); });
}

namespace {

void apply_column_override_at(ColumnMap& map, std::string_view argument) {
  auto [role, column] = split_assignment(argument, "--col", "COLUMN", "heading=HDG");
  const InputLocation where = command_line("--col " + std::string(argument));
  std::string file;
  if (const auto at_sign = column.rfind('@'); at_sign != std::string::npos) {
    file = std::string(detail::trim(std::string_view(column).substr(at_sign + 1)));
    column = std::string(detail::trim(std::string_view(column).substr(0, at_sign)));
    if (file.empty() || column.empty()) {
      throw InputError(where,
                       fmt::format("malformed argument '{}': expected ROLE=COLUMN@FILE", argument),
                       "for example --col heading=HDG@nav.csv");
    }
    if (role == "time") {
      map.set_time_column({.file = file, .column = column}, where);
      return;
    }
  }
  map.replace_column(role, column, where);
  map.set_file(role, file, where);
}

}  // namespace

void apply_clock_offset_override(ColumnMap& map, std::string_view argument) {
  as_option("clock_offset", argument, [&] { apply_clock_offset_override_at(map, argument); });
}

namespace {

void apply_clock_offset_override_at(ColumnMap& map, std::string_view argument) {
  const InputLocation where = command_line("--clock-offset " + std::string(argument));
  const auto eq = argument.rfind('=');
  const std::string_view file =
      eq == std::string_view::npos ? std::string_view{} : detail::trim(argument.substr(0, eq));
  const std::string_view text =
      eq == std::string_view::npos ? std::string_view{} : detail::trim(argument.substr(eq + 1));
  double offset_s = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), offset_s);
  if (file.empty() || text.empty() || ec != std::errc() || ptr != text.data() + text.size()) {
    throw InputError(where, fmt::format("malformed argument '{}': expected FILE=SECONDS", argument),
                     "for example --clock-offset nav.csv=0.25 (added to that file's times)");
  }
  map.set_clock_offset(file, offset_s, where);
}

}  // namespace

void apply_unit_override(ColumnMap& map, std::string_view argument) {
  as_option("unit", argument, [&] {
    auto [role, unit] = split_assignment(argument, "--unit", "UNIT", "heading=deg");
    map.set_unit({.role = role, .unit = unit}, command_line("--unit " + std::string(argument)));
  });
}

void apply_time_overrides(ColumnMap& map, std::string_view format, std::string_view date,
                          std::string_view order) {
  if (!format.empty()) {
    const std::optional<TimeFormat> f = find_time_format(format);
    if (!f) {
      throw InputError::for_option("time_format", fmt::format("unknown time format '{}'", format),
                                   fmt::format("the formats are: {}", time_format_names()));
    }
    map.time().format = *f;
  }
  if (!date.empty()) {
    if (!parse_date_days(date)) {
      throw InputError::for_option("date", fmt::format("'{}' is not a date", date),
                                   "write it as YYYY-MM-DD, e.g. 2024-05-01");
    }
    map.time().date = std::string(date);
  }
  if (!order.empty()) {
    const std::optional<TimeOrder> o = find_time_order(order);
    if (!o) {
      throw InputError::for_option("time_order", fmt::format("unknown time order '{}'", order),
                                   "the policies are: error, drop-duplicates, drop-non-increasing");
    }
    map.time().order = *o;
  }
}

namespace {

// A role given twice by one option (--col heading=A --col heading=B): an error, not the last
// one silently kept. `time=COLUMN@FILE` names the time of FILE, so each file's time is its own.
void check_each_role_once(const std::vector<std::string>& arguments, std::string_view option) {
  std::map<std::string, std::string, std::less<>> seen;  // role (and file of time) → argument
  for (const auto& argument : arguments) {
    const auto eq = argument.find('=');
    if (eq == std::string::npos) continue;  // malformed: its own error comes later
    std::string role(detail::trim(std::string_view(argument).substr(0, eq)));
    if (role == "time" && argument.rfind('@') != std::string::npos) {
      role += argument.substr(argument.rfind('@'));
    }
    const auto [it, fresh] = seen.emplace(role, argument);
    if (!fresh) {
      throw InputError::for_option(
          option == "--col" ? "col" : "unit",
          fmt::format("role '{}' is given twice: '{}' and '{}'", it->first, it->second, argument),
          fmt::format("give each role once with {}", option));
    }
  }
}

}  // namespace

void apply_overrides(ColumnMap& map, const std::vector<std::string>& column_arguments,
                     const std::vector<std::string>& unit_arguments) {
  check_each_role_once(column_arguments, "--col");
  check_each_role_once(unit_arguments, "--unit");
  for (const auto& argument : column_arguments) apply_column_override(map, argument);
  for (const auto& argument : unit_arguments) apply_unit_override(map, argument);
}

}  // namespace dynpos::io
