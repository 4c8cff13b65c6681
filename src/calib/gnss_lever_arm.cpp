#include "dynpos/calib/gnss_lever_arm.hpp"

#include <fmt/format.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

#include "dynpos/core/error.hpp"
#include "dynpos/core/rotation.hpp"
#include "gnss_arm_steps.hpp"

namespace dynpos::calib {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

double unwrap_to(double prev, double x) {
  const double two_pi = 2.0 * std::numbers::pi;
  return x - two_pi * std::round((x - prev) / two_pi);
}

// The motion as continuous signals: attitude and ω linear between samples (angles unwrapped),
// and D(t) = ∫₀ᵗ R·ν dτ (the P₀ displacement of (4.6)) by the trapezoid rule.
class MotionInterp {
 public:
  explicit MotionInterp(const MotionSeries& m) : t_(m.t_s), th_(m.theta_rad), w_(m.omega_b_rps) {
    for (std::size_t i = 1; i < th_.size(); ++i)
      for (int k = 0; k < 3; ++k) th_[i](k) = unwrap_to(th_[i - 1](k), th_[i](k));
    d_.resize(t_.size());
    d_[0].setZero();
    Vec3 prev = rot(0) * m.v_b_mps[0];
    for (std::size_t i = 1; i < t_.size(); ++i) {
      const Vec3 cur = rot(i) * m.v_b_mps[i];
      d_[i] = d_[i - 1] + 0.5 * (prev + cur) * (t_[i] - t_[i - 1]);
      prev = cur;
    }
  }
  bool covers(double t) const { return t >= t_.front() && t <= t_.back(); }
  double front() const { return t_.front(); }
  double back() const { return t_.back(); }
  // Index i and weight a with x(t) = (1 − a)·x_i + a·x_{i+1}.
  std::pair<std::size_t, double> locate(double t) const {
    auto it = std::upper_bound(t_.begin(), t_.end(), t);
    std::size_t i = it == t_.begin() ? 0 : static_cast<std::size_t>(it - t_.begin()) - 1;
    if (i + 1 >= t_.size()) i = t_.size() - 2;
    return {i, (t - t_[i]) / (t_[i + 1] - t_[i])};
  }
  Vec3 theta(double t) const {
    const auto [i, a] = locate(t);
    return (1.0 - a) * th_[i] + a * th_[i + 1];
  }
  Vec3 omega(double t) const {
    const auto [i, a] = locate(t);
    return (1.0 - a) * w_[i] + a * w_[i + 1];
  }
  Vec3 disp(double t) const {
    const auto [i, a] = locate(t);
    return (1.0 - a) * d_[i] + a * d_[i + 1];
  }
  Mat3 R(double t) const {
    const Vec3 th = theta(t);
    return core::R_nb_zyx(th(0), th(1), th(2));
  }

