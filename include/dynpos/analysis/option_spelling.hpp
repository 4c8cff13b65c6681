#pragma once
/// \file
/// Request keys (analysis/options.hpp) as each front end spells them: the command line's options
/// and the Python API's keyword arguments. The library names a bad option by its key only.

#include <string>

#include "dynpos/core/error.hpp"

namespace dynpos::analysis {

/// "min_step" → "--min-step", "col:output" → "--col output=COLUMN", "unit:u" → "--unit u=UNIT",
/// "from/to" → "--from/--to".
std::string option_spelling(const std::string& key);

/// The same keys as the Python API's keyword arguments: "min_step" → "min_step=", "from/to" →
/// "from_=/to=", "col:output" → "col={'output': COLUMN}".
std::string keyword_spelling(const std::string& key);

/// The error's message with its option key in the command line's spelling; what() for an error
/// in a file.
std::string cli_message(const core::InputError& e);

/// The error's message with its option key as a Python keyword argument; what() for an error
/// in a file.
std::string python_message(const core::InputError& e);

}  // namespace dynpos::analysis
