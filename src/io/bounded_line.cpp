#include "bounded_line.hpp"

#include <array>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::io::detail {

LineStatus read_bounded_line(std::istream& in, std::string& out, std::size_t max_bytes,
                             bool& ended) {
  out.clear();
  ended = false;
  std::array<char, 4096> chunk;
  const auto size = static_cast<std::streamsize>(chunk.size());
  bool any = false;
  for (;;) {
    // Stops at a '\n' (taken, counted in gcount), at the end of the file, or with the chunk full
    // (failbit, the line goes on).
    in.getline(chunk.data(), size);
    const auto got = static_cast<std::size_t>(in.gcount());
    const bool full = in.fail() && !in.eof() && !in.bad() && got == chunk.size() - 1;
    const bool line_end = !in.fail() && !in.eof();
    const std::size_t text = line_end ? got - 1 : got;
    if (out.size() + text > max_bytes) {
      out.append(chunk.data(), max_bytes - out.size());
      in.clear(in.rdstate() & ~std::ios::failbit);
      ended = line_end;  // the rest of the chunk, its line end too, is read
      return LineStatus::kTooLong;
    }
    out.append(chunk.data(), text);
    any = any || got > 0;
    if (full) {
      in.clear(in.rdstate() & ~std::ios::failbit);
      continue;
    }
    ended = line_end;
    if (in.fail() && !in.bad()) in.clear(in.rdstate() & ~std::ios::failbit);
    return any ? LineStatus::kLine : LineStatus::kEnd;
  }
}

bool skip_rest_of_line(std::istream& in, std::size_t max_bytes) {
  std::array<char, 4096> chunk;
  const auto size = static_cast<std::streamsize>(chunk.size());
  for (std::size_t skipped = 0;;) {
    in.getline(chunk.data(), size);
    skipped += static_cast<std::size_t>(in.gcount());
    const bool full = in.fail() && !in.eof() && !in.bad() && in.gcount() == size - 1;
    if (!in.bad()) in.clear(in.rdstate() & ~std::ios::failbit);
    if (!full) return true;  // the line end, or the end of the file
    if (skipped > max_bytes) return false;
  }
}

void skip_overlong_line(std::istream& in, bool ended, std::size_t max_bytes,
                        const std::string& file, std::size_t line) {
  if (ended || skip_rest_of_line(in, max_bytes)) return;
  throw core::InputError(
      {file, line, {}, {}},
      fmt::format("no line end within {} MiB: not a text capture", max_bytes >> 20),
      "give a capture of NMEA sentences, one a line");
}

}  // namespace dynpos::io::detail
