#include "leverarm_ins.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <sstream>

#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/calib/imu_mru_arms.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis::detail {
namespace {

using Vec3 = Eigen::Vector3d;

nlohmann::json vec_json(const Vec3& v) {
  return nlohmann::json::array(
      {io::json_number(v(0)), io::json_number(v(1)), io::json_number(v(2))});
}

nlohmann::json arm_json(const calib::ArmEstimate& a, const char* kind) {
  nlohmann::json d = nlohmann::json::array();
  for (const calib::Determinacy x : a.determinacy)
    d.push_back(std::string(calib::determinacy_name(x)));
  return {{"name", a.name},
          {"kind", kind},
          {"x", io::json_number(a.l_b_m(0))},
          {"y", io::json_number(a.l_b_m(1))},
          {"z", io::json_number(a.l_b_m(2))},
          {"std", vec_json(a.std_m)},
          {"determined", d}};
}

}  // namespace

bool has_ins_inputs(const core::Log& log) {
  return !calib::imu_names(log).empty() && log.has("heading");
}

void validate_ins_options(const LeverarmGnssRequest& q) {
  if (!q.imu.empty() && (q.imu.rfind("mru", 0) != 0 || q.imu.size() < 4 ||
                         !std::all_of(q.imu.begin() + 3, q.imu.end(), ::isdigit)))
    throw option_error("imu", "'" + q.imu + "' is not an MRU role prefix",
                       "MRUs are named mruK, e.g. mru1");
  if (q.imu_arm && !q.imu_arm->allFinite())
    throw option_error("imu_arm", "the arm must be three finite numbers X,Y,Z [m]",
                       "for example 0.358,0.804,-4.321");
}

LeverarmInsResult run_ins(const LeverarmGnssRequest& q, const core::Log& log,
                          const std::vector<calib::GnssSeries>& gnss) {
  const std::vector<std::string> imus = calib::imu_names(log);
  LeverarmInsResult out;
  out.imu = q.imu.empty() ? (imus.empty() ? "mru1" : imus.front()) : q.imu;
  calib::ImuSeries imu;
  try {
    imu = calib::imu_from_log(log, out.imu, q.accel);
  } catch (const core::InputError& e) {
    throw q.source.in_log(e);
  }
  calib::InsArmOptions o;
  o.imu_arm_b_m = q.imu_arm;
  o.estimate_time_offset = !q.time_offset.has_value();
  o.time_offset_s = q.time_offset.value_or(0.0);
  o.max_time_offset_s = q.max_time_offset;
  o.gnss_horizontal_std_m = q.gnss_std;
  o.gnss_vertical_std_m = 2.0 * q.gnss_std;
  out.gnss = calib::estimate_ins_arms(imu, gnss, o);
  if (out.gnss.status != core::Status::kOk)
    throw q.source.error("time", out.gnss.message,
                         "log the GNSS fixes and the MRU over the same maneuver");
  out.gnss.notes.insert(out.gnss.notes.begin(), imu.notes.begin(), imu.notes.end());
  for (const std::string& m : calib::mru_accel_names(log))
    if (m != out.imu) out.mru_names.push_back(m);
  if (!out.mru_names.empty()) {
    try {
      out.mrus = calib::estimate_mru_arms_from_imu(imu, log, out.mru_names, 2.0);
    } catch (const core::InputError& e) {
      throw q.source.in_log(e);
    }
    const Vec3 offset = o.imu_arm_b_m.value_or(Vec3::Zero());
    for (calib::ArmEstimate& a : out.mrus.arms) a.l_b_m += offset;
  }
  return out;
}

