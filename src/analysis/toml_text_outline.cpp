// The tables and keys of a TOML text by line (toml_text_outline.hpp).

#include "toml_text_outline.hpp"

#include <algorithm>
#include <cctype>

namespace dynpos::analysis::toml_text {
namespace {

bool is_bare(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

bool all_bare(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), is_bare);
}

std::string trim(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// What a value leaves open at the end of a line: brackets and a multi-line string.
struct Open {
  int depth = 0;        // [ and { not yet closed
  char multi_line = 0;  // '"' or '\'' inside a multi-line string
  bool any() const { return depth > 0 || multi_line != 0; }
};

// Scans `s` from `i` for what the value opens and closes (strings and comments skipped).
void scan(const std::string& s, std::size_t i, Open& open) {
  while (i < s.size()) {
    if (open.multi_line != 0) {
      const std::string close(3, open.multi_line);
      std::size_t j = i;
      for (; j < s.size(); ++j) {
        if (open.multi_line == '"' && s[j] == '\\') {
          ++j;
          continue;
        }
        if (s.compare(j, 3, close) == 0) break;
      }
      if (j >= s.size()) return;
      open.multi_line = 0;
      i = j + 3;
      continue;
    }
    const char c = s[i];
    if (c == '#') return;
    if (c == '"' || c == '\'') {
      if (s.compare(i, 3, std::string(3, c)) == 0) {
        open.multi_line = c;
        i += 3;
        continue;
      }
      std::size_t j = i + 1;
      while (j < s.size() && s[j] != c) j += (c == '"' && s[j] == '\\') ? 2 : 1;
      i = j + 1;
      continue;
    }
    if (c == '[' || c == '{') ++open.depth;
    if (c == ']' || c == '}') --open.depth;
    ++i;
  }
}

// A one-line string value ("…" with the usual escapes, or '…'); nullopt for another value.
std::optional<std::string> string_value(const std::string& value) {
  if (value.empty() || (value[0] != '"' && value[0] != '\'')) return std::nullopt;
  const char quote = value[0];
  std::string out;
  for (std::size_t i = 1; i < value.size(); ++i) {
    const char c = value[i];
    if (c == quote) return out;
    if (quote == '"' && c == '\\' && i + 1 < value.size()) {
      const char e = value[++i];
      out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
      continue;
    }
    out += c;
  }
  return std::nullopt;
}

// A header line "[name]" or "[[name]]" (a comment may follow): the table it opens.
std::optional<TableLines> header(const std::string& line, std::size_t at) {
  const std::string s = trim(line);
  if (s.empty() || s[0] != '[') return std::nullopt;
  TableLines t;
  t.array = s.compare(0, 2, "[[") == 0;
  const std::size_t begin = t.array ? 2 : 1;
  const std::size_t end = s.find(t.array ? "]]" : "]", begin);
  if (end == std::string::npos) return std::nullopt;
  const std::string name = trim(s.substr(begin, end - begin));
  t.name = all_bare(name) ? name : std::string();
  t.header = at;
  return t;
}

}  // namespace

std::vector<TableLines> outline(const std::vector<std::string>& lines) {
  std::vector<TableLines> tables(1);
  Open open;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (open.any()) {  // a value's continuation
      scan(line, 0, open);
      if (!tables.back().keys.empty()) tables.back().keys.back().last = i;
      continue;
    }
    const std::size_t begin = line.find_first_not_of(" \t");
    if (begin == std::string::npos || line[begin] == '#') continue;
    if (auto t = header(line, i)) {
      tables.push_back(std::move(*t));
      continue;
    }
    // key = value: the key bare, or quoted or dotted (kept, not edited).
    std::size_t eq = begin;
    while (eq < line.size() && line[eq] != '=') {
      if (line[eq] == '"' || line[eq] == '\'') {
        const char q = line[eq];
        ++eq;
        while (eq < line.size() && line[eq] != q) eq += (q == '"' && line[eq] == '\\') ? 2 : 1;
      }
      ++eq;
    }
    if (eq >= line.size()) continue;  // not a key line
    const std::string key = trim(line.substr(begin, eq - begin));
    KeyLines k{all_bare(key) ? key : std::string(), line.substr(0, begin), i, i};
    scan(line, eq + 1, open);
    TableLines& table = tables.back();
    if (table.array && k.key == "name") table.element = string_value(trim(line.substr(eq + 1)));
    table.keys.push_back(std::move(k));
  }
  return tables;
}

}  // namespace dynpos::analysis::toml_text
