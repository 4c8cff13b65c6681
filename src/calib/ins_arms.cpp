#include "dynpos/calib/ins_arms.hpp"

#include <fmt/format.h>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "dynpos/calib/attitude_smoother.hpp"
#include "dynpos/core/time_spacing.hpp"
#include "ins_problem.hpp"

namespace dynpos::calib {
namespace {

using Vec3 = Eigen::Vector3d;
using detail::InsFix;
using detail::InsKnots;
using detail::InsProblem;
using SpMat = Eigen::SparseMatrix<double>;

// N = JᵀJ, its lower triangle (all SimplicialLDLT reads). A row-major J is a column-major Jᵀ
// in the same storage: mapped, not copied.
SpMat normal_matrix(const Eigen::SparseMatrix<double, Eigen::RowMajor>& J) {
  const Eigen::Map<const SpMat> Jt(J.cols(), J.rows(), J.nonZeros(), J.outerIndexPtr(),
                                   J.innerIndexPtr(), J.valuePtr());
  SpMat N(J.cols(), J.cols());
  N.selfadjointView<Eigen::Lower>().rankUpdate(Jt);
  return N;
}
using Ldlt = Eigen::SimplicialLDLT<SpMat>;

// Knots every fix interval (the shortest median spacing of the antennas, at least
// knot_spacing_s), starting at the first fix that lies, with any offset δ within its bound,
// inside the MRU's time; each fix is evaluated from its nearest knot.
struct FixPlan {
  InsKnots knots;
  std::vector<InsFix> fixes;
};

FixPlan plan_fixes(const detail::InsPreintegration& ins, const std::vector<GnssSeries>& gnss,
                   const InsArmOptions& o) {
  const double margin = o.estimate_time_offset ? o.max_time_offset_s : 0.0;
  const double lo = ins.t_begin() + margin, hi = ins.t_end() - margin;
  FixPlan plan;
  plan.knots.h_s = 1e9;  // the shortest fix spacing, but at least knot_spacing_s
  double first = 1e300, last = -1e300;
  for (const GnssSeries& g : gnss) {
    plan.knots.h_s = std::min(plan.knots.h_s, core::median_spacing_s(g.t_s, 1));
    for (double t : g.t_s) {
      const double s = t - o.time_offset_s;
      if (s < lo || s > hi) continue;
      first = std::min(first, s);
      last = std::max(last, s);
    }
  }
  plan.knots.h_s = std::max(plan.knots.h_s, o.knot_spacing_s);
  if (!(last > first)) return plan;
  plan.knots.t0_s = first;
  const double h = plan.knots.h_s;
  plan.knots.count = static_cast<std::size_t>(std::floor((last - first) / h + 0.5)) + 1;
  while (plan.knots.count > 2 && plan.knots.time(plan.knots.count - 1) > ins.t_end())
    --plan.knots.count;
  for (std::size_t k = 0; k < gnss.size(); ++k)
    for (std::size_t i = 0; i < gnss[k].t_s.size(); ++i) {
      const double s = gnss[k].t_s[i] - o.time_offset_s;
      if (s < lo || s > hi) continue;
      const double m =
          std::clamp(std::round((s - first) / h), 0.0, static_cast<double>(plan.knots.count - 1));
      plan.fixes.push_back({k, static_cast<std::size_t>(m), gnss[k].t_s[i], gnss[k].p_n_m[i]});
    }
  return plan;
}

// Row ranges of one residual group: every fix row of antenna k on the horizontal (N, E) or
// the vertical axis, or the process rows.
std::vector<long> group_rows(const InsProblem& p, int group, std::size_t antenna) {
  std::vector<long> rows;
  if (group == 0) {
    for (std::size_t i = 0; i < p.process_rows(); ++i) rows.push_back(static_cast<long>(i));
    return rows;
  }
  for (std::size_t j = 0; j < p.fixes().size(); ++j) {
    if (p.fixes()[j].antenna != antenna) continue;
    const auto r = static_cast<long>(p.fix_row(j));
    if (group == 1) {
      rows.push_back(r);
      rows.push_back(r + 1);
    } else {
      rows.push_back(r + 2);
    }
  }
  return rows;
}

// The redundancy n_g − tr(H_g) of each residual group g, H = J·N⁻¹·Jᵀ the hat matrix, by one
// set of Rademacher probes w over all rows (Hutchinson): E[Σ_{i∈g} wᵢ·(H·w)ᵢ] = Σ_{i∈g} Hᵢᵢ,
// so every group's trace comes from the same solves. A fixed seed: the same data give the
// same figures.
std::vector<double> redundancies(const Eigen::SparseMatrix<double, Eigen::RowMajor>& J,
                                 const Ldlt& ldlt, const std::vector<std::vector<long>>& groups,
                                 int probes) {
  std::mt19937_64 rng(20261126);
  std::vector<double> trace(groups.size(), 0.0);
  Eigen::VectorXd w(J.rows());
  for (int k = 0; k < probes; ++k) {
    for (long i = 0; i < w.size(); ++i) w[i] = (rng() & 1U) ? 1.0 : -1.0;
    const Eigen::VectorXd hw = J * ldlt.solve(Eigen::VectorXd(J.transpose() * w));
    for (std::size_t g = 0; g < groups.size(); ++g)
      for (long i : groups[g]) trace[g] += w[i] * hw[i];
  }
  std::vector<double> out(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g)
    out[g] = static_cast<double>(groups[g].size()) - trace[g] / probes;
  return out;
}

double sum_sq(const Eigen::VectorXd& r, const std::vector<long>& rows) {
  double s = 0.0;
  for (long i : rows) s += r[i] * r[i];
  return s;
}

// Divides the rows `rows` of J and r by f: the linearisation with that group's σ times f.
void scale_rows(InsProblem::Linearised& lin, const std::vector<long>& rows, double f) {
  for (long r : rows) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(lin.J, r); it; ++it)
      it.valueRef() /= f;
    lin.r[r] /= f;
  }
}

