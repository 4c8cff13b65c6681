#pragma once
/// \file
/// ColumnMap: which column of a CSV log holds which role, in which unit and scale.
///
/// A map comes from a TOML file (load_column_map) and/or the command line (apply_overrides);
/// the command line wins. Every role, unit and number is checked when it enters the map, so
/// a bad map fails before any log is read, with the file, line and column of the mistake.
///
/// TOML schema (full reference and example in docs/log-format.md):
///
///     [csv]                        # optional; the defaults are shown
///     delimiter = "auto"           # "auto", ",", ";", "\t" or "tab"
///     comment = "#"                # lines starting with this are skipped; "" = none
///     missing = []                 # tokens read as missing, besides the empty cell
///
///     [time]                       # optional; the defaults are shown
///     format = "auto"              # or seconds, epoch-s|ms|us|ns, iso8601, time-of-day, sec-nsec
///     date = ""                    # "YYYY-MM-DD": the date of time-of-day stamps
///     order = "error"              # or drop-duplicates, drop-non-increasing
///
///     [roles]
///     time = "Time [s]"                              # just the column name
///     heading = { column = "HDG", unit = "deg" }     # column and unit
///     "thrust.port" = { column = "PS thrust", unit = "kN", scale = 1.0 }
///     heading = { column = "HDG", file = "nav.csv" }  # a column of another file
///
///     [files."nav.csv"]            # optional, for a file other than the main log
///     time = "t"                   # its time column; default "time"
///     clock_offset = 0.25          # [s] added to its times to put them on the main log's clock
///
/// A relative `file` (and a [files] key) is relative to the folder of the map file; on the
/// command line (--col ROLE=COLUMN@FILE) it is relative to the working directory, like LOG.
/// How the files are aligned on the main log's clock: analysis/log_source.hpp, read_log_files.
///
/// Unit resolution for a mapped column, first match wins:
///   1. the declared unit (--unit ROLE=UNIT, else `unit` in the map file);
///   2. a unit in brackets at the end of the CSV header ("Speed [kn]", "Heading (deg)");
///   3. the role's default unit (roles.hpp).
///
/// Scale multiplies the raw number before unit conversion: value in the unit = raw × scale,
/// then SI = unit.to_si(raw × scale). Use it for loggers that store scaled integers
/// (heading in 0.01° → unit = "deg", scale = 0.01) or the opposite sign convention (-1).

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/core/units.hpp"
#include "dynpos/io/roles.hpp"
#include "dynpos/io/time_stamp.hpp"

namespace dynpos::io {

/// How the CSV text is split and which cells mean "missing".
struct CsvFormat {
  /// Field delimiter; nullopt = detect from the header line (comma, semicolon or tab: the one
  /// that occurs most often outside quotes; comma when none occurs).
  std::optional<char> delimiter;
  /// Lines whose first non-blank characters are this prefix are skipped; empty = no comments.
  std::string comment_prefix = "#";
  /// Cell texts (after trimming spaces, case-sensitive) read as missing, besides the empty
  /// cell, e.g. {"NA", "NaN"}. Without them a literal "nan" or "inf" cell is an error.
  std::vector<std::string> missing_tokens;

  /// Throws core::InputError if the delimiter is not ',', ';' or '\t' or the comment prefix
  /// contains a delimiter character.
  void validate() const;
};

/// One role's column: where it is in the file and how its numbers become SI.
struct RoleColumn {
  std::string column;               ///< header name in the file; empty = not given yet
  std::optional<std::string> unit;  ///< declared unit spelling (checked against the role)
  double scale = 1.0;               ///< multiplies the raw number before unit conversion
  core::InputLocation source;       ///< where the column was declared, for error messages
  std::string file;                 ///< the file holding the column; empty = the main log
};

/// A file other than the main log that roles are read from.
struct LogFileOptions {
  std::string time_column = "time";  ///< its time column (header name)
  /// [s] added to the file's times to put them on the main log's clock: t_main = t_file + offset;
  /// finite, any sign.
  double clock_offset_s = 0.0;
  core::InputLocation source;  ///< where the file was first named, for error messages
};

/// A role and the unit of its column: set_unit({.role = "heading", .unit = "deg"}).
struct RoleUnit {
  std::string_view role;
  std::string_view unit;
};

/// A file other than the main log and its time column: set_time_column({.file = "nav.csv",
/// .column = "t"}).
struct FileTimeColumn {
  std::string_view file;
  std::string_view column;
};

/// Roles → columns, plus the CSV format options.
class ColumnMap {
 public:
  /// Maps `role` to `column`. Throws core::InputError (at `where`) for an unknown role or an
  /// empty column name.
  void set_column(std::string_view role, std::string_view column, core::InputLocation where = {});
  /// Like set_column(), and forgets the role's unit and scale (they described the old column).
  void replace_column(std::string_view role, std::string_view column,
                      core::InputLocation where = {});
  /// Declares the unit of a role. Throws core::InputError for an unknown role, an unknown unit
  /// (the hint lists the spellings of the role's quantity) or a unit of another quantity.
  void set_unit(RoleUnit role_unit, core::InputLocation where = {});
  /// Sets the scale of `role`. Throws core::InputError if it is not finite or is zero.
  void set_scale(std::string_view role, double scale, core::InputLocation where = {});
  /// Reads `role` from `file` (empty = the main log). Throws core::InputError for an unknown
  /// role or for `time` with a file (use set_time_column).
  void set_file(std::string_view role, std::string_view file, core::InputLocation where = {});
  /// The time column of a file other than the main log. Throws core::InputError for an empty
  /// file or column name.
  void set_time_column(FileTimeColumn time, core::InputLocation where = {});
  /// The clock offset [s] of `file`. Throws core::InputError if it is not finite.
  void set_clock_offset(std::string_view file, double offset_s, core::InputLocation where = {});