 private:
  Mat3 rot(std::size_t i) const { return core::R_nb_zyx(th_[i](0), th_[i](1), th_[i](2)); }
  std::vector<double> t_;
  std::vector<Vec3> th_, w_, d_;
};

// One fix epoch: stamp time, motion at stamp − δ, and each antenna's fix (NaN if none).
struct Epoch {
  double t_s = 0.0;  // motion time
  Mat3 R;
  Vec3 D;
  Vec3 omega;
  std::vector<Vec3> p;  // per antenna
  std::vector<bool> has;
};

std::vector<Epoch> make_epochs(const MotionInterp& mi, const std::vector<GnssSeries>& ant,
                               double offset_s) {
  std::map<double, std::vector<std::pair<std::size_t, Vec3>>> by_time;
  for (std::size_t k = 0; k < ant.size(); ++k)
    for (std::size_t i = 0; i < ant[k].t_s.size(); ++i)
      by_time[ant[k].t_s[i]].emplace_back(k, ant[k].p_n_m[i]);
  std::vector<Epoch> out;
  out.reserve(by_time.size());
  for (const auto& [stamp, fixes] : by_time) {
    const double t = stamp - offset_s;  // the fix stamped t holds the position at t − δ
    if (!mi.covers(t)) continue;
    Epoch e;
    e.t_s = t;
    e.R = mi.R(t);
    e.D = mi.disp(t);
    e.omega = mi.omega(t);
    e.p.assign(ant.size(), Vec3::Constant(kNaN));
    e.has.assign(ant.size(), false);
    for (const auto& [k, p] : fixes) {
      e.p[k] = p;
      e.has[k] = true;
    }
    out.push_back(std::move(e));
  }
  return out;
}

// One row block of the least squares: z = Σ_blocks A_b·l_b, 3 rows (one per NED axis).
struct RowBlock {
  Vec3 z;
  int ka = -1, kb = -1;  // antenna blocks: +Aa on ka, −Ab on kb (kb may be −1)
  Mat3 Aa = Mat3::Zero(), Ab = Mat3::Zero();
  int group = 0;            // 0: time differences, 1: antenna differences (× 3 axes)
  std::size_t epoch = 0;    // the later epoch: when the row becomes available
  std::size_t epoch_a = 0;  // time differences: the earlier epoch (its fix enters with −1)
};

std::vector<RowBlock> lsq_rows(const std::vector<Epoch>& ep, std::size_t m, int lag) {
  std::vector<RowBlock> rows;
  // Median spacing of the fixes: pairs further apart than 5 lags are not differenced (gaps).
  std::vector<double> dt;
  for (std::size_t i = 1; i < ep.size(); ++i) dt.push_back(ep[i].t_s - ep[i - 1].t_s);
  double med = 1.0;
  if (!dt.empty()) {
    std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
    med = dt[dt.size() / 2];
  }
  for (std::size_t k = 0; k < m; ++k) {
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < ep.size(); ++i)
      if (ep[i].has[k]) idx.push_back(i);
    for (std::size_t j = static_cast<std::size_t>(lag); j < idx.size(); ++j) {
      const Epoch& a = ep[idx[j - static_cast<std::size_t>(lag)]];
      const Epoch& b = ep[idx[j]];
      if (b.t_s - a.t_s > 5.0 * lag * med) continue;
      RowBlock r;
      // ΔPₖ − ΔD = ΔR·lₖ, from (4.2) with P₀(t_b) − P₀(t_a) = ∫R·ν dτ (4.6).
      r.z = (b.p[k] - a.p[k]) - (b.D - a.D);
      r.ka = static_cast<int>(k);
      r.Aa = b.R - a.R;
      r.group = 0;
      r.epoch = idx[j];
      r.epoch_a = idx[j - static_cast<std::size_t>(lag)];
      rows.push_back(r);
    }
  }
  for (std::size_t k = 1; k < m; ++k) {
    for (std::size_t i = 0; i < ep.size(); ++i) {
      if (!ep[i].has[0] || !ep[i].has[k]) continue;
      RowBlock r;
      // Pₖ − P₁ = R·(lₖ − l₁), (4.2): P₀ cancels.
      r.z = ep[i].p[k] - ep[i].p[0];
      r.ka = static_cast<int>(k);
      r.Aa = ep[i].R;
      r.kb = 0;
      r.Ab = ep[i].R;
      r.group = 1;
      r.epoch = i;
      r.epoch_a = i;
      rows.push_back(r);
    }
  }
  return rows;
}

struct LsqSolution {
  bool ok = false;
  Eigen::VectorXd x;
  Eigen::MatrixXd normal_inv;  // (AᵀWA)⁻¹
  double dof_scale = 1.0;      // N_rows/(N_rows − n_params)
  double cost = kNaN;          // Σ_g n_g·log σ_g² (−2·log-likelihood up to a constant)
  std::array<double, 6> var{};
  std::array<std::size_t, 6> count{};
};

void accumulate(const RowBlock& r, const std::array<double, 6>& var, Eigen::MatrixXd& N,
                Eigen::VectorXd& b) {
  for (int ax = 0; ax < 3; ++ax) {
    const double w = 1.0 / var[static_cast<std::size_t>(3 * r.group + ax)];
    const Eigen::RowVector3d aa = r.Aa.row(ax);
    const int ia = 3 * r.ka;
    N.block<3, 3>(ia, ia) += w * aa.transpose() * aa;
    b.segment<3>(ia) += w * aa.transpose() * r.z(ax);
    if (r.kb >= 0) {
      const Eigen::RowVector3d ab = -r.Ab.row(ax);
      const int ib = 3 * r.kb;
      N.block<3, 3>(ib, ib) += w * ab.transpose() * ab;
      N.block<3, 3>(ia, ib) += w * aa.transpose() * ab;
      N.block<3, 3>(ib, ia) += w * ab.transpose() * aa;
      b.segment<3>(ib) += w * ab.transpose() * r.z(ax);
    }
  }
}

Vec3 predict(const RowBlock& r, const Eigen::VectorXd& x) {
  Vec3 y = r.Aa * x.segment<3>(3 * r.ka);
  if (r.kb >= 0) y -= r.Ab * x.segment<3>(3 * r.kb);
  return y;
}

