#include "convex_qp.hpp"

#include <cmath>

namespace dynpos::model::detail {
namespace {

// The step to the optimum on the working set W and its multipliers, by the null-space method:
// with G_Wᵀ = [Y Z]·R (QR), p = Z·p_z, (ZᵀHZ)·p_z = −Zᵀg, and λ from R·λ = −Yᵀ(H·p + g).
// G_W·p = 0 then holds to round-off of p itself, however ill-conditioned H is.
struct Step {
  Eigen::VectorXd p;
  Eigen::VectorXd lambda;
};

Step working_set_step(const ConvexQp& qp, const std::vector<Eigen::Index>& working,
                      const Eigen::VectorXd& g) {
  const Eigen::Index n = qp.H.rows();
  const auto m = static_cast<Eigen::Index>(working.size());
  Step out;
  if (m == 0) {
    out.p = qp.H.llt().solve(-g);
    return out;
  }
  Eigen::MatrixXd Gt(n, m);
  for (Eigen::Index k = 0; k < m; ++k) {
    Gt.col(k) = qp.G.row(working[static_cast<std::size_t>(k)]).transpose();
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Gt);
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd Z = Q.rightCols(n - m);
  if (n > m) {
    const Eigen::MatrixXd reduced = Z.transpose() * qp.H * Z;
    out.p = Z * reduced.llt().solve(-Z.transpose() * g);
  } else {
    out.p = Eigen::VectorXd::Zero(n);
  }
  const Eigen::VectorXd rhs = -(Q.leftCols(m).transpose() * (qp.H * out.p + g));
  out.lambda = qr.matrixQR().topLeftCorner(m, m).triangularView<Eigen::Upper>().solve(rhs);
  return out;
}

// The constraints of `candidates` that x holds with equality and that are independent of those
// taken before them (Gram–Schmidt on their rows: what is left of a row after its projection on
// the rows taken is more than 10⁻⁸ of it).
std::vector<Eigen::Index> starting_set(const ConvexQp& qp, const Eigen::VectorXd& x,
                                       const std::vector<Eigen::Index>& candidates) {
  std::vector<Eigen::Index> out;
  std::vector<Eigen::VectorXd> basis;
  for (const Eigen::Index i : candidates) {
    if (i < 0 || i >= qp.G.rows() || basis.size() >= static_cast<std::size_t>(x.size())) continue;
    if (std::abs(qp.G.row(i).dot(x) - qp.h(i)) > 1e-9 * (1.0 + std::abs(qp.h(i)))) continue;
    Eigen::VectorXd r = qp.G.row(i).transpose();
    const double size = r.norm();
    for (const Eigen::VectorXd& b : basis) r -= b.dot(r) * b;
    if (r.norm() <= 1e-8 * size) continue;
    basis.push_back(r / r.norm());
    out.push_back(i);
  }
  return out;
}

}  // namespace

QpSolution solve_convex_qp(const ConvexQp& qp, const Eigen::VectorXd& x0,
                           const std::vector<Eigen::Index>& working0) {
  const Eigen::Index n = qp.H.rows();
  const Eigen::Index m = qp.G.rows();
  QpSolution out;
  out.x = x0;
  std::vector<Eigen::Index> working = working0.empty() ? working0 : starting_set(qp, x0, working0);
  std::vector<bool> in_working(static_cast<std::size_t>(m), false);
  for (const Eigen::Index i : working) in_working[static_cast<std::size_t>(i)] = true;
  const int max_iterations = static_cast<int>(4 * (n + m)) + 20;
  bool at_optimum = false;  // at the working set's optimum after a full step (p = 0 then)
  for (out.iterations = 0; out.iterations < max_iterations; ++out.iterations) {
    const Eigen::VectorXd g = qp.H * out.x + qp.c;
    const Step step = working_set_step(qp, working, g);
    const Eigen::VectorXd& p = step.p;
    const double g_size = 1.0 + g.cwiseAbs().maxCoeff();
    if (at_optimum || p.cwiseAbs().maxCoeff() <= 1e-13 * (1.0 + out.x.cwiseAbs().maxCoeff())) {
      at_optimum = false;
      // At the working set's optimum: done unless a multiplier says a constraint pulls.
      Eigen::Index worst = -1;
      double most_negative = -1e-12 * g_size;
      for (Eigen::Index k = 0; k < step.lambda.size(); ++k) {
        if (step.lambda(k) < most_negative) {
          most_negative = step.lambda(k);
          worst = k;
        }
      }
      if (worst < 0) {
        out.converged = true;
        out.working = std::move(working);
        return out;
      }
      in_working[static_cast<std::size_t>(working[static_cast<std::size_t>(worst)])] = false;
      working.erase(working.begin() + worst);
      continue;
    }
    // The longest step towards the working set's optimum that keeps every constraint.
    double alpha = 1.0;
    Eigen::Index blocking = -1;
    const Eigen::VectorXd Gp = qp.G * p;
    const double moving = 1e-14 * p.cwiseAbs().maxCoeff();  // G_i·p below: parallel to it
    for (Eigen::Index i = 0; i < m; ++i) {
      if (in_working[static_cast<std::size_t>(i)] || Gp(i) <= moving) continue;
      const double slack = std::max(qp.h(i) - qp.G.row(i).dot(out.x), 0.0);
      const double alpha_i = slack / Gp(i);
      if (alpha_i < alpha) {
        alpha = alpha_i;
        blocking = i;
      }
    }
    out.x += alpha * p;
    at_optimum = blocking < 0;
    if (blocking >= 0) {
      working.push_back(blocking);
      in_working[static_cast<std::size_t>(blocking)] = true;
    }
  }
  out.working = std::move(working);
  return out;
}

}  // namespace dynpos::model::detail
