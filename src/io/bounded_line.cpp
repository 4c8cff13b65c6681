#include "bounded_line.hpp"

#include <array>

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

}  // namespace dynpos::io::detail
