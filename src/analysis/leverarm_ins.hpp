#pragma once
// `leverarm gnss --method ins`: the logger-only lever arms (GNSS/INS fusion), its inputs from the
// request and its JSON, text and figure. Private to the analysis module; leverarm_gnss.cpp
// calls it when the method resolves to ins.

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/leverarm_gnss.hpp"

namespace dynpos::analysis::detail {

/// Whether `log` has what ins needs: an MRU with every role and the heading.
bool has_ins_inputs(const core::Log& log);

/// Checks the ins options of `q` (imu, imu_arm), each by its request key.
void validate_ins_options(const LeverarmGnssRequest& q);

/// The estimate from the MRU of `log` and the fixes `gnss`; q.source names the log in errors.
LeverarmInsResult run_ins(const LeverarmGnssRequest& q, const core::Log& log,
                          const std::vector<calib::GnssSeries>& gnss);

nlohmann::json ins_json(const LeverarmInsResult& r);
std::string ins_text(const LeverarmInsResult& r);
/// residuals.svg: each antenna's fix residuals N/E/D over time.
std::vector<std::filesystem::path> write_ins_figures(const LeverarmInsResult& r,
                                                     const std::filesystem::path& dir);

}  // namespace dynpos::analysis::detail
