#include "dynpos/calib/mru_observer.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynpos/calib/excitation.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/rotation.hpp"
#include "mru_arm_steps.hpp"

namespace dynpos::calib {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kHistoryRate_hz = 10.0;

core::InputError missing_role(const std::string& role, const std::string& file) {
  return core::InputError(
      {file, {}, {}, role},
      "MRU lever-arm estimation needs the role '" + role + "', not in the log",
      "map it with --col " + role + "=COLUMN (and --unit " + role + "=UNIT if not SI)");
}

/// The finite samples (t, value) of one channel.
struct Samples {
  std::vector<double> t, v;
};

Samples finite_samples(const core::Log& log, const std::string& role, const std::string& file,
                       bool unwrap_angle) {
  if (!log.has(role)) throw missing_role(role, file);
  const std::vector<double>& t = log.time();
  const std::vector<double>& x = log.values(role);
  Samples s;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(t[i])) continue;
    if (!s.t.empty() && !(t[i] > s.t.back())) {
      throw core::InputError({file, i + 2, {}, role}, "time is not increasing",
                             "sort the log by time and drop repeated rows");
    }
    double v = x[i];
    if (unwrap_angle && !s.v.empty()) {
      const double d = std::remainder(v - s.v.back(), 2.0 * std::numbers::pi);
      v = s.v.back() + d;
    }
    s.t.push_back(t[i]);
    s.v.push_back(v);
  }
  if (s.t.size() < 2) {
    throw core::InputError({file, {}, {}, role},
                           "fewer than two valid (finite) samples of '" + role + "'",
                           "check the column: NaN or blank everywhere?");
  }
  return s;
}

/// Linear interpolation of `s` at the increasing times `grid` (all inside [s.t.front, back]).
std::vector<double> interpolate(const Samples& s, const std::vector<double>& grid) {
  std::vector<double> out(grid.size());
  std::size_t j = 0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    while (j + 2 < s.t.size() && s.t[j + 1] < grid[i]) ++j;
    const double t0 = s.t[j], t1 = s.t[j + 1];
    const double a = std::clamp((grid[i] - t0) / (t1 - t0), 0.0, 1.0);
    out[i] = s.v[j] + a * (s.v[j + 1] - s.v[j]);
  }
  return out;
}

/// Quadratic Savitzky–Golay smoothing weights, half-width k: c_j = 3(3k² + 3k − 1 − 5j²) /
/// ((2k − 1)(2k + 1)(2k + 3)), j = −k … k.
std::vector<double> sg_weights(int k) {
  std::vector<double> c(2 * k + 1);
  const double kk = k;
  const double den = (2 * kk - 1) * (2 * kk + 1) * (2 * kk + 3);
  for (int j = -k; j <= k; ++j) c[j + k] = 3.0 * (3 * kk * kk + 3 * kk - 1 - 5.0 * j * j) / den;
  return c;
}

/// F: the smoother with half-width k; near the ends the window shrinks symmetrically.
template <class T>
std::vector<T> smooth(const std::vector<T>& x, int k) {
  const int n = static_cast<int>(x.size());
  std::vector<T> y(x.size());
  std::vector<std::vector<double>> w(k + 1);
  for (int h = 1; h <= k; ++h) w[h] = sg_weights(h);
  for (int i = 0; i < n; ++i) {
    const int h = std::min({k, i, n - 1 - i});
    if (h < 2) {
      y[i] = x[i];
      continue;
    }
    T acc = x[i] * w[h][h];
    for (int j = 1; j <= h; ++j) acc += (x[i - j] + x[i + j]) * w[h][h + j];
    y[i] = acc;
  }
  return y;
}

/// Central difference (one-sided at the ends).
template <class T>
std::vector<T> differentiate(const std::vector<T>& x, const std::vector<double>& t) {
  const std::size_t n = x.size();
  std::vector<T> d(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1;
    const std::size_t b = i + 1 == n ? n - 1 : i + 1;
    d[i] = (x[b] - x[a]) / (t[b] - t[a]);
  }
  return d;
}

double median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

int half_width(const std::vector<double>& t, double window_s) {
  std::vector<double> dt(t.size() - 1);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) dt[i] = t[i + 1] - t[i];
  return std::max(2, static_cast<int>(std::lround(0.5 * window_s / median(dt))));
}

// The normal equations of the least squares on a_i − a₀ = M·l_i: the information matrix
// H = Σ MᵀM and one right-hand side Σ Mᵀ(a_i − a₀) per MRU.
struct NormalEquations {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  std::vector<Eigen::Vector3d> b;
};

