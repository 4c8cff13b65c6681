// The units of a [[thruster]] layout in identify vessel (vessel_layout_units.hpp).

#include "vessel_layout_units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "dynpos/core/log.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/model/unit_drive.hpp"
#include "vessel_unit_steps.hpp"

namespace dynpos::analysis::vessel_units {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr const char* kPrefix = "thruster.";

// The corrections of T_n and δ are iterated (each round fits the model at the last round's
// values) at most this often.
constexpr int kMaxRounds = 10;
// The keys' ranges (docs/vessel-file.md): time_constant_s (0, 60], dead_time_s [0, 10],
// rate_deg_per_s (0, 360].
constexpr double kMinTimeConstantS = 1e-3, kMaxTimeConstantS = 60.0, kMaxDeadTimeS = 10.0;
constexpr double kMaxRateDegS = 360.0;
// A turn is at the slew rate while what is left of it exceeds rate/gain; a stretch is counted
// from 1.5 times that, so that a file's rate up to a third too low or half too high still
// picks samples at the rate limit.
constexpr double kSaturationMargin = 1.5;
// The first 0.5 s of such a stretch is left out: a dead time off by that much does not put the
// start of the turn in it.
constexpr double kTurnStartTrimS = 0.5;
// A stretch is fitted with at least 5 samples over at least 1 s.
constexpr std::size_t kMinTurnSamples = 5;
constexpr double kMinTurnSpanS = 1.0;

constexpr const char* kStepsHow = "order steps (FOPDT fits of command.rpm → rpm)";
constexpr const char* kTurnsHow = "rate-limited turns (slope of the azimuth)";

// The step of the drive's simulation driven by a logged order [s].
constexpr double kDriveStepS = 0.01;

// The drive's shaft speed at the log's samples over a step's window, driven by the logged
// order (held between its samples) through the dead time: the model gets the order the unit
// got, its ramps and re-allocations included, not an ideal step. From steady state at the order
// 10 T_n before the window (the log's start at the earliest); RK4 between the instants the
// delayed order changes (so that the response moves with δ continuously), in steps of at most
// kDriveStepS.
ModelSamples driven(model::UnitDrive drive) {
  return [drive = std::move(drive)](const LoggedStep& s) {
    const std::vector<double>& t = s.log->time_s;
    const std::vector<double>& order = s.unit->order_rps;
    const model::UnitDriveParams& p = drive.params();
    std::vector<double> y(t.size(), kNan);
    const auto valid =
        std::find_if(order.begin(), order.end(), [](double v) { return !core::is_missing(v); });
    if (valid == order.end()) return y;
    double x = std::max(t.front(), s.step.t_begin - 10.0 * p.time_constant_s);
    double held = *valid;  // the order in force at x − δ
    std::size_t j = 0;     // the next order sample, in force from t[j] + δ
    for (; j < t.size() && t[j] <= x - p.dead_time_s; ++j) {
      if (!core::is_missing(order[j])) held = order[j];
    }
    double n = std::clamp(held, -p.max_shaft_speed_rps, p.max_shaft_speed_rps);
    // From x to `to` under the held order.
    auto integrate = [&](double to) {
      const auto f = [&](double v) { return drive.shaft_acceleration(v, held); };
      const int m = std::max(1, static_cast<int>(std::ceil((to - x) / kDriveStepS - 1e-9)));
      const double h = (to - x) / m;
      for (int k = 0; k < m; ++k) {
        const double k1 = f(n), k2 = f(n + 0.5 * h * k1), k3 = f(n + 0.5 * h * k2);
        const double k4 = f(n + h * k3);
        n += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      }
      x = to;
    };
    const auto first =
        static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), s.step.t_begin) - t.begin());
    for (std::size_t i = first; i < t.size() && t[i] <= s.step.t_end; ++i) {
      for (; j < t.size() && t[j] + p.dead_time_s <= t[i]; ++j) {
        integrate(std::max(x, t[j] + p.dead_time_s));
        if (!core::is_missing(order[j])) held = order[j];
      }
      integrate(t[i]);
      if (!core::is_missing(s.unit->shaft_speed_rps[i])) y[i] = n;
    }
    return y;
  };
}

// The estimates of one round: each step's T_n and δ.
struct Round {
  std::vector<Estimate> time_constant, dead_time;
};

model::UnitDrive drive_at(model::ThrusterUnit unit, double t_n, double dead) {
  unit.time_constant_s = t_n;
  unit.dead_time_s = dead;
  return model::UnitDrive(unit);
}

