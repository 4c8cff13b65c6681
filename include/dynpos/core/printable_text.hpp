#pragma once
/// \file
/// A report for the terminal: the user's text in it (names, labels, keys, paths) shown, never
/// sent as a control sequence.

#include <string>
#include <string_view>

namespace dynpos::core {

/// `text` as core::printable() shows it (C0, DEL and C1 controls and bytes that are not
/// well-formed UTF-8 escaped), except that line ends (\n) and tabs are kept and nothing is cut.
std::string printable_text(std::string_view text);

}  // namespace dynpos::core
