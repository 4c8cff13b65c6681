#include "dynpos/analysis/leverarm_gnss_text.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <utility>

#include "dynpos/analysis/option_spelling.hpp"
#include "dynpos/analysis/option_text.hpp"
#include "dynpos/analysis/options.hpp"

namespace dynpos::analysis {
namespace {

// The example of an X,Y,Z option in its error's hint (gains, initial arms and P₀ alike).
const char* const kGainExample = "0.02,0.02,20";

// "gnssK=VALUE" → (gnssK, VALUE); option_error(key) naming the example otherwise.
std::pair<std::string, std::string> split_eq(const std::string& text, const std::string& key,
                                             const std::string& example) {
  if (auto pair = split_assignment(text)) return *std::move(pair);
  throw option_error(key, "malformed argument '" + text + "': expected " + example,
                     "for example " + option_spelling(key) + " " + example);
}

std::map<std::string, std::filesystem::path> files_by_antenna(const std::vector<std::string>& specs,
                                                              const std::string& key,
                                                              const std::string& example) {
  std::map<std::string, std::filesystem::path> out;
  for (const std::string& s : specs) {
    auto [antenna, file] = split_eq(s, key, example);
    out[antenna] = file;
  }
  return out;
}

void set_vec3(std::optional<Eigen::Vector3d>& field, const std::string& text, const char* key,
              const char* example) {
  if (!text.empty()) field = parse_vec3(text, key, example);
}

}  // namespace

void parse_text(const LeverarmGnssText& text, LeverarmGnssRequest& q) {
  q.gnss_log = files_by_antenna(text.gnss_log, "gnss_log", "gnss1=FILE.csv");
  if (!text.utc_at_zero.empty()) q.utc_at_zero = parse_utc_at_zero(text.utc_at_zero);
  q.nmea = files_by_antenna(text.nmea, "nmea", "gnss1=FILE.nmea");
  set_vec3(q.w1, text.w1, "w1", kGainExample);
  set_vec3(q.w2, text.w2, "w2", kGainExample);
  set_vec3(q.gamma, text.gamma, "gamma", kGainExample);
  set_vec3(q.L, text.L, "L", kGainExample);
  set_vec3(q.init_p0, text.init_p0, "init_p0", kGainExample);
  for (const std::string& s : text.init) {
    const auto [antenna, arm] = split_eq(s, "init", "gnss1=0.2,-0.6,-13.9");
    q.init[antenna] = parse_vec3(arm, "init", kGainExample);
  }
  set_vec3(q.imu_arm, text.imu_arm, "imu_arm", "0.358,0.804,-4.321");
}

}  // namespace dynpos::analysis