// The fit of `f`'s step in `fits`, or nullptr.
const ModelFit* fit_of(const std::vector<StepFit>& fits, const StepFit& f) {
  const auto it = std::find_if(fits.begin(), fits.end(),
                               [&](const StepFit& g) { return g.logged == f.logged; });
  return it == fits.end() ? nullptr : &it->model;
}

// Whether a fit's slopes in T from below (lo) and from above (hi) agree within half the larger
// and 0.05 (s/s): a FOPDT fit of a response far from first order can switch between minima as
// T changes, and such a step's slope is no slope.
bool smooth(double lo, double hi) {
  return std::abs(hi - lo) <= 0.5 * std::max(std::abs(lo), std::abs(hi)) + 0.05;
}

// One round at the model's (T, δ): per step, the model's fits (T_m, δ_m) and their slopes in T,
// a = ∂T_m/∂T and c = ∂δ_m/∂T (central differences over ±10 % of T; ∂δ_m/∂δ = 1 and
// ∂T_m/∂δ = 0, a dead time only shifts the response), give the values that make the model's
// fits the log's (T_log, δ_log) to first order: T* = T + (T_log − T_m)/a,
// δ* = δ + (δ_log − δ_m) − c·(T* − T). An ideal step of the self-similar drive (time scales
// with T_n, its rate limit n_max/(4T_n) included) has a = T_m/T and c = (δ_m − δ)/T; a ramped
// order delays the response by its own shape, which c leaves out. σ of δ* is the bound
// σ_δ + |c|·σ_T* for any correlation of the two fitted values. A step whose
// slopes from either side disagree is left out of the round. With T_n held, the dead time
// alone: δ* = δ + δ_log − δ_m.
Round round(const model::ThrusterUnit& unit, const std::vector<LoggedStep>& steps, double t_n,
            double dead, bool fit_time_constant) {
  constexpr double kStep = 0.1;
  const std::vector<StepFit> at = with_model(steps, driven(drive_at(unit, t_n, dead)));
  std::vector<StepFit> below, above;
  if (fit_time_constant) {
    below = with_model(steps, driven(drive_at(unit, t_n * (1.0 - kStep), dead)));
    above = with_model(steps, driven(drive_at(unit, t_n * (1.0 + kStep), dead)));
  }
  const double h = kStep * t_n;
  Round out;
  for (const StepFit& f : at) {
    const LoggedStep& s = *f.logged;
    const std::string& log = s.log->name;
    if (!fit_time_constant) {
      out.dead_time.push_back(
          {dead + s.dead_time_s - f.model.dead_time_s, s.dead_time_sigma_s, log});
      continue;
    }
    const ModelFit* lo = fit_of(below, f);
    const ModelFit* hi = fit_of(above, f);
    if (lo == nullptr || hi == nullptr) continue;
    const double a_lo = (f.model.time_constant_s - lo->time_constant_s) / h;
    const double a_hi = (hi->time_constant_s - f.model.time_constant_s) / h;
    const double c_lo = (f.model.dead_time_s - lo->dead_time_s) / h;
    const double c_hi = (hi->dead_time_s - f.model.dead_time_s) / h;
    if (!smooth(a_lo, a_hi) || !smooth(c_lo, c_hi)) continue;
    const double a = 0.5 * (a_lo + a_hi), c = 0.5 * (c_lo + c_hi);
    if (!(a > 0.0)) continue;  // the step's fit does not see T_n
    const double t_star = t_n + (s.time_constant_s - f.model.time_constant_s) / a;
    const double sigma_t = s.time_constant_sigma_s / a;
    out.time_constant.push_back({t_star, sigma_t, log});
    out.dead_time.push_back({dead + s.dead_time_s - f.model.dead_time_s - c * (t_star - t_n),
                             s.dead_time_sigma_s + std::abs(c) * sigma_t, log});
  }
  return out;
}

