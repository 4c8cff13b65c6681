#pragma once
/// \file
/// How a request names a bad option: by its request key, one convention for every front end.
///
/// Requests are validated once, here in the library. A bad value throws core::InputError whose
/// location carries the request key (InputError::option()): the field name in snake_case
/// ("min_step", "method"), "col:ROLE" for a missing column mapping ("col:output"), and several
/// keys joined by '/' ("from/to"). The CLI shows a key as its option ("--min-step",
/// "--col output=COLUMN", "--from/--to"), the Python API as its keyword argument.

#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "dynpos/core/error.hpp"

namespace dynpos::analysis {

/// An InputError about the option `key` (see the file comment for the spelling).
core::InputError option_error(const std::string& key, const std::string& problem,
                              const std::string& hint = {});

/// An InputError about the option `key` whose value does not fit the input file `file` (e.g. a
/// time window outside the log): the file, then the key as option_error() names it.
core::InputError option_error_in_file(const std::filesystem::path& file, const std::string& key,
                                      const std::string& problem, const std::string& hint = {});

/// The text "X,Y,Z" as three finite numbers; else option_error(key), the hint showing the
/// option with `example`.
Eigen::Vector3d parse_vec3(const std::string& text, const std::string& key,
                           const std::string& example);

/// Throws option_error(key) if the output folder `dir` exists and is not a folder (it is created
/// when needed) or takes no new file (read-only, /proc: a file is made there and removed); "" ok.
void check_output_dir(const std::string& key, const std::filesystem::path& dir);

/// Throws option_error(key) if the folder of the output file `path` is missing or takes no new
/// file, or the target is refused (io::check_output_target). "" and "-" (stdout) are fine.
void check_output_file(const std::string& key, const std::string& path);

}  // namespace dynpos::analysis
