#pragma once
// Reading checked values out of toml++ tables, with errors that name file, line and key.

#include <toml++/toml.h>

#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "dynpos/core/error.hpp"
#include "dynpos/core/param_range.hpp"

namespace dynpos::scenario::detail {

/// A TOML table together with the file it came from and its dotted path, for messages.
class TomlTable {
 public:
  TomlTable(const toml::table& table, std::string file, std::string path)
      : table_(&table), file_(std::move(file)), path_(std::move(path)) {}

  /// Parses a whole TOML document. Throws core::InputError with line and column on syntax errors.
  static toml::table parse_file(const std::string& file);

  const toml::table& raw() const { return *table_; }
  const std::string& file() const { return file_; }
  bool has(std::string_view key) const { return table_->contains(key); }

  /// The location of a key (or of the table itself when the key is absent).
  core::InputLocation where(std::string_view key) const;

  /// A required number in [lo, hi]; integers are accepted.
  double number(std::string_view key, double lo, double hi) const;
  /// A required number within `range` (its key, bounds and open or closed ends), in the
  /// key's unit.
  double number(const core::ParamRange& range) const;
  /// An optional number within `range` with a default.
  double number_or(double fallback, const core::ParamRange& range) const;
  /// An optional number in [lo, hi] with a default.
  double number_or(std::string_view key, double fallback, double lo, double hi) const;
  std::string string(std::string_view key) const;
  std::string string_or(std::string_view key, std::string fallback) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  /// A sub-table; throws if absent or not a table.
  TomlTable table(std::string_view key) const;
  std::optional<TomlTable> optional_table(std::string_view key) const;

  /// Throws core::InputError for any key not in `known` (catches misspelt keys).
  void reject_unknown(const std::set<std::string, std::less<>>& known) const;

 private:
  std::string key_path(std::string_view key) const;

  const toml::table* table_;
  std::string file_;
  std::string path_;
};

}  // namespace dynpos::scenario::detail
