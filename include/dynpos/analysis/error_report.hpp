#pragma once
/// \file
/// How the command line reports the error that ended a command: its message and whether the
/// user can fix it (exit 2) or it is a failure of the program (exit 1); docs/cli.md.

#include <exception>
#include <string>
#include <vector>

namespace dynpos::analysis {

/// The report of one error.
struct ErrorReport {
  std::string message;  ///< without the program's prefix; control characters escaped
  /// Bad input or options (core::InputError, in the command line's spelling: cli_message), or
  /// what the user can change: a path that cannot be read or written, a thread the system will
  /// not start, memory run out. False: any other error.
  bool input_error = false;
};

/// The report of `error`; `arguments` (the command line after the program's name) are named in
/// the out-of-memory message. Rethrows an error that is not a std::exception.
ErrorReport cli_error_report(const std::exception_ptr& error,
                             const std::vector<std::string>& arguments);

}  // namespace dynpos::analysis
