#include "dynpos/analysis/leverarm_mru_text.hpp"

#include "dynpos/analysis/option_text.hpp"
#include "dynpos/analysis/options.hpp"

namespace dynpos::analysis {

std::map<std::string, std::filesystem::path> parse_mru_logs(const std::vector<std::string>& specs) {
  std::map<std::string, std::filesystem::path> out;
  for (const std::string& spec : specs) {
    const auto pair = split_assignment(spec);
    if (!pair) {
      throw option_error("mru_log", "malformed argument '" + spec + "'",
                         "expected NAME=FILE, e.g. --mru-log mru1=mru1.csv");
    }
    out[pair->first] = pair->second;
  }
  return out;
}

}  // namespace dynpos::analysis
