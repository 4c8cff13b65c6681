#include "dynpos/report/table.hpp"

#include <algorithm>
#include <stdexcept>

#include "dynpos/io/markup.hpp"

namespace dynpos::report {
namespace {

std::size_t display_width(const std::string& s) {
  // Code points: every byte that is not a UTF-8 continuation byte.
  return static_cast<std::size_t>(
      std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

// `s` cut to kMaxTextCellWidth code points, the last one "…", when it is longer.
std::string shown_cell(const std::string& s) {
  if (display_width(s) <= kMaxTextCellWidth) return s;
  std::size_t points = 0, end = 0;
  for (; end < s.size(); ++end) {
    if ((s[end] & 0xC0) != 0x80 && ++points == kMaxTextCellWidth) break;
  }
  return s.substr(0, end) + "…";
}

std::string escape_markdown(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

void Table::validate() const {
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].size() != header.size()) {
      throw std::invalid_argument("table row " + std::to_string(r + 1) + " has " +
                                  std::to_string(rows[r].size()) + " cells, the header " +
                                  std::to_string(header.size()));
    }
  }
}

std::string render_text(const Table& t) {
  t.validate();
  std::vector<std::size_t> width(t.header.size(), 0);
  for (std::size_t c = 0; c < t.header.size(); ++c)
    width[c] = display_width(shown_cell(t.header[c]));
  for (const auto& row : t.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      width[c] = std::max(width[c], std::min(display_width(row[c]), kMaxTextCellWidth));
    }
  }
  std::string out;
  auto line = [&](const std::vector<std::string>& cells) {
    std::string text;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string cell = shown_cell(cells[c]);
      const std::string pad(width[c] - display_width(cell), ' ');
      if (c > 0) text += "  ";
      if (c >= t.first_numeric_column) text += pad;
      text += cell;
      if (c < t.first_numeric_column) text += pad;
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    out += text;
    out += '\n';
  };
  line(t.header);
  for (const auto& row : t.rows) line(row);
  return out;
}

std::string render_markdown(const Table& t) {
  t.validate();
  std::string out = "|";
  for (const auto& h : t.header) {
    out += ' ';
    out += escape_markdown(h);
    out += " |";
  }
  out += "\n|";
  for (std::size_t c = 0; c < t.header.size(); ++c) {
    out += c >= t.first_numeric_column ? "---:|" : "---|";
  }
  out += "\n";
  for (const auto& row : t.rows) {
    out += "|";
    for (const auto& cell : row) {
      out += ' ';
      out += escape_markdown(cell);
      out += " |";
    }
    out += "\n";
  }
  return out;
}

std::string render_html(const Table& t) {
  t.validate();
  std::string out = "<table>\n<thead><tr>";
  for (const auto& h : t.header) {
    out += "<th>";
    out += io::escape_markup(h);
    out += "</th>";
  }
  out += "</tr></thead>\n<tbody>\n";
  for (const auto& row : t.rows) {
    out += "<tr>";
    for (std::size_t c = 0; c < row.size(); ++c) {
      out += c >= t.first_numeric_column ? "<td style=\"text-align:right\">" : "<td>";
      out += io::escape_markup(row[c]);
      out += "</td>";
    }
    out += "</tr>\n";
  }
  out += "</tbody>\n</table>\n";
  return out;
}

}  // namespace dynpos::report
