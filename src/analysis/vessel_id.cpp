// identify vessel and compare-trial: the output-error fit of the vessel file's hull model to
// logged tests, its σ, determinability and cross-validation (vessel_id.hpp).

#include "dynpos/analysis/vessel_id.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <utility>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/text_file.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "vessel_fit.hpp"
#include "vessel_test_series.hpp"
#include "vessel_units.hpp"

namespace dynpos::analysis {
namespace {

using vessel_fit::FitParameter;
using vessel_fit::FitTest;
using vessel_fit::HullFit;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// A value of the vessel file the fit may free, and the excitation that determines it.
struct Candidate {
  const char* key;
  bool log_scale;
  const char* excitation;
};

const std::vector<Candidate>& hull_candidates() {
  static const std::vector<Candidate> c{
      {"hull.x_udot_kg", true, "surge accelerations: surge thrust steps from rest"},
      {"hull.x_u_Ns_m", true, "slow steady surge speeds: small surge thrust steps (5-15 %)"},
      {"hull.x_uu_Ns2_m2", true, "fast steady surge speeds: surge thrust steps to 40-80 %"},
      {"hull.y_vdot_kg", true, "sway accelerations: sway thrust steps from rest"},
      {"hull.y_v_Ns_m", true, "slow steady sway speeds: sway thrust steps of 25-50 %"},
      {"hull.y_vv_Ns2_m2", true, "fast steady sway speeds: sway thrust steps to 100 %"},
      {"hull.y_uv_Ns2_m2", true,
       "sway while making way: zig-zags or turning circles at two speeds"},
      {"hull.y_ur_Ns2", false,
       "yaw rate while making way: zig-zags or turning circles at two speeds"},
      {"hull.n_uv_Ns2", false, "sway while making way: zig-zags or turning circles at two speeds"},
      {"hull.y_rdot_kgm", false, "sway and yaw accelerations together: rudder reversals (zig-zag)"},
      {"hull.n_rdot_kgm2", true, "yaw accelerations: rudder or yaw-moment steps"},
      {"hull.n_r_Nms", true, "slow steady turns at low speed: yaw-moment steps at rest"},
      {"hull.n_ur_Nms2", true, "steady turns at two or more speeds: rudder steps at 3 and 6 kn"},
      {"hull.n_rr_Nms2", true, "fast turns: large rudder steps or a turning circle"},
  };
  return c;
}

const std::vector<Candidate>& wind_candidates() {
  static const std::vector<Candidate> c{
      {"wind.cx", true, "wind of 10 m/s or more ahead or astern (station-keeping in wind)"},
      {"wind.cy", true, "wind of 10 m/s or more on the beam (station-keeping in wind)"},
      {"wind.cn", true, "wind of 10 m/s or more from the bow quarters (station-keeping in wind)"},
  };
  return c;
}

// The values kept whatever the data: the motion gives only the sums m + added mass.
const std::vector<std::pair<const char*, const char*>>& kept_values() {
  static const std::vector<std::pair<const char*, const char*>> k{
      {"hull.mass_kg",
       "the motion gives only m + added mass: take the mass from the loading condition"},
      {"hull.iz_kgm2",
       "the motion gives only I_z + added inertia: take it from the loading condition"},
      {"hull.xg_m", "the motion gives only m·x_g + Y_r-dot: take it from the loading condition"},
  };
  return k;
}

std::string unit_of(scenario::VesselConfig& v, const std::string& key, double* to_si) {
  for (core::ParamSection& section : scenario::vessel_param_sections(v)) {
    for (core::ParamField& f : section.fields) {
      if (section.name + "." + f.range.key == key) {
        *to_si = f.range.to_si;
        return f.range.unit;
      }
    }
  }
  *to_si = 1.0;
  return {};
}

struct Setup {
  scenario::VesselConfig start;
  std::vector<FitParameter> params;
  std::vector<std::string> excitation;  // per parameter
  std::vector<VesselParameter> kept;    // never freed, with why
};

Setup setup(const scenario::VesselConfig& start, bool wind) {
  Setup s{start, {}, {}, {}};
  std::vector<Candidate> all = hull_candidates();
  if (wind) all.insert(all.end(), wind_candidates().begin(), wind_candidates().end());
  for (const Candidate& c : all) {
    const double value = *vessel_fit::field(s.start, c.key);
    if (value == 0.0) {
      double to_si = 1.0;
      const std::string unit = unit_of(s.start, c.key, &to_si);
      s.kept.push_back({c.key, unit, 0.0, 0.0, kNan, false, false,
                        std::string("the starting value is 0; to determine it: ") + c.excitation});
      continue;
    }
    s.params.push_back({c.key, value, c.log_scale});
    s.excitation.emplace_back(c.excitation);
  }
  for (const auto& [key, why] : kept_values()) {
    double to_si = 1.0;
    const std::string unit = unit_of(s.start, key, &to_si);
    const double v = *vessel_fit::field(s.start, key) / to_si;
    s.kept.push_back({key, unit, v, v, kNan, false, false, why});
  }
  return s;
}

// σ/|p| of each parameter from σ of θ.
double rel_sigma(const FitParameter& p, double theta, double sigma_theta) {
  if (!std::isfinite(sigma_theta)) return std::numeric_limits<double>::infinity();
  return std::abs(p.slope(theta) * sigma_theta / p.value(theta));
}

// The parameters the tests determine: from `free`, the worst determined one dropped until every
// one left has σ/|p| ≤ max_rel (σ of θ from JᵀJ in noise units, the nuisance marginalised).
std::vector<bool> screen(HullFit& fit, std::vector<bool> free, double max_rel) {
  const Eigen::MatrixXd a = fit.normal_matrix(nullptr);
  const auto n_theta = static_cast<Eigen::Index>(fit.theta.size());
  for (;;) {
    std::vector<Eigen::Index> cols;
    for (Eigen::Index i = 0; i < n_theta; ++i) {
      if (free[static_cast<std::size_t>(i)]) cols.push_back(i);
    }
    if (cols.empty()) return free;
    const std::size_t n_free = cols.size();
    for (Eigen::Index i = n_theta; i < a.rows(); ++i) cols.push_back(i);
    const auto m = static_cast<Eigen::Index>(cols.size());
    Eigen::MatrixXd sub(m, m);
    for (Eigen::Index i = 0; i < m; ++i) {
      for (Eigen::Index j = 0; j < m; ++j) sub(i, j) = a(cols[i], cols[j]);
    }
    // Pseudo-inverse: a direction the data do not see has an infinite σ.
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(sub);
    const Eigen::VectorXd& ev = eig.eigenvalues();
    const double tol = ev.cwiseAbs().maxCoeff() * 1e-14;
    double worst = 0.0;
    std::size_t worst_k = 0;
    for (std::size_t k = 0; k < n_free; ++k) {
      double var = 0.0;
      for (Eigen::Index e = 0; e < m; ++e) {
        const double x = eig.eigenvectors()(static_cast<Eigen::Index>(k), e);
        var += ev[e] > tol ? x * x / ev[e] : (x * x > 1e-12 ? 1e300 : 0.0);
      }
      const auto i = static_cast<std::size_t>(cols[k]);
      const double rel = rel_sigma(fit.parameters()[i], fit.theta[i], std::sqrt(var));
      if (rel > worst) {
        worst = rel;
        worst_k = i;
      }
    }
    if (worst <= max_rel) return free;
    free[worst_k] = false;
  }
}

constexpr std::array<double, 3> kScaleFloor{0.002, 0.002, 5e-5};
// The sandwich σ's blocks [s]: longer than the waves' and the gusts' correlation, short enough
// that a 300 s stretch has five.
constexpr double kSigmaBlock_s = 60.0;
constexpr int kMaxRounds = 4;

struct FitOutcome {
  std::unique_ptr<HullFit> fit;
  std::vector<bool> free;
  std::vector<double> sigma_theta;
  int iterations = 0;
  std::string message;
};

// One round: solve the free parameters, reweight each test's channels by their RMS residual,
// solve again, σ by the Jacobian.
void solve_round(FitOutcome& o) {
  o.iterations += o.fit->solve(o.free, false, 50, &o.message);
  o.fit->rescale(kScaleFloor);
  o.message.clear();
  o.iterations += o.fit->solve(o.free, false, 30, &o.message);
  // σ with the residuals' variance and their correlation in time (waves, gusts and what the
  // model lacks are not white): the scales widened for it, then put back. A current's slow drift
  // leaves a residual correlated over minutes, which the AR(1) widening misses: σ is the larger
  // of that and the sandwich over 60 s blocks.
  const double variance = o.fit->residual_variance(o.free);
  const std::vector<double> blocks = o.fit->theta_sigma_blocks(o.free, kSigmaBlock_s);
  const std::vector<std::array<double, 3>> scale = o.fit->scale;
  o.fit->widen_for_correlation();
  o.sigma_theta = o.fit->theta_sigma(o.free, variance);
  o.fit->scale = scale;
  for (std::size_t i = 0; i < o.sigma_theta.size(); ++i) {
    if (std::isfinite(blocks[i])) o.sigma_theta[i] = std::max(o.sigma_theta[i], blocks[i]);
  }
}

// The fit of `tests` from theta0: each test's start velocity and current with the hull held,
// then the determined parameters (screen) freed. A parameter whose σ at the solution is too large
// leaves the set and goes back to the starting file's value, and the set is screened again at
// the solution; a changed set is solved again (kMaxRounds at most), so that the values and σ
// always come from one solve of the set reported.
FitOutcome fit_tests(const Setup& s, std::vector<const FitTest*> tests,
                     const std::vector<double>& theta0, double max_rel, unsigned jobs) {
  FitOutcome o;
  o.fit = std::make_unique<HullFit>(s.start, s.params, std::move(tests), jobs);
  HullFit& fit = *o.fit;
  if (!theta0.empty()) fit.theta = theta0;
  std::string ignored;
  fit.solve({}, true, 30, &ignored);
  const std::vector<bool> all(s.params.size(), true);
  o.free = screen(fit, all, max_rel);
  for (std::size_t i = 0; i < s.params.size(); ++i) {
    if (!o.free[i]) fit.theta[i] = 0.0;
  }
  for (int round = 1;; ++round) {
    solve_round(o);
    std::vector<bool> next = o.free;
    for (std::size_t i = 0; i < s.params.size(); ++i) {
      if (o.free[i] && rel_sigma(s.params[i], fit.theta[i], o.sigma_theta[i]) > max_rel) {
        next[i] = false;
      }
    }
    if (next == o.free) next = screen(fit, all, max_rel);
    if (next == o.free || round == kMaxRounds) break;
    for (std::size_t i = 0; i < s.params.size(); ++i) {
      if (!next[i]) fit.theta[i] = 0.0;
    }
    o.free = next;
  }
  if (std::none_of(o.free.begin(), o.free.end(), [](bool f) { return f; })) {
    o.sigma_theta.assign(s.params.size(), kNan);
  }
  return o;
}

// NRMSE of `simulated` against the valid `measured`: RMSE / (max − min); NaN without samples.
double nrmse(const std::vector<double>& measured, const std::vector<double>& simulated) {
  double ss = 0.0, lo = 1e300, hi = -1e300;
  std::size_t n = 0;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    if (core::is_missing(measured[i]) || core::is_missing(simulated[i])) continue;
    const double e = simulated[i] - measured[i];
    ss += e * e;
    lo = std::min(lo, measured[i]);
    hi = std::max(hi, measured[i]);
    ++n;
  }
  if (n == 0 || !(hi > lo)) return kNan;
  return std::sqrt(ss / static_cast<double>(n)) / (hi - lo);
}

// The re-simulated track from the first logged position, by η̇ = R(ψ)ν (2.20) with the logged
// heading; its NRMSE is the RMS distance over the larger extent of the logged track.
void add_track(TestResponse& r, const scenario::DriveSeries& d, const std::vector<double>& north,
               const std::vector<double>& east) {
  if (north.empty()) {
    r.track_nrmse = kNan;
    return;
  }
  r.north_m = north;
  r.east_m = east;
  const std::size_t n = d.size();
  r.sim_north_m.assign(n, north[0]);
  r.sim_east_m.assign(n, east[0]);
  auto vel = [&](std::size_t i) {
    const double c = std::cos(d.heading_rad[i]), sn = std::sin(d.heading_rad[i]);
    const double u = r.simulated[0][i], v = r.simulated[1][i];
    return Eigen::Vector2d(c * u - sn * v, sn * u + c * v);
  };
  double ss = 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    const Eigen::Vector2d step = 0.5 * (d.time_s[i] - d.time_s[i - 1]) * (vel(i - 1) + vel(i));
    r.sim_north_m[i] = r.sim_north_m[i - 1] + step.x();
    r.sim_east_m[i] = r.sim_east_m[i - 1] + step.y();
    ss += std::pow(r.sim_north_m[i] - north[i], 2) + std::pow(r.sim_east_m[i] - east[i], 2);
  }
  const auto [n_lo, n_hi] = std::minmax_element(north.begin(), north.end());
  const auto [e_lo, e_hi] = std::minmax_element(east.begin(), east.end());
  const double extent = std::max(*n_hi - *n_lo, *e_hi - *e_lo);
  r.track_nrmse = extent > 0 ? std::sqrt(ss / static_cast<double>(n)) / extent : kNan;
}