NormalEquations normal_equations(const MruSignals& s, detail::SampleSpan span) {
  const std::size_t m = s.names.size();
  NormalEquations ne;
  ne.b.assign(m, Eigen::Vector3d::Zero());
  for (std::size_t i = span.begin; i < span.end; ++i) {
    ne.H += s.M_b[i].transpose() * s.M_b[i];
    for (std::size_t j = 0; j < m; ++j) {
      ne.b[j] += s.M_b[i].transpose() * (s.a_b_mps2[j][i] - s.a0_b_mps2[i]);
    }
  }
  return ne;
}

// One MRU's least-squares arm l = H⁻¹·b and its 1σ from the residuals: cov(l) = σ²·H⁻¹, σ² the
// residual variance, inflated for the correlation the smoother puts between neighbours.
void lsq_arm(const MruSignals& s, std::size_t j, detail::SampleSpan span,
             const Eigen::Matrix3d& Hinv, const Eigen::Vector3d& b, Eigen::Vector3d& l,
             Eigen::Vector3d& std_m) {
  l = Hinv * b;
  std::vector<Eigen::Vector3d> e;
  e.reserve(span.size());
  double rss = 0.0;
  for (std::size_t i = span.begin; i < span.end; ++i) {
    e.push_back(s.a_b_mps2[j][i] - s.a0_b_mps2[i] - s.M_b[i] * l);
    rss += e.back().squaredNorm();
  }
  const double sigma2 = rss / static_cast<double>(3 * span.size() - 3);
  const double inflation = detail::variance_inflation(e);
  for (int a = 0; a < 3; ++a) std_m[a] = std::sqrt(sigma2 * inflation * Hinv(a, a));
}

// The recursive least-squares solution on the data up to t, every `stride` samples: the history
// plot of the least-squares arms.
void lsq_history(const MruSignals& s, detail::SampleSpan span, std::size_t stride,
                 MruEstimateResult& res) {
  const std::size_t m = s.names.size();
  Eigen::Matrix3d Hc = Eigen::Matrix3d::Zero();
  std::vector<Eigen::Vector3d> bc(m, Eigen::Vector3d::Zero());
  for (std::size_t i = span.begin; i < span.end; ++i) {
    Hc += s.M_b[i].transpose() * s.M_b[i];
    for (std::size_t j = 0; j < m; ++j) {
      bc[j] += s.M_b[i].transpose() * (s.a_b_mps2[j][i] - s.a0_b_mps2[i]);
    }
    if ((i - span.begin) % stride != 0) continue;
    res.history_t_s.push_back(s.t_s[i]);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> e(Hc);
    const bool ok =
        e.eigenvalues()(0) > 1e-6 * std::max(1e-30, e.eigenvalues()(2)) && e.eigenvalues()(0) > 0.0;
    for (std::size_t j = 0; j < m; ++j) {
      res.history_l_b_m[j].push_back(ok ? Eigen::Vector3d(Hc.ldlt().solve(bc[j]))
                                        : Eigen::Vector3d::Constant(kNaN));
    }
  }
}