// One pass of variance components on the linearisation `lin` at the current solution: each
// group's σ scaled by √(RSS / redundancy), in the weights and in `lin` (which then holds the
// problem with the new weights at the same point, for the covariance).
void update_weights(InsProblem& p, const InsArmOptions& o, std::size_t antennas,
                    InsProblem::Linearised& lin) {
  const SpMat N = normal_matrix(lin.J);
  const Ldlt ldlt(N);
  if (ldlt.info() != Eigen::Success) return;
  std::vector<std::vector<long>> groups = {group_rows(p, 0, 0)};
  for (std::size_t k = 0; k < antennas; ++k) {
    groups.push_back(group_rows(p, 1, k));
    groups.push_back(group_rows(p, 2, k));
  }
  const std::vector<double> red = redundancies(lin.J, ldlt, groups, o.trace_probes);
  auto factor = [&](std::size_t g) {
    if (!(red[g] > 0.05 * static_cast<double>(groups[g].size()))) return 1.0;
    return std::clamp(std::sqrt(sum_sq(lin.r, groups[g]) / red[g]), 0.1, 10.0);
  };
  std::vector<double> f(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) f[g] = factor(g);
  p.weights().process /= f[0];
  for (std::size_t k = 0; k < antennas; ++k) {
    p.weights().horizontal[k] /= f[1 + 2 * k];
    p.weights().vertical[k] /= f[2 + 2 * k];
  }
  for (std::size_t g = 0; g < groups.size(); ++g) scale_rows(lin, groups[g], f[g]);
}

}  // namespace