  /// The role's entry, or nullptr if the role is not mapped.
  const RoleColumn* find(std::string_view role) const;
  /// All entries, by role name.
  const std::map<std::string, RoleColumn, std::less<>>& roles() const noexcept { return roles_; }
  bool empty() const noexcept { return roles_.empty(); }
  /// The files other than the main log that roles are read from, by path as given, in the
  /// order of their first role by name.
  std::vector<std::string> other_files() const;
  /// The time column and clock offset of `file`; the defaults when none were given.
  LogFileOptions file_options(std::string_view file) const;
  /// The map of one file's roles, as read_csv() takes it: the roles whose file is `file` (no
  /// longer marked with it), `time` mapped to the file's time column (unless its time.sec and
  /// time.nsec are mapped), the same CSV format, date and time order; the time format is the
  /// map's for the main log, detected (kAuto) for any other file. for_file("") is the main log's
  /// map.
  ColumnMap for_file(std::string_view file) const;

  const CsvFormat& format() const noexcept { return format_; }
  CsvFormat& format() noexcept { return format_; }

  /// How the time stamps are read (form, date, order policy).
  const TimeStampOptions& time() const noexcept { return time_; }
  TimeStampOptions& time() noexcept { return time_; }

  /// Throws core::InputError if neither `time` nor time.sec + time.nsec (exactly one form) is
  /// mapped, a role has a unit or scale but no column (e.g. --unit heading=rad without a column
  /// for heading), or a file has options but no role is read from it (e.g. a misspelt
  /// --clock-offset FILE).
  void validate() const;

 private:
  RoleColumn& entry(std::string_view role, const core::InputLocation& where);
  LogFileOptions& file_entry(std::string_view file, const core::InputLocation& where);

  std::map<std::string, RoleColumn, std::less<>> roles_;
  std::map<std::string, LogFileOptions, std::less<>> files_;
  CsvFormat format_;
  TimeStampOptions time_;
};

/// Parses a TOML column map; `source_name` (a path) is used in error messages.
/// Throws core::InputError with line and column for TOML syntax errors, unknown tables or
/// keys, unknown roles and bad units.
ColumnMap parse_column_map(std::string_view toml_text, const std::string& source_name);

/// Reads and parses a TOML column map file. Throws core::InputError if it cannot be read.
ColumnMap load_column_map(const std::filesystem::path& path);

/// Applies one `--col ROLE=COLUMN` or `--col ROLE=COLUMN@FILE` argument (the text after the
/// option; the last '@' separates the file, so a column whose name has an '@' is mapped in the
/// map file). `time=COLUMN@FILE` sets the time column of FILE. Replacing a role's column also
/// drops the unit and scale the map file declared for it, since they described the old column.
/// Throws core::InputError for a malformed argument or an unknown role.
void apply_column_override(ColumnMap& map, std::string_view argument);

/// Applies one `--clock-offset FILE=SECONDS` argument. Throws core::InputError for a malformed
/// argument or an offset that is not a finite number.
void apply_clock_offset_override(ColumnMap& map, std::string_view argument);

/// Applies one `--unit ROLE=UNIT` argument. Throws core::InputError for a malformed argument,
/// an unknown role, an unknown unit or a unit of the wrong quantity.
void apply_unit_override(ColumnMap& map, std::string_view argument);

/// Applies all `--col` arguments, then all `--unit` arguments, so a unit given on the command
/// line always survives a column given there too.
void apply_overrides(ColumnMap& map, const std::vector<std::string>& column_arguments,
                     const std::vector<std::string>& unit_arguments);

/// Applies --time-format, --date and --time-order (each ignored when empty) to map.time().
/// Throws core::InputError::for_option for an unknown format or policy or an invalid date.
void apply_time_overrides(ColumnMap& map, std::string_view format, std::string_view date,
                          std::string_view order);

/// The unit `spelling` for `role`, checked: throws core::InputError at `where` if the
/// spelling is unknown (hint: the accepted spellings for the role's quantity) or measures
/// another quantity than the role's. Generic roles accept any known unit.
core::Unit unit_for_role(const RoleSpec& role, std::string_view spelling,
                         const core::InputLocation& where);

}  // namespace dynpos::io
