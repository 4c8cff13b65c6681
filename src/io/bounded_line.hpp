#pragma once
// Reading a text file line by line with a bound on the line (private to the io module): a file
// without line ends (a binary file, /dev/zero) must end in a clear error, not in a buffer that
// grows with the file.

#include <cstddef>
#include <istream>
#include <string>

namespace dynpos::io::detail {

/// What read_bounded_line() found.
enum class LineStatus {
  kLine,     ///< a line, ended by '\n' or by the end of the file
  kEnd,      ///< the end of the file: nothing more to read
  kTooLong,  ///< more than max_bytes before the line end; `out` holds the first max_bytes
};

/// The next line of `in` into `out`, without its '\n' (a '\r' before it is kept), reading at
/// most max_bytes + 4 KiB of it. `ended` tells whether its '\n' was read (on kTooLong too: the
/// rest of the line is then read already). Sets in's eofbit at the end of the file.
LineStatus read_bounded_line(std::istream& in, std::string& out, std::size_t max_bytes,
                             bool& ended);

/// Reads on to the end of the current line (after a kTooLong that did not end it); false if
/// more than about max_bytes come before it.
bool skip_rest_of_line(std::istream& in, std::size_t max_bytes);

/// After a kTooLong line of a capture: reads on to its end (unless `ended`, when it was read).
/// Throws core::InputError at file:line when more than about max_bytes come without a line end
/// ("not a text capture").
void skip_overlong_line(std::istream& in, bool ended, std::size_t max_bytes,
                        const std::string& file, std::size_t line);

}  // namespace dynpos::io::detail