// The log's stretches fit.tests()[first, first + count) re-simulated, stitched on the log's
// samples and set against its measurements.
TestResponse response(const HullFit& fit, std::size_t first, std::size_t count,
                      const vessel_fit::LoggedTest& logged) {
  const FitTest& whole = logged.whole;
  TestResponse r;
  r.name = whole.name;
  r.time_s = whole.drive.time_s;
  const std::size_t n = r.time_s.size();
  for (std::size_t c = 0; c < 3; ++c) {
    r.measured[c].assign(n, kNan);
    r.simulated[c].assign(n, kNan);
    for (std::size_t m = 0; m < whole.index[c].size(); ++m) {
      r.measured[c][whole.index[c][m]] = whole.measured[c][m];
    }
  }
  r.current_n.setZero();
  for (std::size_t k = first; k < first + count; ++k) {
    const std::vector<Eigen::Vector3d> sim = fit.simulate(k);
    const std::size_t at = fit.tests()[k]->first;
    for (std::size_t i = 0; i < sim.size(); ++i) {
      for (std::size_t c = 0; c < 3; ++c) r.simulated[c][at + i] = sim[i][static_cast<int>(c)];
    }
    r.current_n += fit.nuisance[k].segment<2>(3) / static_cast<double>(count);
  }
  for (std::size_t c = 0; c < 3; ++c) r.nrmse[c] = nrmse(r.measured[c], r.simulated[c]);
  if (std::any_of(r.simulated[0].begin(), r.simulated[0].end(),
                  [](double v) { return core::is_missing(v); })) {
    r.track_nrmse = kNan;  // a stretch without a measurement was not re-simulated
    return r;
  }
  add_track(r, whole.drive, logged.north_m, logged.east_m);
  return r;
}

