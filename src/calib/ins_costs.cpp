#include "ins_costs.hpp"

#include <cmath>

#include "dynpos/core/rotation.hpp"

namespace dynpos::calib::detail {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
template <int R, int C>
using RowMat = Eigen::Map<Eigen::Matrix<double, R, C, Eigen::RowMajor>>;

ProcessCost::ProcessCost(const InsDelta& d, double h_s, const InsWeights* w)
    : d_(d), h_(h_s), w_(w) {
  a_ = std::sqrt(h_s * h_s * h_s / 3.0);
  c_ = 0.5 * h_s * h_s / a_;
  e_ = std::sqrt(h_s - c_ * c_);
}

bool ProcessCost::Evaluate(double const* const* x, double* residuals, double** jacobians) const {
  const Eigen::Map<const Vec3> p0(x[0]), v0(x[0] + 3), p1(x[1]), v1(x[1] + 3), b(x[2]);
  const Vec3 rp = p1 - p0 - v0 * h_ - d_.dp + d_.Mp * b;
  const Vec3 rv = v1 - v0 - d_.dv + d_.Mv * b;
  // Whitening L⁻¹ = [1/a 0; −c/(a·e) 1/e] per axis, times 1/√q.
  const double s = w_->process;
  const double wpp = s / a_, wvp = -s * c_ / (a_ * e_), wvv = s / e_;
  Eigen::Map<Eigen::Matrix<double, 6, 1>> r(residuals);
  r.head<3>() = wpp * rp;
  r.tail<3>() = wvp * rp + wvv * rv;
  if (jacobians == nullptr) return true;
  const Mat3 I = Mat3::Identity();
  if (jacobians[0]) {  // ∂/∂[p0 v0]: rp → [−I, −hI], rv → [0, −I]
    RowMat<6, 6> J(jacobians[0]);
    J.block<3, 3>(0, 0) = -wpp * I;
    J.block<3, 3>(0, 3) = -wpp * h_ * I;
    J.block<3, 3>(3, 0) = -wvp * I;
    J.block<3, 3>(3, 3) = (-wvp * h_ - wvv) * I;
  }
  if (jacobians[1]) {  // ∂/∂[p1 v1]: rp → [I, 0], rv → [0, I]
    RowMat<6, 6> J(jacobians[1]);
    J.setZero();
    J.block<3, 3>(0, 0) = wpp * I;
    J.block<3, 3>(3, 0) = wvp * I;
    J.block<3, 3>(3, 3) = wvv * I;
  }
  if (jacobians[2]) {  // ∂/∂b: rp → Mp, rv → Mv
    RowMat<6, 3> J(jacobians[2]);
    J.block<3, 3>(0, 0) = wpp * d_.Mp;
    J.block<3, 3>(3, 0) = wvp * d_.Mp + wvv * d_.Mv;
  }
  return true;
}

EpochCost::EpochCost(const InsPreintegration* ins, double tau_s, double t_s,
                     std::vector<std::size_t> antennas, std::vector<Vec3> z_n_m,
                     const InsWeights* w)
    : ins_(ins),
      tau_(tau_s),
      t_(t_s),
      at_tau_(ins->at(tau_s)),
      k_(std::move(antennas)),
      z_(std::move(z_n_m)),
      w_(w) {
  set_num_residuals(static_cast<int>(3 * k_.size()));
  mutable_parameter_block_sizes()->push_back(6);
  for (std::size_t i = 0; i < k_.size(); ++i) mutable_parameter_block_sizes()->push_back(3);
  mutable_parameter_block_sizes()->push_back(3);
  mutable_parameter_block_sizes()->push_back(1);
}

bool EpochCost::Evaluate(double const* const* x, double* residuals, double** jacobians) const {
  const std::size_t n = k_.size();
  const Eigen::Map<const Vec3> p(x[0]), v(x[0] + 3), b(x[n + 1]);
  const double s = t_ - x[n + 2][0];
  const InsDelta D = ins_->delta(at_tau_, tau_, s);
  const Mat3 R = ins_->rotation(s);
  const Vec3 P = p + v * (s - tau_) + D.dp - D.Mp * b;
  Vec3 V = Vec3::Zero();
  Mat3 RS = Mat3::Zero();
  if (jacobians && jacobians[n + 2]) {
    V = v + D.dv - D.Mv * b;
    RS = R * core::skew(ins_->omega_b(s));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = k_[i];
    const Eigen::Map<const Vec3> d(x[1 + i]);
    const Vec3 wv(w_->horizontal[k], w_->horizontal[k], w_->vertical[k]);
    const Mat3 W = wv.asDiagonal();
    Eigen::Map<Vec3>(residuals + 3 * i) = W * (z_[i] - P - R * d);
    if (jacobians == nullptr) continue;
    if (jacobians[0]) {  // rows 3i..3i+2 of a (3n × 6) block
      RowMat<Eigen::Dynamic, 6> J(jacobians[0], static_cast<long>(3 * n), 6);
      J.block<3, 3>(static_cast<long>(3 * i), 0) = -W;
      J.block<3, 3>(static_cast<long>(3 * i), 3) = -(s - tau_) * W;
    }
    for (std::size_t a = 0; a < n; ++a)  // ∂/∂d_a: −W·R on its own rows, zero elsewhere
      if (jacobians[1 + a]) {
        RowMat<Eigen::Dynamic, 3> J(jacobians[1 + a], static_cast<long>(3 * n), 3);
        J.block<3, 3>(static_cast<long>(3 * i), 0) = a == i ? Mat3(-W * R) : Mat3::Zero();
      }
    if (jacobians[n + 1]) {
      RowMat<Eigen::Dynamic, 3> J(jacobians[n + 1], static_cast<long>(3 * n), 3);
      J.block<3, 3>(static_cast<long>(3 * i), 0) = W * D.Mp;
    }
    if (jacobians[n + 2]) {  // d/dδ of −y(t − δ) = ẏ(s) = Ṗ(s) + R·S(ω)·d, (2.5)
      Eigen::Map<Vec3>(jacobians[n + 2] + 3 * i) = W * (V + RS * d);
    }
  }
  return true;
}

bool ArmPriorCost::Evaluate(double const* const* x, double* residuals, double** jacobians) const {
  for (int i = 0; i < 3; ++i) residuals[i] = inv_ * x[0][i];
  if (jacobians && jacobians[0]) {
    RowMat<3, 3> J(jacobians[0]);
    J = inv_ * Mat3::Identity();
  }
  return true;
}

}  // namespace dynpos::calib::detail
