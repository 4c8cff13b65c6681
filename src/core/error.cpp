#include "dynpos/core/error.hpp"

namespace dynpos::core {

std::string format_input_error(const InputLocation& where, const std::string& problem,
                               const std::string& hint) {
  std::string out;
  if (!where.file.empty()) {
    out += where.file;
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
    out += "(" + where.column_name + ")";
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
