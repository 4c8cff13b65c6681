#pragma once
// The log options every analysis subcommand shares: LOG, --map, --col, --unit, --clock-offset,
// --max-gap, --format, --strict and the time-stamp options, filling an analysis::LogSource.

#include <CLI/CLI.hpp>
#include <string>

#include "commands.hpp"
#include "dynpos/analysis/log_source.hpp"

namespace dynpos::cli {

/// Adds LOG (positional, required; not in live mode, where the stream is the log), --map, --col
/// (roles_help lists the roles), --unit, --clock-offset, --max-gap, --format, --strict and the
/// time-stamp options to `sub`, filling `source`.
void add_log_options(CLI::App& sub, analysis::LogSource& source, const std::string& roles_help,
                     LogMode mode = LogMode::kFile);
/// The options of add_log_options but LOG, for a command that reads several logs alike.
void add_log_source_options(CLI::App& sub, analysis::LogSource& source,
                            const std::string& roles_help);

}  // namespace dynpos::cli