// The rounds from the file's (T, δ) until a round moves each by under a hundredth of its σ
// (at most kMaxRounds): the last round's estimates, whose means are the values at which the
// model's fits are the log's.
Round converged(const model::ThrusterUnit& unit, const std::vector<LoggedStep>& steps, double t_n,
                double dead, bool fit_time_constant) {
  Round r;
  for (int k = 0; k < kMaxRounds; ++k) {
    r = round(unit, steps, t_n, dead, fit_time_constant);
    const std::optional<Combined> t = combine(r.time_constant);
    const std::optional<Combined> d = combine(r.dead_time);
    const double t_next = t ? std::clamp(t->value, kMinTimeConstantS, kMaxTimeConstantS) : t_n;
    const double d_next = d ? std::clamp(d->value, 0.0, kMaxDeadTimeS) : dead;
    const bool settled = (!t || std::abs(t_next - t_n) <= 0.01 * t->sigma) &&
                         (!d || std::abs(d_next - dead) <= 0.01 * d->sigma);
    if (settled) break;
    t_n = t_next;
    dead = d_next;
  }
  return r;
}

// A determined value outside its key's range is not written.
void within(VesselParameter& p, double lo, double hi) {
  if (!p.determined || (p.value >= lo && p.value <= hi)) return;
  p.note = fmt::format("{:.4g} ± {:.2g} is outside the key's range [{}, {}]: not determined; {}",
                       p.value, p.sigma, lo, hi, p.note);
  p.value = p.start;
  p.sigma = kNan;
  p.determined = p.fitted = false;
}

// The slew rate [deg/s] of one rate-limited stretch: the least-squares slope of the unwrapped
// angle over samples `at` (its first kTurnStartTrimS left out), σ from the residuals.
std::optional<Estimate> turn_rate(const std::vector<double>& t, const std::vector<double>& a,
                                  const std::vector<std::size_t>& at, const std::string& log) {
  std::vector<double> x, y;
  std::size_t last = 0;
  for (std::size_t i : at) {
    if (t[i] < t[at.front()] + kTurnStartTrimS) continue;
    y.push_back(y.empty() ? 0.0
                          : y.back() + std::remainder(a[i] - a[last], 2.0 * std::numbers::pi));
    x.push_back(t[i]);
    last = i;
  }
  const std::size_t n = x.size();
  if (n < kMinTurnSamples || x.back() - x.front() < kMinTurnSpanS) return std::nullopt;
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    mx += x[k] / static_cast<double>(n);
    my += y[k] / static_cast<double>(n);
  }
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  const double slope = sxy / sxx;
  double sse = 0.0;
  for (std::size_t k = 0; k < n; ++k) sse += std::pow(y[k] - my - slope * (x[k] - mx), 2);
  const double sigma = std::sqrt(sse / static_cast<double>(n - 2) / sxx);
  const double rate = std::abs(slope) / kDeg;
  // A noise-free log: σ 0 would be no weight; at least 10⁻¹² of the value.
  return Estimate{rate, std::max(sigma / kDeg, 1e-12 * rate), log};
}

// The rate-limited stretches of an azimuth's turns in `logs`: where the turn left from its
// logged direction to its order δ earlier (the drive's way round) is over kSaturationMargin
// times rate/gain of the file's drive, one sign throughout.
std::vector<Estimate> slew_rates(const model::UnitDrive& drive, const std::vector<LogUnits>& logs,
                                 double dead) {
  std::vector<Estimate> out;
  const double threshold =
      kSaturationMargin * drive.unit().rate_deg_per_s * kDeg / drive.params().steering_gain_per_s;
  for (const LogUnits& log : logs) {
    for (const UnitColumns& u : log.units) {
      if (u.unit != drive.unit().name || u.azimuth_rad.empty() || u.azimuth_order_rad.empty()) {
        continue;
      }
      const std::vector<double>& t = log.time_s;
      std::vector<std::size_t> run;
      int sign = 0;
      auto close = [&]() {
        if (!run.empty()) {
          if (auto e = turn_rate(t, u.azimuth_rad, run, log.name)) out.push_back(*e);
        }
        run.clear();
      };
      double order = kNan;  // the order δ before the sample, held
      for (std::size_t i = 0, j = 0; i < t.size(); ++i) {
        for (; j < t.size() && t[j] <= t[i] - dead; ++j) {
          if (!core::is_missing(u.azimuth_order_rad[j])) order = u.azimuth_order_rad[j];
        }
        if (core::is_missing(u.azimuth_rad[i]) || std::isnan(order)) continue;
        const double turn = drive.turn_rad(u.azimuth_rad[i], order);
        const int s = std::abs(turn) < threshold ? 0 : (turn > 0.0 ? 1 : -1);
        if (s != sign) close();
        sign = s;
        if (s != 0) run.push_back(i);
      }
      close();
    }
  }
  return out;
}