// Luenberger observer (4.80) on x = [A₀; l₁ … l_m] in NED, y_i = R a_i, C (4.76). W₂ from the
// mean eigenvalue of the information matrix per sample, `mean_eig` [1/s⁴]. The arms are the
// mean and std of the state over the converged interval.
void run_observer(const MruSignals& s, const MruEstimateOptions& options, detail::SampleSpan span,
                  double mean_eig, std::size_t stride, MruEstimateResult& res) {
  const std::size_t m = s.names.size();
  const std::size_t i0 = span.begin, i1 = span.end;
  const int nx = static_cast<int>(3 * (m + 1));
  const double w2 = 1.0 / (options.tau_s * mean_eig);
  Eigen::VectorXd Wd(nx);
  Wd.head<3>().setConstant(options.w1_per_s);
  Wd.tail(nx - 3).setConstant(w2);
  Eigen::VectorXd x(nx);
  const auto A0_n = [&](std::size_t i) -> Eigen::Vector3d { return s.R_nb[i] * s.a0_b_mps2[i]; };
  x.head<3>() = A0_n(i0);
  for (std::size_t j = 0; j < m; ++j) x.segment<3>(static_cast<int>(3 + 3 * j)) = options.l0_b_m;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(static_cast<int>(3 * m), nx);
  Eigen::VectorXd y(static_cast<int>(3 * m));
  std::vector<std::vector<Eigen::Vector3d>> trace(m);
  const std::size_t conv_from =
      i0 + static_cast<std::size_t>(options.converge_fraction * static_cast<double>(span.size()));
  for (std::size_t i = i0 + 1; i < i1; ++i) {
    const double h = s.t_s[i] - s.t_s[i - 1];
    // B(t)u(t) (4.74)–(4.75) integrated over the step: Ȧ₀ of (4.70) is the derivative of
    // A₀ = R(ν̇ + ω × ν), so its integral is the change of A₀.
    x.head<3>() += A0_n(i) - A0_n(i - 1);
    const Eigen::Matrix3d RM = s.R_nb[i] * s.M_b[i];
    for (std::size_t j = 0; j < m; ++j) {
      const int r = static_cast<int>(3 * j);
      C.block<3, 3>(r, 0).setIdentity();
      C.block<3, 3>(r, 3 + r) = RM;
      y.segment<3>(r) = s.R_nb[i] * s.a_b_mps2[j][i];
    }
    // Correction W Cᵀ ỹ, integrated implicitly (unconditionally stable for any gain):
    // x⁺ = x + (I + h W CᵀC)⁻¹ h W Cᵀ (y − C x).
    const Eigen::MatrixXd WCt = Wd.asDiagonal() * C.transpose();
    const Eigen::MatrixXd K = Eigen::MatrixXd::Identity(nx, nx) + h * WCt * C;
    x += K.partialPivLu().solve(h * WCt * (y - C * x));
    if (i >= conv_from) {
      for (std::size_t j = 0; j < m; ++j) {
        trace[j].push_back(x.segment<3>(static_cast<int>(3 + 3 * j)));
      }
    }
    if ((i - i0) % stride == 0) {
      res.history_t_s.push_back(s.t_s[i]);
      for (std::size_t j = 0; j < m; ++j) {
        res.history_l_b_m[j].push_back(x.segment<3>(static_cast<int>(3 + 3 * j)));
      }
    }
  }
  for (std::size_t j = 0; j < m; ++j) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& v : trace[j]) mean += v;
    mean /= static_cast<double>(trace[j].size());
    Eigen::Vector3d var = Eigen::Vector3d::Zero();
    for (const auto& v : trace[j]) var += (v - mean).cwiseAbs2();
    var /= static_cast<double>(std::max<std::size_t>(1, trace[j].size() - 1));
    res.arms[j].l_b_m = mean;
    res.arms[j].std_m = var.cwiseSqrt();
  }
  res.interval_from_s = s.t_s[conv_from];
  res.interval_to_s = s.t_s[i1 - 1];
}

// Verdict per component from the residual-based 1σ (the same for both methods: it is what the
// data can tell), and Proposition 3: without rank-3 G anywhere nothing is determined.
void verdicts(const std::vector<std::string>& names, bool invertible, int rank3,
              const std::vector<Eigen::Vector3d>& std_lsq, MruEstimateResult& res) {
  for (std::size_t j = 0; j < names.size(); ++j) {
    for (int a = 0; a < 3; ++a) {
      Determinacy d = invertible ? determinacy_from_std(std_lsq[j][a]) : Determinacy::kNot;
      if (rank3 == 0) d = Determinacy::kNot;
      res.arms[j].determinacy[a] = d;
      const std::string advice = determinacy_advice(a, d);
      if (!advice.empty()) {
        const std::string line = names[j] + ": " + advice;
        res.excitation.advice.push_back(line);
      }
    }
  }
}

}  // namespace

std::string_view to_string(MruAccel a) {
  return a == MruAccel::kKinematic ? "kinematic" : "specific-force";
}
std::optional<MruAccel> parse_mru_accel(std::string_view text) {
  if (text == "kinematic") return MruAccel::kKinematic;
  if (text == "specific-force") return MruAccel::kSpecificForce;
  return std::nullopt;
}
std::string_view to_string(MruMethod m) { return m == MruMethod::kObserver ? "observer" : "lsq"; }
std::optional<MruMethod> parse_mru_method(std::string_view text) {
  if (text == "observer") return MruMethod::kObserver;
  if (text == "lsq") return MruMethod::kLsq;
  return std::nullopt;
}

