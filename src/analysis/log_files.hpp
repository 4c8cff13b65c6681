#pragma once
// Adding the further files of a log to its main log (private to the module).

#include <cstdint>
#include <optional>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/io/log_file.hpp"

namespace dynpos::analysis {

/// Reads every file of map.other_files() (io::read_log_file as `how` says) and
/// puts its roles on out.log's time axis: by the difference of the absolute origins when the
/// main log (main_origin_ns) and the file both have one, plus the file's clock offset; the file
/// and its roles are added to out.input. Errors as read_log_files.
void add_log_files(LoadedLog& out, std::optional<std::int64_t> main_origin_ns,
                   const io::ColumnMap& map, const core::ResampleOptions& options,
                   const io::LogFileRead& how);

}  // namespace dynpos::analysis
