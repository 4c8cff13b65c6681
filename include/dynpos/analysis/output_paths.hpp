#pragma once
/// \file
/// The outputs of one command checked together before anything runs: every output folder and
/// file can be made (analysis/options.hpp), and no output file is one of the command's inputs.

#include <string>
#include <vector>

namespace dynpos::analysis {

/// A path a command names, with the option that names it.
struct NamedPath {
  std::string role;  ///< an output's request key ("json"); an input as given ("--map", "log")
  std::string path;
};

/// Every path of one command.
struct CommandPaths {
  std::vector<NamedPath> output_files;    ///< a file each, or "-" (standard output)
  std::vector<NamedPath> output_folders;  ///< created when needed
  std::vector<NamedPath> inputs;          ///< files and folders read
};

/// The files an input option's value may name: the value itself, FILE of ROLE=COLUMN@FILE and
/// FILE of FILE=SECONDS.
std::vector<std::string> paths_in(const std::string& value);

/// Throws option_error(role) for the first output that cannot be written: an output folder
/// that is a file or takes no new file (check_output_dir), an output file whose folder is
/// missing or takes no new file (check_output_file; a file in an output folder not made yet
/// is not checked), or an output file that is an input (a regular file of the same device and
/// inode), naming both.
void check_command_paths(const CommandPaths& paths);

}  // namespace dynpos::analysis
