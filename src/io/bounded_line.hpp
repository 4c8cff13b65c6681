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

}  // namespace dynpos::io::detail
