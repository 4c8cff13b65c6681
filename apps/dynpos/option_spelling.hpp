#pragma once
// Library request keys (analysis/options.hpp) as the command line spells them.

#include <string>

#include "dynpos/core/error.hpp"

namespace dynpos::cli {

/// "min_step" → "--min-step", "col:output" → "--col output=COLUMN", "from/to" → "--from/--to".
std::string option_spelling(const std::string& key);

/// The error's message with its option key in the command line's spelling.
std::string cli_message(const core::InputError& e);

}  // namespace dynpos::cli