bool solve_normal(const Eigen::MatrixXd& N, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                  Eigen::MatrixXd* cov) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(N);
  const Eigen::VectorXd ev = es.eigenvalues();
  if (!(ev(0) > 1e-10 * std::max(ev(ev.size() - 1), 1e-300))) return false;
  const Eigen::MatrixXd inv =
      es.eigenvectors() * ev.cwiseInverse().asDiagonal() * es.eigenvectors().transpose();
  x = inv * b;
  if (cov) *cov = inv;
  return true;
}

LsqSolution solve_lsq(const std::vector<RowBlock>& rows, std::size_t m) {
  LsqSolution s;
  const int n = static_cast<int>(3 * m);
  s.var.fill(1e-4);
  for (int iter = 0; iter < 4; ++iter) {
    Eigen::MatrixXd N = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    for (const RowBlock& r : rows) accumulate(r, s.var, N, b);
    if (!solve_normal(N, b, s.x, nullptr)) return s;
    // Residual variance per group and axis re-weights the rows (iterated to a fixed point).
    std::array<double, 6> ss{};
    s.count.fill(0);
    for (const RowBlock& r : rows) {
      const Vec3 e = r.z - predict(r, s.x);
      for (int ax = 0; ax < 3; ++ax) {
        const auto g = static_cast<std::size_t>(3 * r.group + ax);
        ss[g] += e(ax) * e(ax);
        ++s.count[g];
      }
    }
    for (std::size_t g = 0; g < 6; ++g)
      if (s.count[g] > 0) s.var[g] = std::max(ss[g] / static_cast<double>(s.count[g]), 1e-16);
  }
  s.cost = 0.0;
  for (std::size_t g = 0; g < 6; ++g)
    if (s.count[g] > 0) s.cost += static_cast<double>(s.count[g]) * std::log(s.var[g]);
  // Cov = (AᵀWA)⁻¹ with W = 1/σ_g² from the residuals: σ²·(AᵀA)⁻¹ per group.
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  for (const RowBlock& r : rows) accumulate(r, s.var, N, b);
  s.ok = solve_normal(N, b, s.x, &s.normal_inv);
  // The degrees of freedom: scale by N_rows/(N_rows − n_params).
  std::size_t nrows = 0;
  for (std::size_t c : s.count) nrows += c;
  if (nrows > static_cast<std::size_t>(n))
    s.dof_scale =
        static_cast<double>(nrows) / static_cast<double>(nrows - static_cast<std::size_t>(n));
  return s;
}

// Covariance of the arms for white fix noise. A fix enters every row it is differenced in (two
// time differences lag epochs apart, and the antenna differences of its epoch), so the rows are
// correlated and (AᵀWA)⁻¹ alone is not the covariance: it overstates the 1σ of what a slow
// turn shows (x, y) and understates that of what the wave roll and pitch show (z), whose ΔR
// changes sign between the two differences sharing a fix.
// With x = N⁻¹·Σ_r c_r·z_r (c_r = Aᵣᵀ·W) and each fix's noise n_s entering z_r with ±1,
// Cov = N⁻¹·(Σ_s σ_s²·h_s·h_sᵀ)·N⁻¹ with h_s = Σ_{r ∋ s} ±c_r. The fix variance per NED axis is
// half the time differences' residual variance (a difference of two fixes).
Eigen::MatrixXd fix_noise_covariance(const std::vector<RowBlock>& rows, const LsqSolution& s,
                                     std::size_t m, std::size_t n_epochs) {
  const long n = static_cast<long>(3 * m);
  // One column per fix and axis: (antenna, epoch, axis).
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, static_cast<long>(3 * m * n_epochs));
  const auto column = [&](int k, std::size_t e, int ax) {
    return static_cast<long>((static_cast<std::size_t>(k) * n_epochs + e) * 3) + ax;
  };
  for (const RowBlock& r : rows) {
    for (int ax = 0; ax < 3; ++ax) {
      const double w = 1.0 / s.var[static_cast<std::size_t>(3 * r.group + ax)];
      Eigen::VectorXd c = Eigen::VectorXd::Zero(n);
      c.segment<3>(3 * r.ka) = w * r.Aa.row(ax).transpose();
      if (r.kb >= 0) c.segment<3>(3 * r.kb) -= w * r.Ab.row(ax).transpose();
      // Time difference: +fix(ka, epoch) − fix(ka, epoch_a); antenna difference: +fix(ka) −
      // fix(kb) at one epoch.
      h.col(column(r.ka, r.epoch, ax)) += c;
      h.col(column(r.group == 0 ? r.ka : r.kb, r.epoch_a, ax)) -= c;
    }
  }
  Eigen::MatrixXd middle = Eigen::MatrixXd::Zero(n, n);
  for (int ax = 0; ax < 3; ++ax) {
    const double fix_var = 0.5 * s.var[static_cast<std::size_t>(ax)];
    for (std::size_t k = 0; k < m; ++k)
      for (std::size_t e = 0; e < n_epochs; ++e) {
        const auto col = h.col(column(static_cast<int>(k), e, ax));
        middle.noalias() += fix_var * col * col.transpose();
      }
  }
  return s.dof_scale * s.normal_inv * middle * s.normal_inv;
}

