#include "dynpos/analysis/outputs.hpp"

#include "dynpos/analysis/options.hpp"
#include "dynpos/io/json_writer.hpp"

namespace dynpos::analysis {

void Outputs::check(const std::string& figures_key, bool figures_are_a_folder) const {
  check_output_file("json", json);
  if (figures.empty()) return;
  if (figures_are_a_folder) {
    check_output_dir(figures_key, figures);
  } else {
    check_output_file(figures_key, figures.string());
  }
}

void write_json_output(const Outputs& outputs, const nlohmann::json& doc, Written& written) {
  if (outputs.json.empty()) return;
  io::write_json(outputs.json, doc);
  if (outputs.json != "-") written.emplace_back(outputs.json);
}

}  // namespace dynpos::analysis
