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

}  // namespace

std::string option_spelling(const std::string& key) {
  std::string out;
  std::size_t begin = 0;
  while (true) {
    const std::size_t slash = key.find('/', begin);
    out += one_option(key.substr(begin, slash - begin));
    if (slash == std::string::npos) return out;
    out += '/';
    begin = slash + 1;
  }
}

std::string cli_message(const core::InputError& e) {
  if (e.option().empty()) return e.what();
  core::InputLocation where = e.where();
  where.column_name = option_spelling(e.option());
  return core::format_input_error(where, e.problem(), e.hint());
}

}  // namespace dynpos::analysis