double lsq_cost_at(const MotionInterp& mi, const std::vector<GnssSeries>& ant, double offset,
                   int lag) {
  const std::vector<Epoch> ep = make_epochs(mi, ant, offset);
  const LsqSolution s = solve_lsq(lsq_rows(ep, ant.size(), lag), ant.size());
  if (!s.ok) return kNaN;
  // Compare costs over the same number of rows: normalise to the mean per row.
  std::size_t n = 0;
  for (std::size_t c : s.count) n += c;
  return s.cost / static_cast<double>(std::max<std::size_t>(n, 1));
}

double median_spacing(const std::vector<Epoch>& ep) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < ep.size(); ++i) dt.push_back(ep[i].t_s - ep[i - 1].t_s);
  if (dt.empty()) return 1.0;
  std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

// Luenberger observer (4.26): x̂ = [P̂₀; l̂₁ … l̂_m]. Between fixes the prediction B(t)ν is
// integrated exactly, P̂₀ += ΔD; each fix's correction W·C(t)ᵀ·(y − C(t)x̂) is applied as the
// continuous law over the fix interval with the fix held (sub-stepped for stability).
void run_luenberger(const std::vector<Epoch>& ep, const GnssArmOptions& o, std::vector<Vec3>& arms,
                    GnssArmResult& res) {
  const std::size_t m = arms.size();
  const double dt = median_spacing(ep);
  const double wmax = std::max(o.luenberger_w_p0.maxCoeff(), o.luenberger_w_arm.maxCoeff());
  const int nsub = std::max(1, static_cast<int>(std::ceil(dt * wmax * double(m + 1) / 0.2)));
  Vec3 p0 = Vec3::Zero();
  if (o.initial_p0_n_m) {
    p0 = *o.initial_p0_n_m;
  } else {
    res.notes.push_back(
        "luenberger: P0 started from the first fixes and the initial arms; its start error "
        "R(0)·(l − l̂(0)) is invisible to the fixes at t = 0 and W1 removes it slowly, so the "
        "arms are only as good as the initial arms unless the maneuver is long. Give the "
        "initial P0 (--init-p0) when it is known, or use lsq");
    int c = 0;
    for (std::size_t k = 0; k < m; ++k)
      if (ep[0].has[k]) {
        p0 += ep[0].p[k] - ep[0].R * arms[k];
        ++c;
      }
    p0 /= std::max(c, 1);
  }
  for (std::size_t i = 0; i < ep.size(); ++i) {
    const Epoch& e = ep[i];
    if (i > 0) p0 += e.D - ep[i - 1].D;  // (4.6) integrated
    const double span = i + 1 < ep.size() ? std::min(ep[i + 1].t_s - e.t_s, 5.0 * dt) : dt;
    const double h = span / nsub;
    for (int s = 0; s < nsub; ++s) {
      Vec3 dp0 = Vec3::Zero();
      for (std::size_t k = 0; k < m; ++k) {
        if (!e.has[k]) continue;
        const Vec3 ytil = e.p[k] - p0 - e.R * arms[k];  // ỹ = C(t)x̃ (4.27)
        dp0 += ytil;
        arms[k] += h * o.luenberger_w_arm.cwiseProduct(e.R.transpose() * ytil);
      }
      p0 += h * o.luenberger_w_p0.cwiseProduct(dp0);
    }
    res.t_s.push_back(e.t_s);
    res.p0_n_m.push_back(p0);
    for (std::size_t k = 0; k < m; ++k) res.arm_history_b_m[k].push_back(arms[k]);
  }
}

