#pragma once
// The residuals of the logger-only arm estimator (ins_arms.hpp) as Ceres cost functions with
// analytic Jacobians. Parameter blocks: a knot x = [P; Ṗ] (6, NED), an arm d (3, BODY), the
// accelerometer bias b (3, BODY) and the time offset δ (1). Every residual is whitened by the
// current noise levels in InsWeights, which the variance components update between solves.

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <vector>

#include "ins_preintegration.hpp"

namespace dynpos::calib::detail {

/// 1/σ of each residual group, shared by the cost functions and updated between solves.
struct InsWeights {
  double process = 1.0;  ///< 1/√q, q the accelerometer noise density [m²/s³]
  std::vector<double> horizontal, vertical;  ///< per antenna [1/m]
};

/// Knot m to knot m + 1 over h: [P₁ − P₀ − Ṗ₀h − Δp + Mp·b; Ṗ₁ − Ṗ₀ − Δv + Mv·b], whitened by
/// the process covariance q·[h³/3, h²/2; h²/2, h] of white acceleration noise.
class ProcessCost : public ceres::SizedCostFunction<6, 6, 6, 3> {
 public:
  ProcessCost(const InsDelta& d, double h_s, const InsWeights* w);
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

 private:
  InsDelta d_;
  double h_;
  double a_, c_, e_;  // Cholesky factor [a 0; c e] of [h³/3 h²/2; h²/2 h]
  const InsWeights* w_;
};

/// The fixes z_k of one epoch stamped t (every antenna that has one), evaluated from knot τ:
/// z_k − [P(t − δ) + R(t − δ)·d_k], whitened by each antenna's σ. One cost per epoch, so the
/// integrals and the attitude at t − δ are computed once for all its antennas. Parameter
/// blocks: the knot, each antenna's arm in the order of `antennas`, b, δ.
class EpochCost : public ceres::CostFunction {
 public:
  EpochCost(const InsPreintegration* ins, double tau_s, double t_s,
            std::vector<std::size_t> antennas, std::vector<Eigen::Vector3d> z_n_m,
            const InsWeights* w);
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

 private:
  const InsPreintegration* ins_;
  double tau_, t_;
  InsPoint at_tau_;  // the integrals at the knot, fixed
  std::vector<std::size_t> k_;
  std::vector<Eigen::Vector3d> z_;
  const InsWeights* w_;
};

/// The weak prior d ~ N(0, σ²I).
class ArmPriorCost : public ceres::SizedCostFunction<3, 3> {
 public:
  explicit ArmPriorCost(double std_m) : inv_(1.0 / std_m) {}
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

 private:
  double inv_;
};

}  // namespace dynpos::calib::detail
