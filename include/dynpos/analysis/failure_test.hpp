#pragma once
/// \file
/// Thruster failure tests from a log (DP annual trials, IMCA M 190; FMEA proving trials): each
/// trip found in the units' feedback, with the excursion of the control origin, the heading
/// excursion, the recovery and the redistribution of thrust, as a request → report analysis.
/// The rules are in ident/failure_test.hpp.

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/ident/failure_test.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {

/// The options of the analysis; request keys in parentheses (analysis/options.hpp).
struct FailureTestRequest {
  /// time; north, east [m, any offset] or lat, lon; heading; per unit thrust.NAME or rpm.NAME.
  LogSource source;
  /// Lever arm (x forward, y starboard, z down; BODY) [m] of the antenna whose position is
  /// logged; the position is moved to the control origin (arm), with the logged roll and pitch
  /// when both are mapped (a z other than 0 needs them). Absent: the logged position is the
  /// control origin's.
  std::optional<Eigen::Vector3d> arm_m;
  /// Each unit's shaft speed even where its thrust is logged (rpm).
  bool use_rpm = false;
  /// Analyse from / up to this log time [s] (from, to): only these rows are read.
  std::optional<double> t_from_s;
  std::optional<double> t_to_s;
  double pre_window_s = 60.0;             ///< pre-failure mean and footprint (pre_window)
  double redistribution_window_s = 30.0;  ///< before/after means (redistribution_window)
  double hold_s = 10.0;                   ///< back within the footprint this long (hold)
  double response_window_s = 300.0;       ///< peak and recovery searched (response_window)
  double max_fall_s = 5.0;                ///< a trip reaches near zero within (max_fall)
  double min_off_s = 20.0;                ///< a tripped unit stays near zero (min_off)

  /// The detection options, checked: option_error naming the key of the first bad one.
  ident::FailureTestOptions options() const;
  /// Throws option_error naming the key of the first bad field.
  void validate() const;
};

/// A unit as analysed: the channel of its feedback and the unit it is reported in.
struct FailureTestUnit {
  std::string name;
  std::string channel;  ///< "thrust.NAME" or "rpm.NAME"
  std::string unit;     ///< "kN" or "rpm"
  double per_si = 1.0;  ///< reported value per SI value (N or rps)
};

/// The events of a log, with what the outputs need to show them.
struct FailureTestReport {
  std::filesystem::path log;  ///< the log as given
  io::InputReport input;      ///< the files read, their formats and skipped lines
  std::optional<Eigen::Vector3d> arm_m;
  std::string position;  ///< the roles of the position: "north/east" or "lat/lon"
  bool has_heading = false;
  bool attitude = false;               ///< the arm was applied with the logged roll and pitch
  std::vector<FailureTestUnit> units;  ///< in the log's order, as result.units
  std::vector<std::string> notes;      ///< channels left out, and why
  ident::FailureTestOptions options;
  ident::FailureTestResult result;
};

/// Validates the request, reads the log and finds the trips. core::InputError naming the log
/// when it holds no unit feedback (thrust.NAME or rpm.NAME with a valid sample) or no position,
/// or when --arm is given without a heading; a log without a trip gives no event.
FailureTestReport run_failure_test(const FailureTestRequest& request);

/// The document `identify failure-test --json` writes: analysis, log, input, the channels and
/// windows used, and "events".
nlohmann::json to_json(const FailureTestReport& report);

/// One row per event: unit(s), time, peak excursion, time to peak, recovery, peak heading.
report::Table failure_test_table(const FailureTestReport& report);

/// What `identify failure-test` prints: the log and its units, the events' table and each
/// event's redistribution.
std::string to_text(const FailureTestReport& report);

/// Writes the outputs of `identify failure-test`: the JSON (it draws no figure).
Written write_outputs(const FailureTestReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
