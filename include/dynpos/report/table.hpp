#pragma once
/// \file
/// A table of text cells rendered as aligned plain text, Markdown or an HTML fragment: the
/// thesis-style tables of the analyses, on stdout and in the report. Missing values are given
/// as "—" by the caller; cells are shown as they are (HTML-escaped in HTML).

#include <cstddef>
#include <string>
#include <vector>

namespace dynpos::report {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  ///< each as long as the header
  /// Columns from this index on are right-aligned in text (numbers); earlier ones left.
  std::size_t first_numeric_column = 1;

  /// Throws std::invalid_argument if a row's length differs from the header's.
  void validate() const;
};

/// The widest cell of a text table [code points]; a longer cell is cut, its last shown character
/// "…", so that one long text (a path, a status) does not widen every row of a large table.
inline constexpr std::size_t kMaxTextCellWidth = 120;

/// Columns padded to their widest cell (counted in UTF-8 code points, at most
/// kMaxTextCellWidth), two spaces apart.
std::string render_text(const Table& table);
/// A GitHub-flavoured Markdown table; '|' in a cell is escaped.
std::string render_markdown(const Table& table);
/// A <table> element with <thead> and <tbody>.
std::string render_html(const Table& table);

}  // namespace dynpos::report