// Adaptive observer (4.42), (4.48): x̂ = [P̂_GNSS1 … P̂_GNSSm], φ̂ = [l̂₁ … l̂_m]. Between fixes
// the prediction R·ν + R·S·φ̂ is integrated exactly, ΔD + ΔR·φ̂ (Ṙ = R·S, (2.5)); each fix's
// correction L·x̃ and Γ·Ωᵀ·x̃ (Ω = R·S, (4.41)) is applied over the fix interval, fix held.
void run_adaptive(const std::vector<Epoch>& ep, const GnssArmOptions& o, std::vector<Vec3>& arms,
                  GnssArmResult& res) {
  const std::size_t m = arms.size();
  const double dt = median_spacing(ep);
  double wmax2 = 0.0, wmean2 = 0.0;
  for (const Epoch& e : ep) {
    wmax2 = std::max(wmax2, e.omega.squaredNorm());
    wmean2 += e.omega.squaredNorm() / static_cast<double>(ep.size());
  }
  Vec3 gamma;
  if (o.adaptive_gamma) {
    gamma = *o.adaptive_gamma;
  } else {
    // Arm error rate ≈ Γ·E|ω|²/L: pick Γ for the requested rate (floor: 1e-6 rad²/s², a
    // vessel at rest, where nothing is observable anyway).
    gamma = o.adaptive_rate_per_s * o.adaptive_l / std::max(wmean2, 1e-6);
    res.notes.push_back(fmt::format(
        "adaptive gain Γ = {:.4g}, {:.4g}, {:.4g} from E|ω|² = {:.3g} rad²/s² and rate {} 1/s",
        gamma(0), gamma(1), gamma(2), wmean2, o.adaptive_rate_per_s));
  }
  res.adaptive_gamma = gamma;
  const double rate = std::max(o.adaptive_l.maxCoeff(), gamma.maxCoeff() * wmax2);
  const int nsub = std::max(1, static_cast<int>(std::ceil(dt * rate / 0.2)));
  std::vector<Vec3> xhat(m, Vec3::Constant(kNaN));
  for (std::size_t i = 0; i < ep.size(); ++i) {
    const Epoch& e = ep[i];
    for (std::size_t k = 0; k < m; ++k) {
      if (!std::isfinite(xhat[k](0))) {
        if (e.has[k]) xhat[k] = e.p[k];
        continue;
      }
      if (i > 0) xhat[k] += (e.D - ep[i - 1].D) + (e.R - ep[i - 1].R) * arms[k];
    }
    const double span = i + 1 < ep.size() ? std::min(ep[i + 1].t_s - e.t_s, 5.0 * dt) : dt;
    const double h = span / nsub;
    const Mat3 omega = e.R * core::skew(e.omega);  // Ω block (4.41)
    for (int s = 0; s < nsub; ++s) {
      for (std::size_t k = 0; k < m; ++k) {
        if (!e.has[k] || !std::isfinite(xhat[k](0))) continue;
        const Vec3 xt = e.p[k] - xhat[k];  // x̃ with C = I (4.39)
        xhat[k] += h * o.adaptive_l.cwiseProduct(xt);
        arms[k] += h * gamma.cwiseProduct(omega.transpose() * xt);  // (4.48)
      }
    }
    Vec3 p0 = Vec3::Zero();
    int c = 0;
    for (std::size_t k = 0; k < m; ++k)
      if (std::isfinite(xhat[k](0))) {
        p0 += xhat[k] - e.R * arms[k];  // (4.32)
        ++c;
      }
    res.t_s.push_back(e.t_s);
    res.p0_n_m.push_back(c > 0 ? Vec3(p0 / c) : Vec3::Constant(kNaN));
    for (std::size_t k = 0; k < m; ++k) res.arm_history_b_m[k].push_back(arms[k]);
  }
}

// Problems of the inputs that leave nothing to estimate, as a message ("" when there is none);
// throws std::invalid_argument for inputs no caller should pass.
std::string input_problem(const MotionSeries& motion, const std::vector<GnssSeries>& antennas,
                          const GnssArmOptions& options) {
  const std::size_t m = antennas.size();
  if (m == 0) return "no GNSS antenna given";
  if (!options.initial_arms_b_m.empty() && options.initial_arms_b_m.size() != m)
    throw std::invalid_argument("GnssArmOptions: initial_arms_b_m needs one arm per antenna");
  if (motion.size() < 3 || motion.v_b_mps.size() != motion.size() ||
      motion.omega_b_rps.size() != motion.size()) {
    return "the motion needs attitude, angular rates and velocity, at least 3 samples";
  }
  for (const GnssSeries& a : antennas) {
    if (a.t_s.size() != a.p_n_m.size())
      throw std::invalid_argument("GnssSeries " + a.name + ": t_s and p_n_m differ in size");
  }
  return {};
}

