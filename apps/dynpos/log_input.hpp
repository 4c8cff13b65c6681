#pragma once
// The log options every analysis subcommand shares: a CSV log, a column map file, --col and
// --unit overrides; and for logs whose header already uses role names (dynpos' own logs), the
// roles found by name.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/io/column_map.hpp"

namespace dynpos::cli {

struct LogInput {
  std::filesystem::path log;
  std::filesystem::path map_file;
  std::vector<std::string> columns;  ///< ROLE=COLUMN
  std::vector<std::string> units;    ///< ROLE=UNIT

  /// Adds LOG (positional, required), --map, --col and --unit to `sub`.
  void add_options(CLI::App& sub, const std::string& roles_help);

  /// The map from --map, then --col/--unit; `time` defaults to the column "time". Then every
  /// header column whose name is a role accepted by `wanted` and not yet mapped is mapped to
  /// itself (so "thrust.port [kN]" in a dynpos log needs no --col).
  io::ColumnMap column_map(const std::function<bool(const std::string& role)>& wanted) const;

  /// Reads the log with column_map(wanted).
  core::Log read(const std::function<bool(const std::string& role)>& wanted) const;
};

/// Thruster names NAME of the channels "PREFIX.NAME" of a log, in channel order, unique.
std::vector<std::string> thruster_names(const core::Log& log, const std::string& prefix);

/// Throws InputError if the parent folder of a --json FILE does not exist (not for "-").
void check_json_target(const std::string& json);

}  // namespace dynpos::cli
