#pragma once
/// \file
/// Request keys (analysis/options.hpp) as the command line spells them: one spelling for the
/// CLI's messages and the Python API's, so both front ends show the same text.

#include <string>

#include "dynpos/core/error.hpp"

namespace dynpos::analysis {

/// "min_step" → "--min-step", "col:output" → "--col output=COLUMN", "unit:u" → "--unit u=UNIT",
/// "from/to" → "--from/--to".
std::string option_spelling(const std::string& key);

/// The error's message with its option key in the command line's spelling; what() for an error
/// in a file.
std::string cli_message(const core::InputError& e);

}  // namespace dynpos::analysis