// The time offset δ: profile of the least-squares cost over δ, a coarse grid over ±max, a fine
// grid around its best point, and a parabola through the best three. Fills the scan and the 1σ
// of δ into `res`.
double estimate_time_offset(const MotionInterp& mi, const std::vector<GnssSeries>& antennas,
                            const GnssArmOptions& options, GnssArmResult& res) {
  const std::size_t m = antennas.size();
  const int lag = options.lag_epochs;
  const double step = options.time_offset_step_s;
  const double coarse = std::min(5.0 * step, options.max_time_offset_s);
  auto scan = [&](double lo, double hi, double st) {
    for (double d = lo; d <= hi + 1e-12; d += st) {
      const double c = lsq_cost_at(mi, antennas, d, lag);
      res.offset_scan_s.push_back(d);
      res.offset_scan_cost.push_back(c);
    }
  };
  scan(-options.max_time_offset_s, options.max_time_offset_s, coarse);
  const double c0 = res.offset_scan_s[detail::best_offset_index(res.offset_scan_cost)];
  scan(c0 - coarse, c0 + coarse, step);
  // Sorted by δ for the parabola and for the caller's plot.
  detail::sort_offset_scan(res.offset_scan_s, res.offset_scan_cost);
  const std::size_t best = detail::best_offset_index(res.offset_scan_cost);
  const auto refined = detail::refine_offset(res.offset_scan_s, res.offset_scan_cost, best);
  if (!refined) return res.offset_scan_s[best];
  // cost per row ≈ −2·log L / N: var(δ) = 2 / (N·c'').
  std::size_t nrows = 0;
  {
    const LsqSolution s =
        solve_lsq(lsq_rows(make_epochs(mi, antennas, refined->offset_s), m, lag), m);
    for (std::size_t c : s.count) nrows += c;
  }
  res.time_offset_std_s = std::sqrt(2.0 / (static_cast<double>(nrows) * refined->curvature));
  return refined->offset_s;
}

// The growing-window least-squares solution at every epoch, with the final weights `var`: the
// history plot of the least-squares arms.
void lsq_history(const std::vector<RowBlock>& rows, const std::array<double, 6>& var,
                 const std::vector<Epoch>& ep, std::size_t m, GnssArmResult& res) {
  const int n = static_cast<int>(3 * m);
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  std::vector<std::size_t> order(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t c) { return rows[a].epoch < rows[c].epoch; });
  std::size_t ri = 0;
  for (std::size_t i = 0; i < ep.size(); ++i) {
    while (ri < order.size() && rows[order[ri]].epoch <= i)
      accumulate(rows[order[ri++]], var, N, b);
    Eigen::VectorXd x;
    const bool good = solve_normal(N, b, x, nullptr);
    res.t_s.push_back(ep[i].t_s);
    for (std::size_t k = 0; k < m; ++k)
      res.arm_history_b_m[k].push_back(good ? Vec3(x.segment<3>(static_cast<long>(3 * k)))
                                            : Vec3::Constant(kNaN));
  }
}

// Batch least squares: the arms, their covariance for white fix noise and the history. False
// when the normal equations are singular.
bool run_lsq(const std::vector<Epoch>& ep, int lag, std::vector<Vec3>& arms, Eigen::MatrixXd& cov,
             GnssArmResult& res) {
  const std::size_t m = arms.size();
  const std::vector<RowBlock> rows = lsq_rows(ep, m, lag);
  const LsqSolution s = solve_lsq(rows, m);
  if (!s.ok) return false;
  for (std::size_t k = 0; k < m; ++k) arms[k] = s.x.segment<3>(static_cast<long>(3 * k));
  cov = fix_noise_covariance(rows, s, m, ep.size());
  lsq_history(rows, s.var, ep, m, res);
  return true;
}

// The converged interval and the reported arms: least squares its solution and own 1σ, the
// observers mean and std over the interval; each component's verdict from the excitation.
void report_arms(const MotionSeries& motion, const std::vector<GnssSeries>& antennas,
                 const GnssArmOptions& options, const std::vector<Epoch>& ep,
                 const std::vector<Vec3>& arms, const Eigen::MatrixXd& cov, GnssArmResult& res) {
  const double t0 = ep.front().t_s;
  const double t1 = ep.back().t_s;
  res.converged_from_s = t0 + options.converged_from_fraction * (t1 - t0);
  res.converged_to_s = t1;
  res.excitation = excitation_diagnostics(motion, options.excitation);
  for (std::size_t k = 0; k < antennas.size(); ++k) {
    const detail::IntervalStats stats =
        detail::interval_statistics(res.t_s, res.arm_history_b_m[k], res.converged_from_s);
    res.interval_mean_b_m.push_back(stats.mean);
    res.interval_std_b_m.push_back(stats.std);
    ArmEstimate a;
    a.name = antennas[k].name;
    if (options.method == GnssArmMethod::kLsq) {
      a.l_b_m = arms[k];
      for (int j = 0; j < 3; ++j) a.std_m(j) = std::sqrt(cov(3 * long(k) + j, 3 * long(k) + j));
    } else {
      a.l_b_m = stats.mean;
      a.std_m = res.interval_std_b_m.back();
    }
    for (int j = 0; j < 3; ++j)
      a.determinacy[j] = worse(res.excitation.verdict[static_cast<std::size_t>(j)],
                               determinacy_from_std(a.std_m(j), options.excitation.verdict));
    res.arms.push_back(a);
  }
}

