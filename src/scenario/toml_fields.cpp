#include "toml_fields.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <limits>

#include "dynpos/io/text_file.hpp"

namespace dynpos::scenario::detail {
namespace {

core::InputLocation location_of(const toml::source_region& region, const std::string& file,
                                std::string name) {
  core::InputLocation where;
  where.file = file;
  if (region.begin.line > 0) {
    where.line = region.begin.line;
    where.column = region.begin.column;
  }
  where.column_name = std::move(name);
  return where;
}

}  // namespace

toml::table TomlTable::parse_file(const std::string& file) {
  // A folder (or a device) would read as an empty document: every key its default.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw core::InputError(
        {file, {}, {}, {}},
        std::filesystem::exists(file, ec) ? "not a regular file" : "cannot open the file",
        "give a TOML file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw core::InputError({file, {}, {}, {}}, "cannot open the file", "give a TOML file");
  const std::string text = io::read_capped(in, file, io::kMaxTomlBytes,
                                           "vessel and scenario files are a few kB of TOML");
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    const std::string description(e.description());
    if (e.source().begin.line == 0) {
      throw core::InputError({file, {}, {}, {}}, "cannot read TOML file: " + description);
    }
    throw core::InputError(location_of(e.source(), file, {}), "TOML syntax error: " + description);
  }
}

std::string TomlTable::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

core::InputLocation TomlTable::where(std::string_view key) const {
  if (const toml::node* node = table_->get(key)) {
    return location_of(node->source(), file_, key_path(key));
  }
  return location_of(table_->source(), file_, key_path(key));
}

double TomlTable::number(std::string_view key, double lo, double hi) const {
  return number({std::string(key), "", lo, hi});
}

double TomlTable::number(const core::ParamRange& range) const {
  const std::string& key = range.key;
  const toml::node* node = table_->get(key);
  if (node == nullptr) {
    throw core::InputError(where(key), "missing required key",
                           fmt::format("add '{} = <number>' to [{}]", key, path_));
  }
  std::optional<double> value = node->value<double>();
  if (!value) {
    throw core::InputError(where(key), "expected a number");
  }
  if (!range.contains(*value)) {
    throw core::InputError(where(key), fmt::format("value {} is out of range", *value),
                           "expected a number in " + range.interval());
  }
  return *value;
}

double TomlTable::number_or(double fallback, const core::ParamRange& range) const {
  return has(range.key) ? number(range) : fallback;
}

double TomlTable::number_or(std::string_view key, double fallback, double lo, double hi) const {
  return has(key) ? number(key, lo, hi) : fallback;
}

std::string TomlTable::string(std::string_view key) const {
  const toml::node* node = table_->get(key);
  if (node == nullptr) {
    throw core::InputError(where(key), "missing required key",
                           fmt::format("add '{} = \"...\"' to [{}]", key, path_));
  }
  std::optional<std::string> value = node->value<std::string>();
  if (!value) throw core::InputError(where(key), "expected a string");
  return *value;
}

std::string TomlTable::string_or(std::string_view key, std::string fallback) const {
  return has(key) ? string(key) : fallback;
}

bool TomlTable::boolean_or(std::string_view key, bool fallback) const {
  const toml::node* node = table_->get(key);
  if (node == nullptr) return fallback;
  std::optional<bool> value = node->value_exact<bool>();
  if (!value) throw core::InputError(where(key), "expected true or false");
  return *value;
}

TomlTable TomlTable::table(std::string_view key) const {
  std::optional<TomlTable> sub = optional_table(key);
  if (!sub) {
    throw core::InputError(where(key), "missing required table",
                           fmt::format("add a [{}] table", key_path(key)));
  }
  return *sub;
}

std::optional<TomlTable> TomlTable::optional_table(std::string_view key) const {
  const toml::node* node = table_->get(key);
  if (node == nullptr) return std::nullopt;
  const toml::table* sub = node->as_table();
  if (sub == nullptr) throw core::InputError(where(key), "expected a table");
  return TomlTable(*sub, file_, key_path(key));
}

void TomlTable::reject_unknown(const std::set<std::string, std::less<>>& known) const {
  for (const auto& [key, node] : *table_) {
    if (known.count(key.str()) == 0) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw core::InputError(location_of(node.source(), file_, key_path(key.str())), "unknown key",
                             "known keys here: " + list);
    }
  }
}

}  // namespace dynpos::scenario::detail
