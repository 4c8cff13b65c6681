#include "dynpos/capability/load_table.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::capability {
namespace {

constexpr std::array<std::string_view, 4> kColumns{"direction_deg", "X_N", "Y_N", "N_Nm"};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

// The fields of a line split at commas, with the 1-based column where each starts.
std::vector<std::pair<std::string_view, std::size_t>> split(std::string_view line) {
  std::vector<std::pair<std::string_view, std::size_t>> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    out.emplace_back(trim(line.substr(start, end - start)), start + 1);
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

}  // namespace

std::vector<LoadCase> read_load_table(const std::string& path) {
  const auto where = [&](std::size_t line, std::size_t column, std::string name = {}) {
    return core::InputLocation{path, line, column, std::move(name)};
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw core::InputError(
        where(0, 0),
        std::filesystem::exists(path, ec) ? "not a regular file" : "cannot open the file",
        "give a CSV file with the columns direction_deg,X_N,Y_N,N_Nm");
  }
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::size_t number = 0;
  std::array<std::size_t, 4> field_of{};  // the field of each column of kColumns
  std::size_t fields = 0;
  std::vector<LoadCase> out;
  while (std::getline(in, line)) {
    ++number;
    if (line.size() > kMaxLoadLineBytes) {
      throw core::InputError(where(number, 0), "a line longer than 64 KiB",
                             "is this a load table? one load a line, four numbers");
    }
    const std::string_view text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const auto cells = split(text);
    if (fields == 0) {  // the header
      fields = cells.size();
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        std::size_t found = fields;
        for (std::size_t f = 0; f < fields; ++f) {
          if (cells[f].first == kColumns[c]) found = f;
        }
        if (found == fields) {
          throw core::InputError(where(number, 0),
                                 fmt::format("the header has no column '{}'", kColumns[c]),
                                 "the first line names the columns: direction_deg,X_N,Y_N,N_Nm");
        }
        field_of[c] = found;
      }
      continue;
    }
    if (cells.size() != fields) {
      throw core::InputError(
          where(number, 0), fmt::format("{} fields where the header has {}", cells.size(), fields));
    }
    if (out.size() == kMaxLoadRows) {
      throw core::InputError(where(number, 0), "more than 100 000 loads", "split the table");
    }
    std::array<double, 4> v{};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      const auto& [cell, column] = cells[field_of[c]];
      const auto [ptr, err] = std::from_chars(cell.data(), cell.data() + cell.size(), v[c]);
      if (cell.empty() || err != std::errc() || ptr != cell.data() + cell.size() ||
          !std::isfinite(v[c])) {
        throw core::InputError(where(number, column, std::string(kColumns[c])),
                               fmt::format("'{}' is not a finite number", cell));
      }
    }
    out.push_back({v[0], {v[1], v[2], v[3]}});
  }
  if (in.bad()) throw core::InputError(where(number + 1, 0), "read error");
  if (out.empty()) {
    throw core::InputError(where(number, 0), "no load in the table",
                           "give a header direction_deg,X_N,Y_N,N_Nm and one load a line");
  }
  return out;
}

}  // namespace dynpos::capability
