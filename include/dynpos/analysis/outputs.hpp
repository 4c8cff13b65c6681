#pragma once
/// \file
/// Where an analysis writes what it found: the one output path of every front end. The CLI's
/// --json and figure options and the Python API's json= and figure keywords fill an Outputs;
/// each analysis' write_outputs(report, outputs) (its NAME_report.cpp) writes it, for both.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dynpos::analysis {

/// The outputs of one run of an analysis. Empty fields write nothing.
struct Outputs {
  /// The report as JSON (io::write_json): a file, "-" for standard output, or empty.
  std::string json;
  /// The analysis' figures: a folder, created when needed, or an SVG file where the analysis
  /// draws one figure (each analysis' header says which); empty: none.
  std::filesystem::path figures;

  /// Throws option_error for an output that cannot be written, before any work is done: "json"
  /// (check_output_file), and `figures_key` for the figures, checked as a folder or as a file.
  /// The CLI checks every output when the command line is parsed; the Python API calls this.
  void check(const std::string& figures_key, bool figures_are_a_folder) const;
};

/// The files an analysis' write_outputs wrote, in the order written (the JSON last; standard
/// output is not listed).
using Written = std::vector<std::filesystem::path>;

/// Writes `doc` where outputs.json says (nothing when it is empty); a file written is added to
/// `written`.
void write_json_output(const Outputs& outputs, const nlohmann::json& doc, Written& written);

}  // namespace dynpos::analysis