// The stretches of logs[k] as fit tests, and where each log's start in the list.
std::vector<const FitTest*> stretches(const std::vector<vessel_fit::LoggedTest>& logs,
                                      std::size_t skip, std::vector<std::size_t>* starts) {
  std::vector<const FitTest*> out;
  for (std::size_t k = 0; k < logs.size(); ++k) {
    if (starts != nullptr) starts->push_back(out.size());
    if (k == skip) continue;
    for (const FitTest& t : logs[k].stretches) out.push_back(&t);
  }
  if (starts != nullptr) starts->push_back(out.size());
  return out;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return io::read_capped(in, path, io::kMaxTomlBytes, "a vessel file is a few kB of TOML");
}

// The parameter table of the final fit.
std::vector<VesselParameter> parameters(Setup& s, const FitOutcome& o,
                                        const std::vector<Eigen::VectorXd>& information,
                                        double max_rel, double max_rel_fitted) {
  std::vector<VesselParameter> out;
  for (std::size_t i = 0; i < s.params.size(); ++i) {
    const FitParameter& p = s.params[i];
    double to_si = 1.0;
    VesselParameter v;
    v.key = p.key;
    v.unit = unit_of(s.start, p.key, &to_si);
    v.start = p.start / to_si;
    v.fitted = o.free[i];
    const double theta = o.fit->theta[i];
    v.value = p.value(theta) / to_si;
    v.sigma = std::abs(p.slope(theta)) * o.sigma_theta[i] / to_si;
    v.determined = v.fitted && v.sigma <= max_rel * std::abs(v.value);
    if (v.fitted) {
      double total = 0.0;
      std::vector<std::pair<std::string, double>> by_log;  // in the logs' order
      for (std::size_t k = 0; k < information.size(); ++k) {
        const double info = information[k][static_cast<Eigen::Index>(i)];
        total += info;
        const std::string& name = o.fit->tests()[k]->name;
        if (by_log.empty() || by_log.back().first != name) by_log.emplace_back(name, 0.0);
        by_log.back().second += info;
      }
      std::vector<std::string> from;
      for (const auto& [name, info] : by_log) {
        if (info >= 0.1 * total) from.push_back(name);
      }
      v.note = "from " + fmt::format("{}", fmt::join(from, ", "));
      if (!v.determined) {
        v.note = fmt::format("weakly determined (σ/|value| over {:.1f} %), {}; to determine it: {}",
                             100.0 * max_rel, v.note, s.excitation[i]);
      }
    } else {
      v.value = v.start;
      v.sigma = kNan;
      v.note = fmt::format("σ/|value| would exceed {:.0f} % with these tests; to determine it: {}",
                           100.0 * max_rel_fitted, s.excitation[i]);
    }
    out.push_back(v);
  }
  out.insert(out.end(), s.kept.begin(), s.kept.end());
  return out;
}

}  // namespace