void MruEstimateOptions::validate() const {
  if (!(w1_per_s > 0.0) || !std::isfinite(w1_per_s)) {
    throw std::invalid_argument("w1_per_s must be > 0");
  }
  if (!(tau_s > 0.0) || !std::isfinite(tau_s)) throw std::invalid_argument("tau_s must be > 0");
  if (!l0_b_m.allFinite()) throw std::invalid_argument("l0_b_m must be finite");
  if (!(converge_fraction >= 0.0 && converge_fraction < 1.0)) {
    throw std::invalid_argument("converge_fraction must be in [0, 1)");
  }
  if (!(edge_s >= 0.0) || !std::isfinite(edge_s)) {
    throw std::invalid_argument("edge_s must be >= 0");
  }
}

Eigen::Matrix3d mru_g_matrix(const Eigen::Vector3d& omega, const Eigen::Vector3d& omega_dot,
                             const Eigen::Vector3d& omega_ddot) {
  // (4.77): G = S³ + ṠS + 2SṠ + S̈.
  const Eigen::Matrix3d S = core::skew(omega);
  const Eigen::Matrix3d Sd = core::skew(omega_dot);
  return S * S * S + Sd * S + 2.0 * S * Sd + core::skew(omega_ddot);
}

MruSignals mru_signals_from_samples(const MruRawSamples& raw, const MruSignalOptions& options) {
  if (!(options.smooth_window_s > 0.0) || !std::isfinite(options.smooth_window_s)) {
    throw core::InputError::for_option("window_s", "the smoothing window must be > 0 s",
                                       "give e.g. --window-s 1");
  }
  const std::size_t n = raw.t_s.size();
  if (raw.names.empty()) {
    throw core::InputError({{}, {}, {}, "mru"}, "no MRU acceleration channels found",
                           "log mruK.ax, mruK.ay, mruK.az or give --mru-log mruK=FILE");
  }
  const int k = n >= 3 ? half_width(raw.t_s, options.smooth_window_s) : 2;
  if (n < static_cast<std::size_t>(8 * k + 8)) {
    throw core::InputError({{}, {}, {}, "time"},
                           "the log is too short: " + std::to_string(n) +
                               " samples, the smoothing window alone spans " +
                               std::to_string(2 * k + 1),
                           "log at least several smoothing windows of motion (minutes of "
                           "rotation are typical)");
  }
  MruSignals s;
  s.t_s = raw.t_s;
  s.names = raw.names;
  s.R_nb.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& th = raw.theta_rad[i];
    s.R_nb[i] = core::R_nb_zyx(th.x(), th.y(), th.z());
  }
  // F(ω), ω̇ = d/dt F(ω), ω̈ likewise (central differences of the smoothed signals).
  s.omega_b_rps = smooth(raw.omega_b_rps, k);
  s.omega_dot_b = differentiate(s.omega_b_rps, s.t_s);
  s.omega_ddot_b = smooth(differentiate(s.omega_dot_b, s.t_s), k);
  // M = F(S(ω)²) + S(ω̇): the smoother is applied to the product, as to every term.
  std::vector<Eigen::Matrix3d> S2(n);
  std::vector<Eigen::Vector3d> wxv(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Matrix3d S = core::skew(raw.omega_b_rps[i]);
    S2[i] = S * S;
    wxv[i] = raw.omega_b_rps[i].cross(raw.v_b_mps[i]);
  }
  S2 = smooth(S2, k);
  s.M_b.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.M_b[i] = S2[i] + core::skew(s.omega_dot_b[i]);
  // a₀ = ν̇ + ω × ν (4.69) in BODY, filtered: d/dt F(ν) + F(ω × ν).
  const std::vector<Eigen::Vector3d> nu_dot = differentiate(smooth(raw.v_b_mps, k), s.t_s);
  wxv = smooth(wxv, k);
  s.a0_b_mps2.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.a0_b_mps2[i] = nu_dot[i] + wxv[i];
  const Eigen::Vector3d g_n(0.0, 0.0, options.gravity_mps2);
  for (const auto& a_raw : raw.a_b_mps2) {
    std::vector<Eigen::Vector3d> a = a_raw;
    if (options.accel == MruAccel::kSpecificForce) {
      // f = Rᵀ(A − g_n)  ⇒  a = f + Rᵀ g_n.
      for (std::size_t i = 0; i < n; ++i) a[i] += s.R_nb[i].transpose() * g_n;
    }
    s.a_b_mps2.push_back(smooth(a, k));
  }
  return s;
}

