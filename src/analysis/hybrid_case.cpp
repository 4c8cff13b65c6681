#include "dynpos/analysis/hybrid_case.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/angle.hpp"

namespace dynpos::analysis {
namespace {

// Applies the common settings to the timing; option_error on a bad value.
void apply_timing(const HybridCaseRequest& request, hybrid::CaseTiming& timing) {
  if (request.dwell_s) timing.dwell_time_s = *request.dwell_s;
  if (request.sample_period_s) timing.sample_period_s = *request.sample_period_s;
  if (request.noise_power) timing.noise_power = *request.noise_power;
  if (request.end_time_s) {
    // 1 h at the 1 ms step is 3.6 M steps and a trace of 360 k rows: more is not a case study.
    if (!std::isfinite(*request.end_time_s) || *request.end_time_s > 3600.0) {
      throw option_error("end_time",
                         fmt::format("{} s is not a run length up to 3600 s", *request.end_time_s),
                         "the case studies last 60 s; give at most 3600");
    }
    timing.end_time_s = *request.end_time_s;
  }
  timing.seed = request.seed;
  try {
    timing.validate();
  } catch (const std::invalid_argument& e) {
    // The library names its fields ("CaseTiming: end_time …"); the message names the option.
    std::string what = e.what();
    if (what.rfind("CaseTiming: ", 0) == 0) what.erase(0, 12);
    const auto field_is = [&what](std::string_view field) { return what.rfind(field, 0) == 0; };
    const char* key = field_is("end_time")        ? "end_time"
                      : field_is("dwell_time")    ? "dwell"
                      : field_is("sample_period") ? "sample_period"
                      : field_is("noise_power")   ? "noise_power"
                                                  : "dwell/sample_period/noise_power/end_time";
    throw option_error(key, what, "times must be multiples of the 1 ms step");
  }
}

// The case's own checks (hybrid/case_study.hpp) as an option error under `key`: with the
// timing and the theorem's conditions already checked, what is left is a step outside the run.
template <typename CaseOptions>
void check_case_options(const CaseOptions& o, const char* key) {
  try {
    o.validate();
  } catch (const std::invalid_argument& e) {
    const std::string text = e.what();
    const std::size_t colon = text.find(": ");
    throw option_error(key, colon == std::string::npos ? text : text.substr(colon + 2),
                       "give a longer --end-time");
  }
}

hybrid::JumpSet hybrid_jump_set(const HybridCaseRequest& request) {
  return request.sampled ? hybrid::JumpSet::kSampled : hybrid::JumpSet::kIdeal;
}

// The first-order case as the request sets it up, Theorem 6 checked.
FirstOrderStudy first_order_study(const HybridCaseRequest& request) {
  if (request.heading_deg) {
    throw option_error("heading", "only the dp case has a heading", "drop --heading");
  }
  FirstOrderStudy s;
  hybrid::FirstOrderCaseOptions& o = s.options;
  apply_timing(request, o.timing);
  if (request.lambda) o.params.lambda = *request.lambda;
  if (request.ki) o.params.ki = *request.ki;
  if (request.solve_p) {
    const auto P = hybrid::solve_lyapunov(o.params.A(), Eigen::Matrix2d::Identity());
    if (!P) throw option_error("solve_p", "the Lyapunov equation has no unique solution");
    o.params.P = *P;
  }
  o.params.jump_set = hybrid_jump_set(request);
  s.check = o.params.check();
  if (!s.check.ok()) {
    throw option_error(request.ki ? "ki" : "lambda",
                       "the conditions of Theorem 6 fail: " + s.check.reason,
                       request.solve_p ? "" : "try --solve-p to compute P from A^T P + PA = -I");
  }
  check_case_options(o, "end_time");  // the disturbance steps must fall within the run
  return s;
}

// The DP case as the request sets it up, Theorem 7 checked.
DpStudy dp_study(const HybridCaseRequest& request) {
  if (request.ki || request.solve_p) {
    throw option_error(request.ki ? "ki" : "solve_p", "only the first-order case has this option",
                       "the dp case uses the gains of thesis section 5.3.2");
  }
  DpStudy s;
  hybrid::DpCaseOptions& o = s.options;
  apply_timing(request, o.timing);
  if (request.lambda) o.params.lambda = *request.lambda;
  if (request.heading_deg) {
    // The range of every heading of a scenario file: a turn of either sign, no more (400° is
    // more likely a typing error than 40°).
    if (!(std::abs(*request.heading_deg) <= 360.0)) {
      throw option_error(
          "heading",
          fmt::format("the set-point heading must be within ±360°, got {:g}", *request.heading_deg),
          "give it in degrees, e.g. --heading 40");
    }
    o.params.eta_d.z() = core::wrap_pi(core::deg_to_rad(*request.heading_deg));
  }
  o.params.jump_set = hybrid_jump_set(request);
  s.check = o.params.check();
  if (!s.check.ok()) {
    throw option_error("lambda", "the conditions of Theorem 7 fail: " + s.check.reason);
  }
  check_case_options(o, "end_time");  // the bias steps must fall within the run
  return s;
}

std::variant<FirstOrderStudy, DpStudy> study_of(const HybridCaseRequest& request) {
  if (request.no_jumps && request.sampled) {
    throw option_error("sampled",
                       "--sampled chooses the jump set of the hybrid run, and "
                       "--no-jumps runs no hybrid run",
                       "drop one of them");
  }
  if (request.study_case == HybridCase::kDp) return dp_study(request);
  return first_order_study(request);
}

// Runs the conventional design and (unless no_jumps) the hybrid one with the options' jump set.
template <typename CaseOptions, typename RunCase>
void run_both(HybridCaseReport& report, CaseOptions o, bool no_jumps, RunCase run_case) {
  const hybrid::JumpSet jump_set = o.params.jump_set;
  o.params.jump_set = hybrid::JumpSet::kNone;
  report.conventional = run_case(o);
  if (!no_jumps) {
    o.params.jump_set = jump_set;
    report.hybrid = run_case(o);
  }
}

}  // namespace

std::string to_string(HybridCase study_case) {
  return study_case == HybridCase::kDp ? "dp" : "first-order";
}

HybridCase hybrid_case_from_string(const std::string& name) {
  for (const HybridCase c : {HybridCase::kFirstOrder, HybridCase::kDp}) {
    if (name == to_string(c)) return c;
  }
  throw option_error("case", "unknown case '" + name + "'", "choose one of first-order, dp");
}

void HybridCaseRequest::validate() const { (void)study_of(*this); }

HybridCaseReport run_hybrid_case(const HybridCaseRequest& request) {
  HybridCaseReport report;
  report.study = study_of(request);
  report.study_case = request.study_case;
  report.jump_set = hybrid_jump_set(request);
  report.seed = request.seed;
  if (const auto* fo = std::get_if<FirstOrderStudy>(&report.study)) {
    run_both(report, fo->options, request.no_jumps, hybrid::run_first_order_case);
  } else {
    run_both(report, std::get<DpStudy>(report.study).options, request.no_jumps,
             hybrid::run_dp_case);
  }
  return report;
}

void check_hybrid_case_outputs(const std::filesystem::path& out_dir, const std::string& json) {
  check_output_dir("out", out_dir);
  if (json.empty() || json == "-") return;
  const std::filesystem::path parent = std::filesystem::path(json).parent_path();
  const bool in_out_dir =
      !out_dir.empty() && parent.lexically_normal() == out_dir.lexically_normal();
  if (!in_out_dir) check_output_file("json", json);  // a folder that --out makes is fine
}

}  // namespace dynpos::analysis