void add_logs(VesselIdRequest& request, const LogSource& shared,
              const std::vector<std::string>& logs) {
  request.jobs = shared.jobs;
  for (const std::string& log : logs) {
    LogSource source = shared;
    source.log = log;
    request.logs.push_back(std::move(source));
  }
}

void VesselIdRequest::validate() const {
  if (logs.empty()) throw option_error("logs", "no log given", "name one log per test");
  if (!(max_rel_sigma > 0.0 && max_rel_sigma <= 1.0)) {
    throw option_error("max_rel_sigma", fmt::format("{} is not in (0, 1]", max_rel_sigma));
  }
  if (!(max_rel_sigma_fitted >= max_rel_sigma && max_rel_sigma_fitted <= 1.0)) {
    throw option_error("max_rel_sigma_fitted",
                       fmt::format("{} is not in [max_rel_sigma, 1]", max_rel_sigma_fitted));
  }
  if (!(step_s >= 0.01 && step_s <= 1.0)) {
    throw option_error("step", fmt::format("{} s is not in [0.01, 1] s", step_s));
  }
  if (!(sample_s >= step_s && sample_s <= 60.0)) {
    throw option_error("sample", fmt::format("{} s is not in [step, 60] s", sample_s));
  }
  if (!(stretch_s >= 30.0 && stretch_s <= 1e6)) {
    throw option_error("stretch", fmt::format("{} s is not in [30, 1e6] s", stretch_s));
  }
  if (!holdout.empty() && holdout != "none") {
    const bool known = std::any_of(logs.begin(), logs.end(),
                                   [&](const LogSource& l) { return l.log.string() == holdout; });
    if (!known) {
      throw option_error("holdout", "'" + holdout + "' is not one of the logs",
                         "name a LOG as given, or 'none'");
    }
  }
}

