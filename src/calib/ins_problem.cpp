#include "ins_problem.hpp"

#include <algorithm>
#include <cmath>

namespace dynpos::calib::detail {

using Vec3 = Eigen::Vector3d;

InsProblem::InsProblem(const InsPreintegration& ins, const InsKnots& knots,
                       std::vector<InsFix> fixes, std::size_t antennas, double time_offset_s,
                       bool estimate_offset, double max_offset_s, double arm_prior_std_m,
                       double bias_prior_std_mps2)
    : ins_(ins),
      knots_(knots),
      fixes_(std::move(fixes)),
      x_(knots.count),
      arms_(antennas, {0.0, 0.0, 0.0}),
      offset_(time_offset_s),
      estimate_(estimate_offset) {
  std::stable_sort(fixes_.begin(), fixes_.end(),
                   [](const InsFix& a, const InsFix& b) { return a.t_s < b.t_s; });
  weights_.horizontal.assign(antennas, 1.0);
  weights_.vertical.assign(antennas, 1.0);
  initialise();
  ceres::Problem::Options po;
  po.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  problem_ = std::make_unique<ceres::Problem>(po);
  for (std::size_t m = 0; m < knots_.count; ++m) problem_->AddParameterBlock(x_[m].data(), 6);
  for (auto& a : arms_) problem_->AddParameterBlock(a.data(), 3);
  problem_->AddParameterBlock(bias_.data(), 3);
  problem_->AddParameterBlock(&offset_, 1);
  for (std::size_t m = 0; m + 1 < knots_.count; ++m) {
    const InsDelta d = ins_.delta(knots_.time(m), knots_.time(m + 1));
    problem_->AddResidualBlock(new ProcessCost(d, knots_.h_s, &weights_), nullptr, x_[m].data(),
                               x_[m + 1].data(), bias_.data());
  }
  add_epochs();
  for (auto& a : arms_)
    problem_->AddResidualBlock(new ArmPriorCost(arm_prior_std_m), nullptr, a.data());
  if (std::isfinite(bias_prior_std_mps2))
    problem_->AddResidualBlock(new ArmPriorCost(bias_prior_std_mps2), nullptr, bias_.data());
  if (estimate_) {
    problem_->SetParameterLowerBound(&offset_, 0, -max_offset_s);
    problem_->SetParameterUpperBound(&offset_, 0, max_offset_s);
  } else {
    problem_->SetParameterBlockConstant(&offset_);
  }
}

// One cost per epoch: the fixes (sorted by stamp) that share a stamp, in antenna order, so that
// fix j's residuals are rows fix_row(j).
void InsProblem::add_epochs() {
  for (std::size_t j = 0; j < fixes_.size();) {
    std::size_t e = j;
    std::vector<std::size_t> antennas;
    std::vector<Vec3> z;
    std::vector<double*> blocks = {x_[fixes_[j].knot].data()};
    while (e < fixes_.size() && fixes_[e].t_s == fixes_[j].t_s) {
      antennas.push_back(fixes_[e].antenna);
      z.push_back(fixes_[e].z_n_m);
      blocks.push_back(arms_[fixes_[e].antenna].data());
      ++e;
    }
    blocks.push_back(bias_.data());
    blocks.push_back(&offset_);
    problem_->AddResidualBlock(new EpochCost(&ins_, knots_.time(fixes_[j].knot), fixes_[j].t_s,
                                             std::move(antennas), std::move(z), &weights_),
                               nullptr, blocks);
    j = e;
  }
}

// P at each knot: the mean of the fixes evaluated from it (the arms start at zero), carried
// over knots without fixes; Ṗ from the neighbouring knots.
void InsProblem::initialise() {
  std::vector<Vec3> sum(knots_.count, Vec3::Zero());
  std::vector<int> count(knots_.count, 0);
  for (const InsFix& f : fixes_) {
    sum[f.knot] += f.z_n_m;
    ++count[f.knot];
  }
  Vec3 last = fixes_.front().z_n_m;
  std::vector<Vec3> p(knots_.count);
  for (std::size_t m = 0; m < knots_.count; ++m) {
    if (count[m] > 0) last = sum[m] / count[m];
    p[m] = last;
  }
  for (std::size_t m = 0; m < knots_.count; ++m) {
    const std::size_t a = m > 0 ? m - 1 : 0, b = std::min(m + 1, knots_.count - 1);
    const Vec3 v = b > a ? Vec3((p[b] - p[a]) / (knots_.time(b) - knots_.time(a))) : Vec3::Zero();
    for (int i = 0; i < 3; ++i) {
      x_[m][static_cast<std::size_t>(i)] = p[m][i];
      x_[m][static_cast<std::size_t>(i) + 3] = v[i];
    }
  }
}

ceres::Solver::Summary InsProblem::solve(int max_iterations) {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  o.max_num_iterations = max_iterations;
  // Relative: below 1e-10 a change of the cost is rounding, not progress.
  o.function_tolerance = 1e-10;
  o.gradient_tolerance = 1e-14;
  o.parameter_tolerance = 1e-10;
  o.num_threads = 1;
  // Linear but for δ and the attitude at t − δ: Gauss–Newton steps from the start.
  o.initial_trust_region_radius = 1e12;
  o.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(o, problem_.get(), &summary);
  return summary;
}

std::vector<double*> InsProblem::blocks() {
  std::vector<double*> b;
  for (auto& x : x_) b.push_back(x.data());
  for (auto& a : arms_) b.push_back(a.data());
  b.push_back(bias_.data());
  b.push_back(&offset_);
  return b;
}

// The whitened residuals (and with `crs` the Jacobian) at the current parameters, columns in
// the order of blocks().
Eigen::VectorXd InsProblem::evaluate(ceres::CRSMatrix* crs) {
  ceres::Problem::EvaluateOptions eo;
  eo.parameter_blocks = blocks();
  eo.apply_loss_function = false;
  std::vector<double> r;
  problem_->Evaluate(eo, nullptr, &r, nullptr, crs);
  return Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<long>(r.size()));
}

InsProblem::Linearised InsProblem::linearise() {
  ceres::CRSMatrix crs;
  Linearised out;
  out.r = evaluate(&crs);
  // Ceres orders each row's columns by parameter block; δ's column goes when it is held.
  const auto cols = static_cast<int>(columns());
  std::vector<int> outer(static_cast<std::size_t>(crs.num_rows) + 1, 0), inner;
  std::vector<double> values;
  inner.reserve(crs.cols.size());
  values.reserve(crs.values.size());
  for (std::size_t i = 0; i < static_cast<std::size_t>(crs.num_rows); ++i) {
    for (int k = crs.rows[i]; k < crs.rows[i + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      if (crs.cols[kk] >= cols) continue;
      inner.push_back(crs.cols[kk]);
      values.push_back(crs.values[kk]);
    }
    outer[i + 1] = static_cast<int>(inner.size());
  }
  out.J = Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>>(
      crs.num_rows, cols, static_cast<long>(values.size()), outer.data(), inner.data(),
      values.data());
  return out;
}

Eigen::VectorXd InsProblem::residuals() { return evaluate(nullptr); }

Vec3 InsProblem::fix_residual_m(const Eigen::VectorXd& r, std::size_t j) const {
  const std::size_t k = fixes_[j].antenna;
  const auto row = static_cast<long>(fix_row(j));
  return {r[row] / weights_.horizontal[k], r[row + 1] / weights_.horizontal[k],
          r[row + 2] / weights_.vertical[k]};
}

}  // namespace dynpos::calib::detail
