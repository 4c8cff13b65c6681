#include "dynpos/io/json_writer.hpp"

#include <cmath>
#include <iostream>
#include <stdexcept>

#include "dynpos/io/atomic_file.hpp"

namespace dynpos::io {

std::string json_text(const nlohmann::json& doc) { return doc.dump(2) + "\n"; }

void write_json(const std::filesystem::path& path, const nlohmann::json& doc) {
  const std::string text = json_text(doc);
  if (path == "-") {
    std::cout << text << std::flush;
    if (!std::cout) throw std::runtime_error("writing JSON to stdout failed");
    return;
  }
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

nlohmann::json json_number(double value) {
  if (!std::isfinite(value)) return nullptr;
  return value;
}

nlohmann::json json_number(const std::optional<double>& value) {
  return value ? json_number(*value) : nlohmann::json(nullptr);
}

nlohmann::json json_numbers(std::span<const double> values) {
  nlohmann::json out = nlohmann::json::array();
  for (const double value : values) out.push_back(json_number(value));
  return out;
}

}  // namespace dynpos::io