VesselIdReport run_vessel_id(const VesselIdRequest& request) {
  const auto t_start = std::chrono::steady_clock::now();
  request.validate();
  VesselIdReport report;
  report.vessel_file = vessel_file_or_default(request.vessel_file);
  scenario::VesselConfig start = scenario::load_vessel_config(report.vessel_file);
  report.vessel_text = read_text(report.vessel_file);
  const scenario::ThrustFeedback feedback(start);
  std::vector<vessel_fit::LoggedTest> logged;
  std::vector<vessel_units::LogUnits> unit_logs;
  for (const LogSource& source : request.logs) {
    logged.push_back(vessel_fit::read_test(source, feedback, request.step_s, request.sample_s,
                                           request.stretch_s));
    report.inputs.push_back(logged.back().input);
    unit_logs.push_back(std::move(logged.back().units));
  }
  // The units first: the hull is driven by their thrust, so it is fitted with their maps.
  vessel_units::UnitResult units =
      vessel_units::identify_units(start, unit_logs, request.max_rel_sigma, request.jobs);
  unit_logs.clear();
  vessel_units::apply(start, units.parameters);
  report.units = std::move(units.units);
  const bool wind = std::all_of(logged.begin(), logged.end(), [](const auto& t) {
    return !t.whole.drive.wind_speed_mps.empty();
  });
  Setup s = setup(start, wind);
  std::size_t held = logged.size();  // none
  if (request.holdout.empty() && logged.size() >= 2) held = logged.size() - 1;
  for (std::size_t k = 0; k < logged.size(); ++k) {
    if (request.logs[k].log.string() == request.holdout) held = k;
  }
  std::vector<double> theta0;
  std::optional<TestResponse> held_response;
  if (held < logged.size()) {
    FitOutcome o = fit_tests(s, stretches(logged, held, nullptr), {}, request.max_rel_sigma_fitted,
                             request.jobs);
    theta0 = o.fit->theta;
    std::vector<const FitTest*> own;
    for (const FitTest& t : logged[held].stretches) own.push_back(&t);
    HullFit score(s.start, s.params, own, request.jobs);
    score.theta = theta0;
    std::string ignored;
    score.solve({}, true, 30, &ignored);
    held_response = response(score, 0, own.size(), logged[held]);
    held_response->held_out = true;
    report.held_out = logged[held].whole.name;
  }
  std::vector<std::size_t> starts;
  FitOutcome o = fit_tests(s, stretches(logged, logged.size(), &starts), theta0,
                           request.max_rel_sigma_fitted, request.jobs);
  std::vector<Eigen::VectorXd> information;
  o.fit->normal_matrix(&information);
  report.parameters =
      parameters(s, o, information, request.max_rel_sigma, request.max_rel_sigma_fitted);
  report.parameters.insert(report.parameters.end(), units.parameters.begin(),
                           units.parameters.end());
  for (std::size_t k = 0; k < logged.size(); ++k) {
    report.tests.push_back(response(*o.fit, starts[k], starts[k + 1] - starts[k], logged[k]));
  }
  if (held_response) report.tests.push_back(*held_response);
  report.iterations = o.iterations;
  report.solver_message = o.message;
  report.run_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return report;
}

CompareTrialReport run_compare_trial(const CompareTrialRequest& request) {
  CompareTrialReport report;
  report.vessel_file = vessel_file_or_default(request.vessel_file);
  const scenario::VesselConfig vessel = scenario::load_vessel_config(report.vessel_file);
  const scenario::ThrustFeedback feedback(vessel);
  vessel_fit::LoggedTest logged = vessel_fit::read_test(request.source, feedback, request.step_s,
                                                        request.sample_s, request.stretch_s);
  report.input = logged.input;
  std::vector<const FitTest*> own;
  for (const FitTest& t : logged.stretches) own.push_back(&t);
  HullFit fit(vessel, {}, own, request.jobs);
  std::string ignored;
  fit.solve({}, true, 30, &ignored);
  report.test = response(fit, 0, own.size(), logged);
  return report;
}

}  // namespace dynpos::analysis
