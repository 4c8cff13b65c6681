#include "dynpos/io/text_file.hpp"

#include <array>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::io {

std::string read_capped(std::istream& in, const std::filesystem::path& path,
                        std::uint64_t max_bytes, const std::string& hint) {
  const std::string name = path.string();
  const auto too_large = [&](const std::string& how) {
    throw core::InputError({name, {}, {}, {}},
                           fmt::format("more than {} MiB{}", max_bytes >> 20, how), hint);
  };
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_bytes) too_large(fmt::format(" ({} bytes)", size));
  }
  std::string text;
  std::array<char, 1 << 16> chunk;
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    // A file that grew since its size was taken is read to the cap as well.
    if (text.size() + got > max_bytes) too_large(" read without an end");
    text.append(chunk.data(), got);
  }
  if (in.bad()) {
    throw core::InputError({name, {}, {}, {}}, "reading the file failed",
                           "check that the file is readable");
  }
  return text;
}

}  // namespace dynpos::io
