#pragma once
/// \file
/// The one error type for bad user input (files, options, column maps).
///
/// Our own bugs are asserts; anything a user can get wrong throws InputError, which carries
/// where the problem is (file, line, column or channel) and how to fix it. The CLI catches it at
/// the top, prints what(), and exits non-zero.
///
/// The convention for parameters: the validate() of a struct that users fill (vessel and
/// scenario files, command-line options) throws InputError with column_name the key as the
/// file spells it, "section.key" (core/param_range.hpp: check_ranges), and the reader that
/// knows the file adds it. A precondition that only our own code can break (a figure without
/// panels, a log written with rows of the wrong length, simulator options built by code) throws
/// std::invalid_argument, a std::logic_error: our bug, not the user's.

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace dynpos::core {

/// Where in the user's input a problem was found. Every field is optional.
struct InputLocation {
  std::string file;                   ///< path as the user gave it
  std::optional<std::size_t> line;    ///< 1-based line number in the file
  std::optional<std::size_t> column;  ///< 1-based column (field) number
  std::string column_name;            ///< header name of the column, or channel/role name
};

/// Bad user input: the message says what is wrong, where, and (in `hint`) how to fix it.
class InputError : public std::runtime_error {
 public:
  InputError(InputLocation where, std::string what, std::string hint = {});

  /// A bad option of a request, named by its request key, e.g. "min_step" or "col:output"
  /// (analysis/options.hpp): each front end shows the key in its own spelling ("--min-step" on
  /// the command line). what() shows it as "(key): problem; hint". `file`, when not empty, names
  /// the input the option was checked against (e.g. a time window outside the log): what() shows
  /// "file (key): problem; hint".
  static InputError for_option(std::string key, std::string what, std::string hint = {},
                               std::string file = {});

  const InputLocation& where() const noexcept { return where_; }
  const std::string& problem() const noexcept { return problem_; }
  const std::string& hint() const noexcept { return hint_; }
  /// The request key of a bad option; empty for an error in a file.
  const std::string& option() const noexcept { return option_; }

 private:
  InputLocation where_;
  std::string problem_;
  std::string hint_;
  std::string option_;
};

/// The most bytes of each part of a message (file, name, problem, hint) what() shows: an
/// offending cell or header of megabytes is not echoed whole.
inline constexpr std::size_t kMaxMessagePartBytes = 1000;

/// `text` safe for a terminal: controls (C0, DEL: \t, \n, \r, \xNN; C1: \u0080…\u009f) and bytes
/// not of well-formed UTF-8 (\xNN) shown, not sent; cut after max_bytes (at a UTF-8 character
/// boundary) with "… (N more bytes)". core/printable_text.hpp: the same for a whole report.
std::string printable(std::string_view text, std::size_t max_bytes = kMaxMessagePartBytes);

/// "file:line:column (name): problem; hint" — the text InputError::what() returns, each part
/// printable().
std::string format_input_error(const InputLocation& where, const std::string& problem,
                               const std::string& hint);

}  // namespace dynpos::core
