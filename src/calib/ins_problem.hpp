#pragma once
// The batch problem of the logger-only arm estimator (ins_arms.hpp): its parameters, the Ceres
// problem over them, and what the variance components and the covariance need from it — the
// whitened residuals by group and the Jacobian as an Eigen sparse matrix.

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <vector>

#include "dynpos/calib/gnss_lever_arm.hpp"
#include "ins_costs.hpp"
#include "ins_preintegration.hpp"

namespace dynpos::calib::detail {

/// Knots every h seconds from t0.
struct InsKnots {
  double t0_s = 0.0, h_s = 1.0;
  std::size_t count = 0;
  double time(std::size_t m) const { return t0_s + h_s * static_cast<double>(m); }
};

/// One fix, the knot it is evaluated from and its antenna.
struct InsFix {
  std::size_t antenna = 0, knot = 0;
  double t_s = 0.0;
  Eigen::Vector3d z_n_m;
};

class InsProblem {
 public:
  InsProblem(const InsPreintegration& ins, const InsKnots& knots, std::vector<InsFix> fixes,
             std::size_t antennas, double time_offset_s, bool estimate_offset, double max_offset_s,
             double arm_prior_std_m, double bias_prior_std_mps2);

  InsWeights& weights() { return weights_; }
  /// Runs the solver from the current parameters, at most `max_iterations` steps; returns its
  /// summary.
  ceres::Solver::Summary solve(int max_iterations = 100);

  /// The whitened residuals and Jacobian at the current parameters. Columns: the knots
  /// (6 each), the arms (3 each), b (3), then δ when estimated.
  struct Linearised {
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double, Eigen::RowMajor> J;
  };
  Linearised linearise();
  /// The whitened residuals alone at the current parameters.
  Eigen::VectorXd residuals();

  std::size_t process_rows() const { return 6 * (knots_.count - 1); }
  std::size_t fix_row(std::size_t j) const { return process_rows() + 3 * j; }
  std::size_t global_col() const { return 6 * knots_.count; }  ///< first arm column
  std::size_t columns() const { return global_col() + 3 * arms_.size() + 3 + (estimate_ ? 1 : 0); }

  const std::vector<InsFix>& fixes() const { return fixes_; }
  Eigen::Vector3d arm(std::size_t k) const {
    return Eigen::Map<const Eigen::Vector3d>(arms_[k].data());
  }
  Eigen::Vector3d bias() const { return Eigen::Map<const Eigen::Vector3d>(bias_.data()); }
  double time_offset() const { return offset_; }
  bool offset_estimated() const { return estimate_; }
  /// The unwhitened fix residual z − y of fix j [m] from the whitened one.
  Eigen::Vector3d fix_residual_m(const Eigen::VectorXd& r, std::size_t j) const;

 private:
  void initialise();
  void add_epochs();
  std::vector<double*> blocks();
  Eigen::VectorXd evaluate(ceres::CRSMatrix* crs);

  const InsPreintegration& ins_;
  InsKnots knots_;
  std::vector<InsFix> fixes_;
  std::vector<std::array<double, 6>> x_;
  std::vector<std::array<double, 3>> arms_;
  std::array<double, 3> bias_{0.0, 0.0, 0.0};
  double offset_;
  bool estimate_;
  InsWeights weights_;
  std::unique_ptr<ceres::Problem> problem_;
};

}  // namespace dynpos::calib::detail