// P₀ from the fixes with the reported arms (4.32) (least squares: also the P₀ track, the mean
// offset plus the integrated velocity), and the rms residual of the model (4.2).
void p0_and_residuals(const std::vector<Epoch>& ep, GnssArmMethod method, GnssArmResult& res) {
  const std::size_t m = res.arms.size();
  Vec3 c_sum = Vec3::Zero();
  int c_n = 0;
  for (const Epoch& e : ep) {
    Vec3 p = Vec3::Zero();
    int c = 0;
    for (std::size_t k = 0; k < m; ++k)
      if (e.has[k]) {
        p += e.p[k] - e.R * res.arms[k].l_b_m;
        ++c;
      }
    const Vec3 pm = c > 0 ? Vec3(p / c) : Vec3::Constant(kNaN);
    res.p0_measured_n_m.push_back(pm);
    if (c > 0) {
      c_sum += pm - e.D;
      ++c_n;
    }
  }
  const Vec3 c0 = c_sum / std::max(c_n, 1);
  if (method == GnssArmMethod::kLsq) {
    for (const Epoch& e : ep) res.p0_n_m.push_back(c0 + e.D);
  }
  Vec3 ss = Vec3::Zero();
  int nres = 0;
  for (std::size_t i = 0; i < ep.size(); ++i) {
    // An observer's start transient is not a model residual: its interval only.
    if (method != GnssArmMethod::kLsq && ep[i].t_s < res.converged_from_s) continue;
    for (std::size_t k = 0; k < m; ++k)
      if (ep[i].has[k] && res.p0_n_m[i].allFinite()) {
        const Vec3 e = ep[i].p[k] - res.p0_n_m[i] - ep[i].R * res.arms[k].l_b_m;
        ss += e.cwiseProduct(e);
        ++nres;
      }
  }
  res.residual_rms_n_m = (ss / std::max(nres, 1)).cwiseSqrt();
}

}  // namespace

std::string_view gnss_arm_method_name(GnssArmMethod m) {
  switch (m) {
    case GnssArmMethod::kLuenberger:
      return "luenberger";
    case GnssArmMethod::kAdaptive:
      return "adaptive";
    case GnssArmMethod::kLsq:
      return "lsq";
  }
  return "lsq";
}

void GnssArmOptions::validate() const {
  auto pos = [](const Vec3& v) { return (v.array() > 0.0).all() && v.allFinite(); };
  if (!pos(luenberger_w_p0) || !pos(luenberger_w_arm))
    throw std::invalid_argument("GnssArmOptions: Luenberger gains W1, W2 must be > 0");
  if (!pos(adaptive_l) || (adaptive_gamma && !pos(*adaptive_gamma)))
    throw std::invalid_argument("GnssArmOptions: adaptive gains L, Gamma must be > 0");
  if (!(adaptive_rate_per_s > 0.0) || !std::isfinite(adaptive_rate_per_s))
    throw std::invalid_argument("GnssArmOptions: adaptive_rate_per_s must be > 0");
  if (lag_epochs < 1) throw std::invalid_argument("GnssArmOptions: lag_epochs must be >= 1");
  if (!std::isfinite(time_offset_s))
    throw std::invalid_argument("GnssArmOptions: time_offset_s must be finite");
  if (!(max_time_offset_s > 0.0) || !(time_offset_step_s > 0.0) ||
      time_offset_step_s > max_time_offset_s)
    throw std::invalid_argument("GnssArmOptions: need 0 < time_offset_step_s <= max_time_offset_s");
  if (!(converged_from_fraction >= 0.0 && converged_from_fraction < 1.0))
    throw std::invalid_argument("GnssArmOptions: converged_from_fraction must be in [0, 1)");
  for (const Vec3& a : initial_arms_b_m)
    if (!a.allFinite()) throw std::invalid_argument("GnssArmOptions: initial arm not finite");
  excitation.validate();
}