MruSignals mru_signals_from_logs(const core::Log& motion, const std::vector<MruSource>& mrus,
                                 const MruSignalOptions& options) {
  if (mrus.empty()) {
    throw core::InputError({{}, {}, {}, "mru"}, "no MRU acceleration channels found",
                           "log mruK.ax, mruK.ay, mruK.az or give --mru-log mruK=FILE");
  }
  std::vector<Samples> motion_ch;
  std::vector<std::string> notes;
  for (const char* role : {"roll", "pitch", "heading", "p", "q", "r", "u", "v"}) {
    motion_ch.push_back(finite_samples(motion, role, {}, std::string(role) == "heading"));
  }
  const bool heave = motion.has("w");
  if (heave) {
    motion_ch.push_back(finite_samples(motion, "w", {}, false));
  } else {
    notes.emplace_back(
        "w (heave speed) not logged: taken as 0, which biases z unless the "
        "vessel does not heave");
  }
  // ν̇ needs velocity at wave frequency: a 1 Hz speed log leaves a₀ (4.69) biased.
  for (std::size_t c = 6; c < motion_ch.size(); ++c) {
    const Samples& v = motion_ch[c];
    const double rate_hz =
        static_cast<double>(v.t.size() - 1) / std::max(1e-9, v.t.back() - v.t.front());
    if (rate_hz < 5.0) {
      notes.push_back(std::string(c == 6   ? "u"
                                  : c == 7 ? "v"
                                           : "w") +
                      " is logged at " + std::to_string(rate_hz).substr(0, 4) +
                      " Hz: too slow for the wave-frequency acceleration of the origin (4.69); "
                      "the arms are biased, their differences are not (log velocity at >= 10 Hz)");
    }
  }
  std::vector<std::array<Samples, 3>> acc;
  for (const MruSource& m : mrus) {
    if (m.log == nullptr) throw std::invalid_argument("MruSource without a log");
    acc.push_back({finite_samples(*m.log, m.name + ".ax", m.file, false),
                   finite_samples(*m.log, m.name + ".ay", m.file, false),
                   finite_samples(*m.log, m.name + ".az", m.file, false)});
  }
  // The grid: the first MRU's az samples, inside every channel's span.
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  const auto cover = [&](const Samples& s) {
    lo = std::max(lo, s.t.front());
    hi = std::min(hi, s.t.back());
  };
  for (const Samples& s : motion_ch) cover(s);
  for (const auto& a : acc) {
    for (const Samples& s : a) cover(s);
  }
  MruRawSamples raw;
  for (double t : acc[0][2].t) {
    if (t >= lo && t <= hi) raw.t_s.push_back(t);
  }
  if (raw.t_s.size() < 2) {
    throw core::InputError({mrus[0].file, {}, {}, mrus[0].name + ".az"},
                           "the MRU samples do not overlap the motion channels in time",
                           "check that the logs cover the same interval on the same clock");
  }
  std::vector<std::vector<double>> m;
  for (const Samples& s : motion_ch) m.push_back(interpolate(s, raw.t_s));
  const std::size_t n = raw.t_s.size();
  for (std::size_t i = 0; i < n; ++i) {
    raw.theta_rad.emplace_back(m[0][i], m[1][i], m[2][i]);
    raw.omega_b_rps.emplace_back(m[3][i], m[4][i], m[5][i]);
    raw.v_b_mps.emplace_back(m[6][i], m[7][i], heave ? m[8][i] : 0.0);
  }
  for (std::size_t j = 0; j < mrus.size(); ++j) {
    raw.names.push_back(mrus[j].name);
    const std::vector<double> ax = interpolate(acc[j][0], raw.t_s);
    const std::vector<double> ay = interpolate(acc[j][1], raw.t_s);
    const std::vector<double> az = interpolate(acc[j][2], raw.t_s);
    std::vector<Eigen::Vector3d> a(n);
    for (std::size_t i = 0; i < n; ++i) a[i] = {ax[i], ay[i], az[i]};
    raw.a_b_mps2.push_back(std::move(a));
  }
  MruSignals s = mru_signals_from_samples(raw, options);
  s.notes = std::move(notes);
  return s;
}

