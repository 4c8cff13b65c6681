#pragma once
/// \file
/// The case studies of thesis section 5.3 (`dynpos hybrid first-order|dp`): the conventional
/// integral action and the hybrid one (jumps of the integral state) on the same disturbance
/// steps, with the stability conditions (Theorem 6 or 7) checked first.
///
/// Request keys (option_error): the field name without its unit suffix ("dwell" for dwell_s,
/// "heading" for heading_deg); "case" for study_case.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/outputs.hpp"
#include "dynpos/hybrid/case_study.hpp"
#include "dynpos/hybrid/stability_check.hpp"

namespace dynpos::analysis {

/// The case studies of thesis section 5.3.
enum class HybridCase {
  kFirstOrder,  ///< "first-order": a first-order system (5.3.1)
  kDp,          ///< "dp": a DP vessel, backstepping (5.3.2)
};

/// "first-order" or "dp".
std::string to_string(HybridCase study_case);

/// The case named `name` ("first-order", "dp"); option_error("case") for another name.
HybridCase hybrid_case_from_string(const std::string& name);

/// One run of a case study: which case, which designs, and the settings that differ from the
/// thesis. An absent value keeps the thesis' (hybrid::FirstOrderCaseOptions, DpCaseOptions).
struct HybridCaseRequest {
  HybridCase study_case = HybridCase::kFirstOrder;  ///< the case study (case)
  bool no_jumps = false;   ///< run only the conventional (continuous) integral action
  bool sampled = false;    ///< hybrid run with the practical (sampled) jump set, not the ideal one
  std::uint64_t seed = 1;  ///< master seed of the derivative noise (sampled)
  std::optional<double> lambda;           ///< jump gain λ, > 0 ((5.76) or (5.88))
  std::optional<double> dwell_s;          ///< least time between jumps [s], ≥ 0
  std::optional<double> sample_period_s;  ///< derivative sampling period T_s [s], > 0
  std::optional<double> noise_power;      ///< derivative noise power, ≥ 0
  std::optional<double> end_time_s;       ///< run length [s], > 0
  std::optional<double> heading_deg;      ///< set-point heading [deg]; dp only
  std::optional<double> ki;               ///< integral gain k_i [1/s²]; first-order only
  bool solve_p = false;  ///< first-order only: P from AᵀP + PA = −I instead of (5.75)

  /// Throws option_error naming the bad option: an unknown case, an option of the other case,
  /// no_jumps with sampled, times off the 1 ms grid, or violated conditions of Theorem 6 / 7.
  void validate() const;
};

/// The first-order case (5.68)–(5.80) as run, with its Theorem 6 check.
struct FirstOrderStudy {
  hybrid::FirstOrderCaseOptions options;
  hybrid::FirstOrderCheck check;
};

/// The DP case (5.81)–(5.92) as run, with its Theorem 7 check.
struct DpStudy {
  hybrid::DpCaseOptions options;
  hybrid::DpCheck check;
};

/// Both designs of one case study.
struct HybridCaseReport {
  HybridCase study_case = HybridCase::kFirstOrder;
  hybrid::JumpSet jump_set = hybrid::JumpSet::kIdeal;  ///< of the hybrid run
  std::uint64_t seed = 1;
  std::variant<FirstOrderStudy, DpStudy> study;  ///< options (jump set aside) and the check
  std::optional<hybrid::CaseResult> hybrid;      ///< absent with no_jumps
  hybrid::CaseResult conventional;
};

/// Validates, then runs the conventional design and (unless no_jumps) the hybrid one.
HybridCaseReport run_hybrid_case(const HybridCaseRequest& request);

/// Throws option_error if `out_dir` exists and is not a folder ("out"), or if the folder of the
/// JSON file `json` does not exist and is not `out_dir` ("json"; "" and "-" are fine). The
/// Python API's check of the outputs of `hybrid` and `hybrid vessel` (the CLI's is
/// check_outputs).
void check_hybrid_case_outputs(const std::filesystem::path& out_dir, const std::string& json);

/// The `--json` document: case, jump_set, seed, parameters, stability, both runs in full under
/// "hybrid" and "conventional", the primary run's (hybrid, else conventional) figures at the top
/// level, and `plots`.
nlohmann::json to_json(const HybridCaseReport& report,
                       const std::vector<std::filesystem::path>& plots = {});

/// The table: the stability check, then the figures of both runs side by side.
std::string to_text(const HybridCaseReport& report);

/// Writes the SVG plots like thesis figs. 5.1–5.12 into `dir` (created if needed):
/// <prefix>_states/_lyapunov.svg (first order) or _position/_velocity/_integral/_lyapunov.svg
/// (dp), prefix the case name with "-sampled" or "-conventional". Returns the paths.
std::vector<std::filesystem::path> write_figures(const HybridCaseReport& report,
                                                 const std::filesystem::path& dir);

/// The plots into outputs.figures (a folder, write_figures), then the JSON listing them.
Written write_outputs(const HybridCaseReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
