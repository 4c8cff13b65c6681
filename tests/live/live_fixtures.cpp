#include "live_fixtures.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace dynpos::live::test {
namespace {

// A deterministic noise in [-1, 1] (a linear congruential generator).
class Noise {
 public:
  double next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state_ >> 11) / static_cast<double>(1ULL << 53) * 2.0 - 1.0;
  }

 private:
  std::uint64_t state_ = 42;
};

std::string checksum_hex(const std::string& text) {
  unsigned sum = 0;
  for (const char c : text) sum ^= static_cast<unsigned char>(c);
  return fmt::format("{:02X}", sum);
}

}  // namespace

std::vector<std::string> step_csv(double duration_s) {
  constexpr double kGain = 2.0, kTau_s = 3.0, kDelay_s = 0.5, kDt_s = 0.1;
  constexpr double kLevels[] = {0.0, 1.0, 3.0, 2.0};
  const auto command = [&](double t) {
    std::size_t k = 0;
    while (k < 3 && t >= kStepTimes[k]) ++k;
    return kLevels[k];
  };
  // The exact response to the piecewise constant command: a sum of delayed first-order steps.
  const auto response = [&](double t) {
    double y = kGain * kLevels[0];
    for (std::size_t k = 0; k < 3; ++k) {
      const double since = t - kStepTimes[k] - kDelay_s;
      if (since > 0) y += kGain * (kLevels[k + 1] - kLevels[k]) * (1.0 - std::exp(-since / kTau_s));
    }
    return y;
  };
  std::vector<std::string> lines{"time [s],cmd [1],y [1]\n"};
  Noise noise;
  const auto rows = static_cast<int>(std::lround(duration_s / kDt_s));
  for (int i = 0; i <= rows; ++i) {
    const double t = i * kDt_s;
    lines.push_back(
        fmt::format("{:.1f},{},{:.6f}\n", t, command(t), response(t) + 0.002 * noise.next()));
  }
  return lines;
}

std::string nmea_sentence(const std::string& body) {
  return "$" + body + "*" + checksum_hex(body) + "\r\n";
}

std::string tag_block(long unix_s, bool corrupt) {
  const std::string text = fmt::format("s:GP0001,c:{}", unix_s);
  std::string sum = checksum_hex(text);
  if (corrupt) sum = sum == "00" ? "01" : "00";
  return "\\" + text + "*" + sum + "\\";
}

std::vector<std::string> station_capture(int seconds) {
  std::vector<std::string> lines;
  Noise noise;
  for (int s = 0; s < seconds; ++s) {
    const int tod = 10 * 3600 + s;
    const std::string hms = fmt::format("{:02}{:02}{:02}.00", tod / 3600, tod / 60 % 60, tod % 60);
    // About 63°25' N, 10°23' E; 1e-5' of latitude is about 1.9 cm.
    const double lat_min =
        25.0 + 0.0003 * std::sin(2 * std::numbers::pi * s / 37.0) + 0.00002 * noise.next();
    const double lon_min = 23.0 + 0.0004 * std::cos(2 * std::numbers::pi * s / 53.0);
    lines.push_back(nmea_sentence(
        fmt::format("GPGGA,{},63{:08.5f},N,010{:08.5f},E,4,12,0.8,12.30,M,40.10,M,1.0,0001", hms,
                    lat_min, lon_min)));
    lines.push_back(nmea_sentence(fmt::format("HEHDT,{:.2f},T", 90.0 + 2.0 * std::sin(s / 11.0))));
  }
  return lines;
}

TempDir::TempDir() {
  std::string name = (std::filesystem::temp_directory_path() / "dynpos-live-test-XXXXXX").string();
  if (::mkdtemp(name.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  path_ = name;
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

void write_lines(const std::filesystem::path& file, const std::vector<std::string>& lines) {
  std::ofstream out(file, std::ios::binary);
  for (const std::string& line : lines) out << line;
}

std::vector<std::string> read_back(std::FILE* file) {
  std::fflush(file);
  std::rewind(file);
  std::vector<std::string> lines;
  std::string line;
  for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) {
    if (c == '\n') {
      lines.push_back(line);
      line.clear();
    } else {
      line.push_back(static_cast<char>(c));
    }
  }
  EXPECT_TRUE(line.empty()) << "a JSON line without its line end: " << line;
  return lines;
}

LiveLine split_live_line(const std::string& line) {
  LiveLine out;
  const std::string key = ",\"stream_time_s\":";
  const std::size_t at = line.rfind(key);
  EXPECT_NE(at, std::string::npos) << line;
  if (at == std::string::npos) return out;
  out.document = line.substr(0, at) + "}";
  const nlohmann::json added = nlohmann::json::parse("{" + line.substr(at + 1));
  EXPECT_EQ(added.size(), 2u) << line.substr(at);
  if (!added.at("stream_time_s").is_null()) out.stream_time_s = added.at("stream_time_s");
  out.final = added.at("final").get<bool>();
  return out;
}

}  // namespace dynpos::live::test