void InsArmOptions::validate() const {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw std::invalid_argument(std::string("InsArmOptions: ") + name + " must be > 0");
  };
  positive(max_time_offset_s, "max_time_offset_s");
  positive(attitude_window_s, "attitude_window_s");
  positive(knot_spacing_s, "knot_spacing_s");
  positive(gnss_horizontal_std_m, "gnss_horizontal_std_m");
  positive(gnss_vertical_std_m, "gnss_vertical_std_m");
  positive(arm_prior_std_m, "arm_prior_std_m");
  if (!(accel_bias_prior_std_mps2 > 0.0))
    throw std::invalid_argument("InsArmOptions: accel_bias_prior_std_mps2 must be > 0");
  if (!std::isfinite(time_offset_s))
    throw std::invalid_argument("InsArmOptions: time_offset_s must be finite");
  if (estimate_time_offset && std::abs(time_offset_s) > max_time_offset_s)
    throw std::invalid_argument("InsArmOptions: |time_offset_s| beyond max_time_offset_s");
  if (variance_iterations < 0 || variance_iterations > 20)
    throw std::invalid_argument("InsArmOptions: variance_iterations must be in [0, 20]");
  if (trace_probes < 1 || trace_probes > 1000)
    throw std::invalid_argument("InsArmOptions: trace_probes must be in [1, 1000]");
  verdict.validate();
}

namespace {

// The covariance of the global parameters (arms, b, δ) from `lin` (the problem with the final
// weights, linearised at the solution or at the one before the last Gauss–Newton step: the
// problem is linear but for δ), and the result's figures at the solution.
void fill_result(InsProblem& p, const InsArmOptions& o, const std::vector<GnssSeries>& gnss,
                 const InsProblem::Linearised& lin, InsArmResult& out) {
  const SpMat N = normal_matrix(lin.J);
  const Ldlt ldlt(N);
  const auto g0 = static_cast<long>(p.global_col());
  const long ng = static_cast<long>(p.columns()) - g0;
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(N.rows(), ng);
  for (long i = 0; i < ng; ++i) E(g0 + i, i) = 1.0;
  const Eigen::MatrixXd X = ldlt.solve(E);
  const Eigen::MatrixXd cov = X.bottomRows(ng);
  const Vec3 offset = o.imu_arm_b_m.value_or(Vec3::Zero());
  for (std::size_t k = 0; k < gnss.size(); ++k) {
    ArmEstimate a;
    a.name = gnss[k].name;
    a.l_b_m = p.arm(k) + offset;
    for (int i = 0; i < 3; ++i) {
      const long c = static_cast<long>(3 * k) + i;
      a.std_m[i] = std::sqrt(std::max(0.0, cov(c, c)));
      a.determinacy[i] = determinacy_from_std(a.std_m[i], o.verdict);
    }
    out.arms.push_back(a);
  }
  const long cb = static_cast<long>(3 * gnss.size());
  out.accel_bias_b_mps2 = p.bias();
  for (int i = 0; i < 3; ++i)
    out.accel_bias_std_mps2[i] = std::sqrt(std::max(0.0, cov(cb + i, cb + i)));
  out.time_offset_s = p.time_offset();
  out.time_offset_estimated = p.offset_estimated();
  if (p.offset_estimated()) out.time_offset_std_s = std::sqrt(std::max(0.0, cov(cb + 3, cb + 3)));
  std::vector<Vec3> ss(gnss.size(), Vec3::Zero());
  std::vector<double> n(gnss.size(), 0.0);
  out.residual_t_s.resize(gnss.size());
  out.residual_n_m.resize(gnss.size());
  const Eigen::VectorXd r = p.residuals();
  for (std::size_t j = 0; j < p.fixes().size(); ++j) {
    const Vec3 e = p.fix_residual_m(r, j);
    const std::size_t k = p.fixes()[j].antenna;
    ss[k] += e.cwiseProduct(e);
    n[k] += 1.0;
    out.residual_t_s[k].push_back(p.fixes()[j].t_s);
    out.residual_n_m[k].push_back(e);
  }
  for (std::size_t k = 0; k < gnss.size(); ++k) {
    out.residual_rms_n_m.push_back((ss[k] / std::max(1.0, n[k])).cwiseSqrt());
    out.noise.gnss_horizontal_std_m.push_back(1.0 / p.weights().horizontal[k]);
    out.noise.gnss_vertical_std_m.push_back(1.0 / p.weights().vertical[k]);
  }
}

// Per axis, for the worst antenna: what the maneuver lacked. A horizontal arm shows only as
// the heading changes, and in a steady turn a BODY accelerometer bias b integrates to the same
// rotating offset R(ψ)·b/r² as an arm: the turn rate has to change too.
void add_advice(InsArmResult& out) {
  static const char* const kAxis[3] = {"x", "y", "z"};
  static const char* const kNeed[3] = {
      "turn through more heading, at a changing rate (turns both ways or a zig-zag), or for "
      "longer",
      "turn through more heading, at a changing rate (turns both ways or a zig-zag), or for "
      "longer",
      "more roll or pitch needed (a beam or head sea, or a zig-zag)"};
  for (int axis = 0; axis < 3; ++axis) {
    Determinacy worst = Determinacy::kWell;
    for (const ArmEstimate& a : out.arms) worst = worse(worst, a.determinacy[axis]);
    if (worst == Determinacy::kWell) continue;
    out.advice.push_back(
        fmt::format("{} is {} determined: {}", kAxis[axis], determinacy_name(worst), kNeed[axis]));
  }
}

}  // namespace