GnssArmResult estimate_gnss_arms(const MotionSeries& motion,
                                 const std::vector<GnssSeries>& antennas,
                                 const GnssArmOptions& options) {
  options.validate();
  GnssArmResult res;
  res.method = options.method;
  res.message = input_problem(motion, antennas, options);
  if (!res.message.empty()) return res;
  const std::size_t m = antennas.size();
  const MotionInterp mi(motion);
  const int lag = options.lag_epochs;

  double offset = options.time_offset_s;
  res.time_offset_std_s = kNaN;
  if (options.estimate_time_offset) {
    offset = estimate_time_offset(mi, antennas, options, res);
    res.time_offset_estimated = true;
  }
  res.time_offset_s = offset;

  const std::vector<Epoch> ep = make_epochs(mi, antennas, offset);
  res.epochs_used = ep.size();
  if (ep.size() < static_cast<std::size_t>(lag) + 3) {
    res.message = "only " + std::to_string(ep.size()) +
                  " GNSS fixes fall inside the motion's time span: need at least " +
                  std::to_string(lag + 3);
    return res;
  }
  res.arm_history_b_m.assign(m, {});
  std::vector<Vec3> arms(m, Vec3::Zero());
  if (!options.initial_arms_b_m.empty()) arms = options.initial_arms_b_m;

  Eigen::MatrixXd cov;
  if (options.method == GnssArmMethod::kLsq) {
    if (!run_lsq(ep, lag, arms, cov, res)) {
      res.message =
          "the least-squares problem is singular: the maneuver does not rotate the vessel "
          "enough to see the arms (see the excitation diagnostics)";
      return res;
    }
  } else if (options.method == GnssArmMethod::kLuenberger) {
    run_luenberger(ep, options, arms, res);
  } else {
    run_adaptive(ep, options, arms, res);
  }
  report_arms(motion, antennas, options, ep, arms, cov, res);
  p0_and_residuals(ep, options.method, res);
  if (m == 1)
    res.notes.emplace_back(
        "one antenna: P0 and the arm are estimated together (thesis case study 2); the arm is "
        "from the point whose velocity u, v, w is logged");
  res.status = core::Status::kOk;
  res.message = "ok";
  return res;
}

namespace detail {

std::size_t best_offset_index(const std::vector<double>& cost_per_row) {
  std::size_t b = 0;
  for (std::size_t i = 0; i < cost_per_row.size(); ++i)
    if (std::isfinite(cost_per_row[i]) &&
        (!std::isfinite(cost_per_row[b]) || cost_per_row[i] < cost_per_row[b]))
      b = i;
  return b;
}

void sort_offset_scan(std::vector<double>& offset_s, std::vector<double>& cost_per_row) {
  std::vector<std::size_t> order(offset_s.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return offset_s[a] < offset_s[b]; });
  std::vector<double> xs, cs;
  for (std::size_t i : order) {
    if (!xs.empty() && std::abs(offset_s[i] - xs.back()) < 1e-9) continue;
    xs.push_back(offset_s[i]);
    cs.push_back(cost_per_row[i]);
  }
  offset_s = xs;
  cost_per_row = cs;
}

std::optional<OffsetRefinement> refine_offset(const std::vector<double>& xs,
                                              const std::vector<double>& cs, std::size_t bi) {
  if (!(bi > 0 && bi + 1 < xs.size() && std::isfinite(cs[bi - 1]) && std::isfinite(cs[bi + 1])))
    return std::nullopt;
  const double h1 = xs[bi] - xs[bi - 1];
  const double h2 = xs[bi + 1] - xs[bi];
  if (!(std::abs(h1 - h2) < 1e-9)) return std::nullopt;
  const double curv = (cs[bi + 1] - 2.0 * cs[bi] + cs[bi - 1]) / (h1 * h1);
  if (!(curv > 0.0)) return std::nullopt;
  double offset =
      xs[bi] - h1 * (cs[bi + 1] - cs[bi - 1]) / (2.0 * (cs[bi + 1] - 2.0 * cs[bi] + cs[bi - 1]));
  offset = std::clamp(offset, xs[bi] - h1, xs[bi] + h1);
  return OffsetRefinement{offset, curv};
}

IntervalStats interval_statistics(const std::vector<double>& t_s,
                                  const std::vector<Eigen::Vector3d>& history, double from_s) {
  Vec3 sum = Vec3::Zero();
  Vec3 sq = Vec3::Zero();
  int c = 0;
  for (std::size_t i = 0; i < t_s.size(); ++i) {
    const Vec3& a = history[i];
    if (t_s[i] < from_s || !a.allFinite()) continue;
    sum += a;
    sq += a.cwiseProduct(a);
    ++c;
  }
  const Vec3 mean = c > 0 ? Vec3(sum / c) : Vec3::Constant(kNaN);
  const Vec3 var = c > 1 ? Vec3(((sq - c * mean.cwiseProduct(mean)) / (c - 1)).cwiseMax(0.0))
                         : Vec3::Constant(kNaN);
  return {mean, var.cwiseSqrt()};
}

}  // namespace detail
}  // namespace dynpos::calib