nlohmann::json ins_json(const LeverarmInsResult& r) {
  const calib::InsArmResult& g = r.gnss;
  nlohmann::json j;
  j["method"] = "ins";
  j["reference"] = g.reference;
  j["imu"] = r.imu;
  j["arms"] = nlohmann::json::array();
  for (const calib::ArmEstimate& a : g.arms) j["arms"].push_back(arm_json(a, "gnss"));
  for (const calib::ArmEstimate& a : r.mrus.arms) j["arms"].push_back(arm_json(a, "mru"));
  j["arms_frame"] = "BODY (x forward, y starboard, z down) from the reference [m]";
  j["time_offset_s"] = g.time_offset_s;
  j["time_offset_estimated"] = g.time_offset_estimated;
  j["time_offset_std_s"] = io::json_number(g.time_offset_std_s);
  j["accel_bias_mps2"] = vec_json(g.accel_bias_b_mps2);
  j["accel_bias_std_mps2"] = vec_json(g.accel_bias_std_mps2);
  j["gyro_euler_rate_bias_rps"] = vec_json(g.euler_rate_bias_rps);
  nlohmann::json noise = {{"accel_std_mps2", vec_json(g.noise.accel_std_mps2)},
                          {"process_scale", g.noise.process_scale},
                          {"gnss", nlohmann::json::array()}};
  for (std::size_t k = 0; k < g.arms.size(); ++k)
    noise["gnss"].push_back({{"name", g.arms[k].name},
                             {"horizontal_std_m", g.noise.gnss_horizontal_std_m[k]},
                             {"vertical_std_m", g.noise.gnss_vertical_std_m[k]},
                             {"residual_rms_m", vec_json(g.residual_rms_n_m[k])}});
  j["noise"] = noise;
  j["knots"] = g.knots;
  j["fixes"] = g.fixes;
  j["advice"] = g.advice;
  j["notes"] = g.notes;
  return j;
}

std::string ins_text(const LeverarmInsResult& r) {
  const calib::InsArmResult& g = r.gnss;
  std::string out = fmt::format(
      "GNSS lever arms from the logger alone (GNSS/INS fusion, {}), {} antenna(s), {} fixes, "
      "arms from {}\n",
      r.imu, g.arms.size(), g.fixes, g.reference == "co" ? "CO" : "the MRU " + g.reference);
  report::Table t;
  t.header = {"sensor", "x [m]", "σx [m]", "y [m]", "σy [m]", "z [m]", "σz [m]", "determined"};
  auto row = [&t](const calib::ArmEstimate& a) {
    std::vector<std::string> cells = {a.name};
    for (int i = 0; i < 3; ++i) {
      const bool shown = a.determinacy[i] != calib::Determinacy::kNot;
      cells.push_back(shown ? number_cell(a.l_b_m(i), "{:.4f}") : "—");
      cells.push_back(number_cell(a.std_m(i), "{:.4f}"));
    }
    cells.push_back(fmt::format("{}/{}/{}", calib::determinacy_name(a.determinacy[0]),
                                calib::determinacy_name(a.determinacy[1]),
                                calib::determinacy_name(a.determinacy[2])));
    t.rows.push_back(std::move(cells));
  };
  for (const auto& a : g.arms) row(a);
  for (const auto& a : r.mrus.arms) row(a);
  out += report::render_text(t);
  if (g.time_offset_estimated)
    out += fmt::format("GNSS time offset: {:.4f} s (±{:.4f} s), estimated\n", g.time_offset_s,
                       g.time_offset_std_s);
  else
    out += fmt::format("GNSS time offset: {:.4f} s (given)\n", g.time_offset_s);
  out += fmt::format("accelerometer bias: {:.2e} {:.2e} {:.2e} m/s² (±{:.1e})\n",
                     g.accel_bias_b_mps2(0), g.accel_bias_b_mps2(1), g.accel_bias_b_mps2(2),
                     g.accel_bias_std_mps2.maxCoeff());
  for (std::size_t k = 0; k < g.arms.size(); ++k)
    out += fmt::format("{} noise: {:.4f} m horizontal, {:.4f} m vertical\n", g.arms[k].name,
                       g.noise.gnss_horizontal_std_m[k], g.noise.gnss_vertical_std_m[k]);
  for (const std::string& a : g.advice) out += fmt::format("  advice: {}\n", a);
  for (const std::string& n : g.notes) out += fmt::format("note: {}\n", n);
  return out;
}

std::vector<std::filesystem::path> write_ins_figures(const LeverarmInsResult& r,
                                                     const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  report::Figure f;
  f.title = "Fix residuals, GNSS/INS fusion";
  const char* axes[3] = {"north", "east", "down"};
  for (int i = 0; i < 3; ++i) {
    report::Panel p;
    p.title = axes[i];
    p.x_axis = {"Time", "s", {}, {}};
    p.y_axis = {"residual", "m", {}, {}};
    for (std::size_t k = 0; k < r.gnss.arms.size(); ++k) {
      report::Series s;
      s.label = r.gnss.arms[k].name;
      s.x = r.gnss.residual_t_s[k];
      for (const Vec3& e : r.gnss.residual_n_m[k]) s.y.push_back(e(i));
      p.series.push_back(std::move(s));
    }
    f.panels.push_back(std::move(p));
  }
  const std::filesystem::path out = dir / "residuals.svg";
  report::write_svg(out, f);
  return {out};
}

}  // namespace dynpos::analysis::detail
