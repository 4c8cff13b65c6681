#pragma once
/// \file
/// Side-by-side comparison of two results of the same analysis (two campaigns, before and after
/// a retrofit, August vs November): every numeric figure of A and B with B − A and (B − A)/|A|.
///
/// The comparison works on the JSON documents the analyses write, so a new analysis compares
/// without new code: numeric leaves are flattened by path, and the items of arrays are paired by
/// a natural key (legs, arms and thrusters by "name", agility directions by "direction_deg" and
/// "case", step tests by the nearest "t_step", anything else by position). Missing figures
/// (JSON null, or a figure on one side only) stay missing.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/report/table.hpp"

namespace dynpos::report {

/// The kind of analysis result a document is, from its "analysis" key if present, else from its
/// keys: "step" (steps), "four-corner" (legs), "agility" (directions), "leverarm" (arms),
/// "station-keeping" (position_std_m or windows), "hybrid" (case + variant), else "generic".
std::string result_kind(const nlohmann::json& doc);

struct ComparisonOptions {
  /// Two step tests are the same test if their step times differ by at most this [s]; the
  /// default tolerates the jitter of step detection on two trials of the same programme.
  double t_step_match_s = 5.0;
  /// Keys whose string values are compared too (shown when they differ), besides numbers.
  std::vector<std::string> text_keys = {"status", "method", "output_unit", "unit"};
};

/// One figure of the comparison. `a`/`b` are empty when missing (null or absent).
struct ComparisonRow {
  std::string figure;  ///< path, e.g. "steps[t_step=20].T" or "legs[name=fwd].thrust_kNs.port"
  std::optional<double> a, b;
  std::string a_text, b_text;  ///< for text figures (status, method ...); numbers stay empty
  bool text = false;

  /// B − A when both are numbers.
  std::optional<double> difference() const;
  /// (B − A)/|A| in % when both are numbers and A ≠ 0.
  std::optional<double> relative_difference_pct() const;
};

struct ComparisonResult {
  std::string kind;  ///< the common kind of both documents
  std::vector<ComparisonRow> rows;
  std::size_t only_in_a = 0, only_in_b = 0;  ///< figures present on one side only
};

/// Compares two documents. Throws std::invalid_argument naming both kinds if they differ.
ComparisonResult compare_results(const nlohmann::json& a, const nlohmann::json& b,
                                 const ComparisonOptions& options = {});

/// Parses a JSON file; core::InputError with the file, line and column of a syntax error.
nlohmann::json load_json_file(const std::filesystem::path& path);

/// The table: figure | label A | label B | B − A | (B − A)/|A| [%]; missing cells are "—".
Table comparison_table(const ComparisonResult& result, const std::string& label_a,
                       const std::string& label_b);

/// The comparison as JSON: kind, labels, and one object per row (nulls where missing).
nlohmann::json comparison_json(const ComparisonResult& result, const std::string& label_a,
                               const std::string& label_b);

/// 1-based line and column of byte offset `byte` (as nlohmann's parse_error gives it) in `text`.
std::pair<std::size_t, std::size_t> line_column_of(const std::string& text, std::size_t byte);

}  // namespace dynpos::report
