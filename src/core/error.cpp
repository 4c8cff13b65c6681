#include "dynpos/core/error.hpp"

#include <cstdio>
#include <string_view>

namespace dynpos::core {

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::size_t keep = text.size();
  if (keep > max_bytes) {
    keep = max_bytes;
    // Never cut a UTF-8 character: back off over its continuation bytes (top bits 10).
    while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;
  }
  std::string out;
  out.reserve(keep + 16);
  for (std::size_t i = 0; i < keep; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c != 0x7F) {
      out += static_cast<char>(c);
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      char code[8];
      std::snprintf(code, sizeof code, "\\x%02x", c);
      out += code;
    }
  }
  if (keep < text.size()) out += "… (" + std::to_string(text.size() - keep) + " more bytes)";
  return out;
}

std::string format_input_error(const InputLocation& where, const std::string& problem_text,
                               const std::string& hint_text) {
  const std::string problem = printable(problem_text, kMaxMessagePartBytes);
  const std::string hint = printable(hint_text, kMaxMessagePartBytes);
  std::string out;
  if (!where.file.empty()) {
    out += printable(where.file, kMaxMessagePartBytes);
    if (where.line) {
      out += ':';
      out += std::to_string(*where.line);
    }
    if (where.column) {
      out += ':';
      out += std::to_string(*where.column);
    }
  } else if (where.line) {
    out += "line " + std::to_string(*where.line);
    if (where.column) out += ", column " + std::to_string(*where.column);
  }
  if (!where.column_name.empty()) {
    out += out.empty() ? "" : " ";
    out += "(" + printable(where.column_name, kMaxMessagePartBytes) + ")";
  }
  if (!out.empty()) out += ": ";
  out += problem;
  if (!hint.empty()) out += "; " + hint;
  return out;
}

InputError::InputError(InputLocation where, std::string what, std::string hint)
    : std::runtime_error(format_input_error(where, what, hint)),
      where_(std::move(where)),
      problem_(std::move(what)),
      hint_(std::move(hint)) {}

InputError InputError::for_option(std::string key, std::string what, std::string hint,
                                  std::string file) {
  InputError e({std::move(file), {}, {}, key}, std::move(what), std::move(hint));
  e.option_ = std::move(key);
  return e;
}

}  // namespace dynpos::core
