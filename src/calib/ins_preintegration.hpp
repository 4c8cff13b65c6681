#pragma once
// The integrals of the MRU's NED acceleration that the logger-only arm estimator needs between
// any two times: A(t) = R(Θ(t))·a(t) [+ g_n] and the bias map R(Θ(t)), both linear between
// samples, integrated once and twice from the first sample. Then for a < s,
//   ∫ₐˢ A dτ = V(s) − V(a),   ∫ₐˢ (s − τ)·A dτ = W(s) − W(a) − V(a)·(s − a),
// and likewise for R, so each knot interval and each fix costs O(1) after an O(n) pass.

#include <Eigen/Core>
#include <vector>

#include "dynpos/calib/imu_series.hpp"

namespace dynpos::calib::detail {

/// What the integrals give between a knot at τ and a time s: the motion of P as
/// P(s) = P(τ) + Ṗ(τ)·(s − τ) + dp − Mp·b and Ṗ(s) = Ṗ(τ) + dv − Mv·b.
struct InsDelta {
  Eigen::Vector3d dp, dv;  ///< ∫∫A and ∫A [m], [m/s]
  Eigen::Matrix3d Mp, Mv;  ///< ∫∫R and ∫R
};

/// The integrals from the first sample to one time: V, W and their bias maps MV, MW.
struct InsPoint {
  Eigen::Vector3d V, W;
  Eigen::Matrix3d MV, MW;
};

class InsPreintegration {
 public:
  /// `theta_rad` the attitude per sample of `imu` (smoothed); gravity added for specific force.
  InsPreintegration(const ImuSeries& imu, const std::vector<Eigen::Vector3d>& theta_rad,
                    double gravity_mps2);

  double t_begin() const { return t_.front(); }
  double t_end() const { return t_.back(); }
  /// The integrals from τ to s (s may be before τ).
  InsDelta delta(double tau_s, double s) const { return delta(at(tau_s), tau_s, s); }
  /// The same from the integrals at τ, at(τ), computed once.
  InsDelta delta(const InsPoint& at_tau, double tau_s, double s) const;
  InsPoint at(double s) const;
  /// R(Θ(s)) (attitude linear between samples) and ω(s) in BODY.
  Eigen::Matrix3d rotation(double s) const;
  Eigen::Vector3d omega_b(double s) const;

 private:
  struct Node {
    Eigen::Vector3d A, V, W;  // A at the sample, its integrals from the start
    Eigen::Matrix3d R, MV, MW;
  };
  std::size_t segment(double s) const;  // i with t_[i] ≤ s < t_[i+1], clamped

  std::vector<double> t_;
  double inv_dt_ = 0.0;  // 1 / mean sample spacing: the first guess of a segment
  std::vector<Node> node_;
  std::vector<Eigen::Vector3d> theta_, omega_;
};

}  // namespace dynpos::calib::detail
