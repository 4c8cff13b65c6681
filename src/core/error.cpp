#include "dynpos/core/error.hpp"

#include <cstdio>
#include <string_view>

#include "dynpos/core/printable_text.hpp"

namespace dynpos::core {

namespace {

// The length of the well-formed UTF-8 character at text[i] (2 to 4 bytes; RFC 3629: no
// overlong form, no surrogate, nothing above U+10FFFF), or 0 when the bytes there are not one.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) {
    return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u;
  };
  const unsigned c = byte(0);
  const auto cont = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) {
    return byte(k) >= lo && byte(k) <= hi;
  };
  if (c >= 0xC2 && c <= 0xDF) return cont(1) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    const unsigned lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    return cont(1, lo, hi) && cont(2) ? 3 : 0;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    const unsigned lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    return cont(1, lo, hi) && cont(2) && cont(3) ? 4 : 0;
  }
  return 0;
}

// The first `keep` bytes of `text` with every control character (C0, DEL, C1) and every byte
// that is not part of well-formed UTF-8 escaped; line ends and tabs too unless `keep_lines`.
std::string escape(std::string_view text, std::size_t keep, bool keep_lines) {
  std::string out;
  out.reserve(keep + 16);
  char code[12];
  for (std::size_t i = 0; i < keep;) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      const std::size_t n = utf8_length(text.substr(0, keep), i);
      const auto next = n == 2 ? static_cast<unsigned char>(text[i + 1]) : 0u;
      if (n == 0) {
        std::snprintf(code, sizeof code, "\\x%02x", c);
        out += code;
        ++i;
        continue;
      }
      if (n == 2 && c == 0xC2 && next <= 0x9F) {  // U+0080 … U+009F: C1 controls
        std::snprintf(code, sizeof code, "\\u%04x", next);
        out += code;
      } else {
        out.append(text, i, n);
      }
      i += n;
      continue;
    }
    if (c >= 0x20 && c != 0x7F) {
      out += static_cast<char>(c);
    } else if (keep_lines && (c == '\t' || c == '\n')) {
      out += static_cast<char>(c);
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      std::snprintf(code, sizeof code, "\\x%02x", c);
      out += code;
    }
    ++i;
  }
  return out;
}

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::size_t keep = text.size();
  if (keep > max_bytes) {
    keep = max_bytes;
    // Never cut a UTF-8 character: back off over its continuation bytes (top bits 10).
    while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;
  }
  std::string out = escape(text, keep, false);
  if (keep < text.size()) out += "… (" + std::to_string(text.size() - keep) + " more bytes)";
  return out;
}

std::string printable_text(std::string_view text) { return escape(text, text.size(), true); }

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
