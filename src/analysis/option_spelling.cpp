#include "dynpos/analysis/option_spelling.hpp"

#include <algorithm>

namespace dynpos::analysis {
namespace {

std::string one_option(std::string key) {
  if (key.rfind("col:", 0) == 0) return "--col " + key.substr(4) + "=COLUMN";
  if (key.rfind("unit:", 0) == 0) return "--unit " + key.substr(5) + "=UNIT";
  std::replace(key.begin(), key.end(), '_', '-');
  return "--" + key;
}

// A Python keyword that is a reserved word takes a trailing underscore (from_, lambda_).
std::string one_keyword(const std::string& key) {
  if (key.rfind("col:", 0) == 0) return "col={'" + key.substr(4) + "': COLUMN}";
  if (key.rfind("unit:", 0) == 0) return "unit={'" + key.substr(5) + "': UNIT}";
  static const char* const reserved[] = {"from", "lambda", "in", "is", "global", "with"};
  for (const char* word : reserved) {
    if (key == word) return key + "_=";
  }
  return key + "=";
}

// Each key of "a/b" spelled by `one`, joined by '/'.
template <class One>
std::string spelled(const std::string& key, One one) {
  std::string out;
  std::size_t begin = 0;
  while (true) {
    const std::size_t slash = key.find('/', begin);
    out += one(key.substr(begin, slash - begin));
    if (slash == std::string::npos) return out;
    out += '/';
    begin = slash + 1;
  }
}

std::string message_with(const core::InputError& e, const std::string& spelling) {
  core::InputLocation where = e.where();
  where.column_name = spelling;
  return core::format_input_error(where, e.problem(), e.hint());
}

}  // namespace

std::string option_spelling(const std::string& key) { return spelled(key, one_option); }

std::string keyword_spelling(const std::string& key) { return spelled(key, one_keyword); }

std::string cli_message(const core::InputError& e) {
  if (e.option().empty()) return e.what();
  return message_with(e, option_spelling(e.option()));
}

std::string python_message(const core::InputError& e) {
  if (e.option().empty()) return e.what();
  return message_with(e, keyword_spelling(e.option()));
}

}  // namespace dynpos::analysis