InsArmResult estimate_ins_arms(const ImuSeries& imu, const std::vector<GnssSeries>& gnss,
                               const InsArmOptions& o) {
  o.validate();
  InsArmResult out;
  out.reference = o.imu_arm_b_m ? "co" : imu.name;
  if (gnss.empty() || imu.size() < 3) {
    out.message = "no antenna or too few MRU samples";
    return out;
  }
  const SmoothedAttitude att =
      smooth_attitude(imu, std::max(o.attitude_window_s, 10.0 * imu.heading_spacing_s));
  out.euler_rate_bias_rps = att.euler_rate_bias_rps;
  const detail::InsPreintegration ins(imu, att.theta_rad, kMruGravity_mps2);
  FixPlan plan = plan_fixes(ins, gnss, o);
  if (plan.knots.count < 10 || plan.fixes.size() < 10) {
    out.message = fmt::format(
        "{} fixes lie inside the MRU's time ({:.1f} … {:.1f} s); at least 10 are needed",
        plan.fixes.size(), ins.t_begin(), ins.t_end());
    return out;
  }
  out.knots = plan.knots.count;
  out.fixes = plan.fixes.size();
  out.noise.accel_std_mps2 = white_noise_std(imu.accel_b_mps2);
  const double dt = core::median_spacing_s(imu.t_s, 1);
  const double sigma_a = std::max(out.noise.accel_std_mps2.norm() / std::sqrt(3.0), 1e-5);
  InsProblem p(ins, plan.knots, std::move(plan.fixes), gnss.size(), o.time_offset_s,
               o.estimate_time_offset, o.max_time_offset_s, o.arm_prior_std_m,
               o.accel_bias_prior_std_mps2);
  p.weights().process = 1.0 / (sigma_a * std::sqrt(dt));
  p.weights().horizontal.assign(gnss.size(), 1.0 / o.gnss_horizontal_std_m);
  p.weights().vertical.assign(gnss.size(), 1.0 / o.gnss_vertical_std_m);
  InsProblem::Linearised lin;
  for (int it = 0;; ++it) {
    // After new weights one Gauss–Newton step is the new optimum: the problem is linear but for
    // δ, already converged, and the attitude at t − δ.
    const ceres::Solver::Summary s = p.solve(it == 0 ? 100 : 1);
    out.solver_iterations += static_cast<int>(s.iterations.size());
    if (!s.IsSolutionUsable()) {
      out.message = "the solver failed: " + s.message;
      return out;
    }
    if (it >= o.variance_iterations) break;
    lin = p.linearise();
    update_weights(p, o, gnss.size(), lin);
  }
  if (o.variance_iterations == 0) lin = p.linearise();
  out.noise.process_scale = 1.0 / (p.weights().process * sigma_a * std::sqrt(dt));
  fill_result(p, o, gnss, lin, out);
  add_advice(out);
  out.status = core::Status::kOk;
  return out;
}

}  // namespace dynpos::calib
