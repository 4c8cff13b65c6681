#pragma once
/// \file
/// An option that takes one of a few names (a method, a convention): the lookup both front ends
/// use, so that a bad name reads the same on the command line and in the Python API.

#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "dynpos/analysis/options.hpp"

namespace dynpos::analysis {

/// The value named `text` in `names` (any case), else option_error(key): "unknown KEY 'TEXT'",
/// hint "choose one of A, B, …" (an empty name, a value given by omitting the option, is not
/// listed).
template <typename Enum>
Enum enum_by_name(const std::vector<std::pair<std::string, Enum>>& names, const std::string& text,
                  const std::string& key) {
  const auto lower = [](std::string v) {
    for (char& c : v) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return v;
  };
  std::string known;
  for (const auto& [name, value] : names) {
    if (lower(name) == lower(text)) return value;
    if (!name.empty()) known += (known.empty() ? "" : ", ") + name;
  }
  throw option_error(key, "unknown " + key + " '" + text + "'", "choose one of " + known);
}

}  // namespace dynpos::analysis