// One unit's values.
void layout_unit(const model::ThrusterUnit& unit, const std::vector<LogUnits>& logs, double max_rel,
                 UnitResult& out) {
  const model::UnitDrive file(unit);
  const double t_n = file.params().time_constant_s;
  const std::vector<LoggedStep> steps = logged_steps(logs, unit.name);
  UnitIdentification id =
      dynamics(unit.name, with_model(steps, driven(file)), thrust_maps(logs, unit.name));
  const std::string excitation = fmt::format(
      "steps of its shaft speed order ({}) with rpm.{} and command.rpm.{} logged at 10 Hz or "
      "more",
      unit.type == model::UnitType::kTunnel ? "sway steps" : "surge, sway or yaw steps", unit.name,
      unit.name);
  Round r = converged(unit, steps, t_n, unit.dead_time_s, true);
  VesselParameter time_constant = parameter(layout_key(unit.name, "time_constant_s"), "s", t_n,
                                            r.time_constant, kStepsHow, excitation, max_rel);
  within(time_constant, kMinTimeConstantS, kMaxTimeConstantS);
  // T_n kept: δ with the file's T_n.
  if (!time_constant.determined) r = converged(unit, steps, t_n, unit.dead_time_s, false);
  VesselParameter dead = parameter(layout_key(unit.name, "dead_time_s"), "s", unit.dead_time_s,
                                   r.dead_time, kStepsHow, excitation, max_rel);
  within(dead, 0.0, kMaxDeadTimeS);
  out.parameters.push_back(dead);
  out.parameters.push_back(time_constant);
  if (unit.type == model::UnitType::kAzimuth) {
    const double threshold_deg =
        kSaturationMargin * unit.rate_deg_per_s / file.params().steering_gain_per_s;
    const std::vector<Estimate> rates =
        slew_rates(file, logs, dead.determined ? dead.value : unit.dead_time_s);
    set(combine(rates), id.slew_rate_deg_per_s, id.slew_rate_sigma_deg_per_s);
    id.turns = rates.size();
    VesselParameter rate = parameter(
        layout_key(unit.name, "rate_deg_per_s"), "deg/s", unit.rate_deg_per_s, rates, kTurnsHow,
        fmt::format("turns of its order over {:.0f}° with azimuth.{} and command.azimuth.{} "
                    "logged at 10 Hz or more",
                    threshold_deg + unit.rate_deg_per_s * (kTurnStartTrimS + kMinTurnSpanS),
                    unit.name, unit.name),
        max_rel);
    within(rate, 0.0, kMaxRateDegS);
    out.parameters.push_back(rate);
  }
  out.units.push_back(id);
}

}  // namespace

std::string layout_key(const std::string& unit, const std::string& key) {
  return kPrefix + unit + "." + key;
}

std::optional<std::pair<std::string, std::string>> layout_key_parts(const std::string& key) {
  const std::string prefix = kPrefix;
  const std::size_t dot = key.rfind('.');
  if (key.rfind(prefix, 0) != 0 || dot == std::string::npos || dot <= prefix.size()) {
    return std::nullopt;
  }
  return std::pair{key.substr(prefix.size(), dot - prefix.size()), key.substr(dot + 1)};
}

void layout_units(const scenario::VesselConfig& start, const std::vector<LogUnits>& logs,
                  double max_rel_sigma, unsigned jobs, UnitResult& out) {
  std::vector<UnitResult> each(start.thrusters.size());  // one slot per unit: in layout order
  core::parallel_for(each.size(), jobs, [&](std::size_t k) {
    layout_unit(start.thrusters[k], logs, max_rel_sigma, each[k]);
  });
  for (const UnitResult& r : each) {
    out.parameters.insert(out.parameters.end(), r.parameters.begin(), r.parameters.end());
    out.units.insert(out.units.end(), r.units.begin(), r.units.end());
  }
}

bool apply_layout(scenario::VesselConfig& config, const VesselParameter& p) {
  const auto parts = layout_key_parts(p.key);
  if (!parts) return false;
  for (model::ThrusterUnit& u : config.thrusters) {
    if (u.name != parts->first) continue;
    if (parts->second == "dead_time_s") u.dead_time_s = p.value;
    if (parts->second == "time_constant_s") u.time_constant_s = p.value;
    if (parts->second == "rate_deg_per_s") u.rate_deg_per_s = p.value;
    return true;
  }
  return false;
}

}  // namespace dynpos::analysis::vessel_units
