#pragma once
// The tables and keys of a TOML text by line, for replacing values in place (private to the
// module): each table's header line, each key's lines (a value may span several: an array, a
// multi-line string) and, for the tables of an array of tables, the element's `name`.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace dynpos::analysis::toml_text {

/// One `key = value` of a table: lines [first, last] (0-based) of the text.
struct KeyLines {
  std::string key;     ///< the bare key; empty for a quoted or dotted one (not edited)
  std::string indent;  ///< the spaces before it
  std::size_t first = 0, last = 0;
};

/// One table: the root (no header), a [table] or an element of an [[array]].
struct TableLines {
  std::string name;                    ///< "hull"; empty for the root, a quoted or a dotted name
  bool array = false;                  ///< an element of [[name]]
  std::optional<std::size_t> header;   ///< its header line; nullopt for the root
  std::optional<std::string> element;  ///< an array's element: its `name = "…"` value
  std::vector<KeyLines> keys;
};

/// The tables of `lines` in their order, the root first. A text that is not TOML gives some
/// outline; the caller checks the result by reading it.
std::vector<TableLines> outline(const std::vector<std::string>& lines);

}  // namespace dynpos::analysis::toml_text