MruEstimateResult estimate_mru_arms(const MruSignals& s, const MruEstimateOptions& options) {
  options.validate();
  MruEstimateResult res;
  res.method = options.method;
  const std::size_t n = s.size();
  const std::size_t m = s.names.size();
  if (n < 3 || m == 0) {
    res.message = "too few samples or no MRU";
    return res;
  }
  // The used span: the edges where the smoother's window is cut off are dropped.
  const detail::SampleSpan span = detail::used_span(s.t_s, options.edge_s);
  if (span.end < span.begin + 10) {
    res.message = "the log is too short once the filter edges are dropped";
    return res;
  }
  const std::size_t used = span.size();
  const double dt = (s.t_s[span.end - 1] - s.t_s[span.begin]) / static_cast<double>(used - 1);
  const std::size_t stride =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(1.0 / (kHistoryRate_hz * dt))));

  const NormalEquations ne = normal_equations(s, span);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(ne.H / static_cast<double>(used));
  res.excitation.info_min_eig = eig.eigenvalues()(0);
  res.excitation.info_condition =
      eig.eigenvalues()(0) > 0 ? eig.eigenvalues()(2) / eig.eigenvalues()(0) : kNaN;
  const bool invertible = eig.eigenvalues()(0) > 1e-12 * std::max(1e-30, eig.eigenvalues()(2));
  const Eigen::Matrix3d Hinv =
      invertible ? Eigen::Matrix3d(ne.H.inverse()) : Eigen::Matrix3d::Constant(kNaN);
  std::vector<Eigen::Vector3d> l_lsq(m), std_lsq(m);
  for (std::size_t j = 0; j < m; ++j) lsq_arm(s, j, span, Hinv, ne.b[j], l_lsq[j], std_lsq[j]);

  // Excitation along the log: G(t) (4.77) at the history rate.
  const int rank3 = detail::g_excitation(s, span, stride, res.excitation);

  res.arms.resize(m);
  for (std::size_t j = 0; j < m; ++j) res.arms[j].name = s.names[j];
  res.history_l_b_m.assign(m, {});
  if (options.method == MruMethod::kLsq) {
    lsq_history(s, span, stride, res);
    for (std::size_t j = 0; j < m; ++j) {
      res.arms[j].l_b_m = l_lsq[j];
      res.arms[j].std_m = std_lsq[j];
    }
    res.interval_from_s = s.t_s[span.begin];
    res.interval_to_s = s.t_s[span.end - 1];
  } else {
    run_observer(s, options, span, std::max(1e-30, eig.eigenvalues().mean()), stride, res);
  }
  verdicts(s.names, invertible, rank3, std_lsq, res);
  res.status = core::Status::kOk;
  res.message = "ok";
  return res;
}

namespace detail {

SampleSpan used_span(const std::vector<double>& t_s, double edge_s) {
  const std::size_t n = t_s.size();
  std::size_t i0 = 0, i1 = n;
  while (i0 < n && t_s[i0] < t_s.front() + edge_s) ++i0;
  while (i1 > i0 && t_s[i1 - 1] > t_s.back() - edge_s) --i1;
  return {i0, i1};
}

double variance_inflation(const std::vector<Eigen::Vector3d>& e) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 1; i < e.size(); ++i) {
    num += e[i - 1].dot(e[i]);
    den += e[i - 1].squaredNorm();
  }
  const double rho = den > 0 ? std::clamp(num / den, 0.0, 0.999) : 0.0;
  return (1.0 + rho) / (1.0 - rho);
}

int g_excitation(const MruSignals& s, SampleSpan span, std::size_t stride, MruExcitation& out) {
  std::vector<double> min_sv, cond;
  int rank3 = 0;
  for (std::size_t i = span.begin; i < span.end; i += stride) {
    const Eigen::Matrix3d G = mru_g_matrix(s.omega_b_rps[i], s.omega_dot_b[i], s.omega_ddot_b[i]);
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(G);
    const Eigen::Vector3d sv = svd.singularValues();
    const double tol = std::max(1e-9, 1e-3 * sv(0));
    const int rank = static_cast<int>((sv.array() > tol).count());
    rank3 += rank == 3 ? 1 : 0;
    out.t_s.push_back(s.t_s[i]);
    out.g_min_sv.push_back(sv(2));
    out.g_rank.push_back(rank);
    min_sv.push_back(sv(2));
    cond.push_back(sv(2) > 0 ? sv(0) / sv(2) : std::numeric_limits<double>::infinity());
  }
  out.rank3_fraction =
      min_sv.empty() ? 0.0 : static_cast<double>(rank3) / static_cast<double>(min_sv.size());
  out.g_min_sv_median = median(min_sv);
  out.g_condition_median = median(cond);
  return rank3;
}

}  // namespace detail
}  // namespace dynpos::calib
