#include "convex_qp.hpp"

#include <array>
#include <cassert>
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

void working_set_step(const ConvexQp& qp, const std::vector<Eigen::Index>& working,
                      const Eigen::VectorXd& g, Step& out) {
  const Eigen::Index n = qp.H.rows();
  const auto m = static_cast<Eigen::Index>(working.size());
  out.lambda.resize(m);
  if (m == 0) {
    out.p = qp.H.llt().solve(-g);
    return;
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
}

// What block_step keeps between iterations, so that a step allocates nothing once warm.
struct BlockWorkspace {
  std::vector<int> count;                      // working rows per block
  std::vector<std::array<std::size_t, 2>> of;  // their positions in the working set
  std::vector<Eigen::Index> z_at;              // each null-space column's first variable
  std::vector<int> z_width;                    // and its block's size
  std::vector<Eigen::Vector2d> z;              // its coefficients there
  Eigen::MatrixXd reduced;
  Eigen::LLT<Eigen::MatrixXd> llt;
  Eigen::VectorXd y, r;
};

// working_set_step for a G of blocks (ConvexQp): Z block by block — a block of size w with c
// working rows (independent, so c ≤ w) leaves w − c free directions, an orthonormal basis of
// them — then the same reduced system, and each block's multipliers from its own rows.
void block_step(const ConvexQp& qp, const std::vector<Eigen::Index>& working,
                const Eigen::VectorXd& g, BlockWorkspace& w, Step& out) {
  const std::size_t blocks = qp.block_start.size();
  w.count.assign(blocks, 0);
  w.of.resize(blocks);
  for (std::size_t k = 0; k < working.size(); ++k) {
    const auto b = static_cast<std::size_t>(qp.row_block[static_cast<std::size_t>(working[k])]);
    // Independent rows (starting_set, and a blocking row moves off the working ones): at
    // most the block's size.
    assert(w.count[b] < 2);
    if (w.count[b] < 2) w.of[b][static_cast<std::size_t>(w.count[b]++)] = k;
  }
  w.z_at.clear();
  w.z_width.clear();
  w.z.clear();
  for (std::size_t b = 0; b < blocks; ++b) {
    const Eigen::Index o = qp.block_start[b];
    const int size = qp.block_size[b];
    const auto add = [&](const Eigen::Vector2d& z) {
      w.z_at.push_back(o);
      w.z_width.push_back(size);
      w.z.push_back(z);
    };
    if (w.count[b] >= size) continue;
    if (size == 1 || w.count[b] == 0) {
      add({1.0, 0.0});
      if (size == 2) add({0.0, 1.0});
      continue;
    }
    const Eigen::Index i = working[w.of[b][0]];
    const Eigen::Vector2d a(qp.G(i, o), qp.G(i, o + 1));
    add(Eigen::Vector2d(-a.y(), a.x()) / a.norm());
  }
  const auto k = static_cast<Eigen::Index>(w.z.size());
  out.p.setZero(qp.H.rows());
  if (k > 0) {
    // zᵢᵀ·H·zⱼ and −zᵢᵀ·g over the one or two variables of each column.
    const auto zHz = [&](Eigen::Index i, Eigen::Index j) {
      const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
      double v = 0.0;
      for (int a = 0; a < w.z_width[ui]; ++a) {
        for (int c = 0; c < w.z_width[uj]; ++c) {
          v += w.z[ui](a) * qp.H(w.z_at[ui] + a, w.z_at[uj] + c) * w.z[uj](c);
        }
      }
      return v;
    };
    w.reduced.resize(k, k);
    w.y.resize(k);
    for (Eigen::Index i = 0; i < k; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      for (Eigen::Index j = 0; j <= i; ++j) w.reduced(i, j) = w.reduced(j, i) = zHz(i, j);
      double zg = w.z[ui](0) * g(w.z_at[ui]);
      if (w.z_width[ui] == 2) zg += w.z[ui](1) * g(w.z_at[ui] + 1);
      w.y(i) = -zg;
    }
    w.llt.compute(w.reduced);
    w.llt.solveInPlace(w.y);
    for (Eigen::Index i = 0; i < k; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      out.p(w.z_at[ui]) += w.z[ui](0) * w.y(i);
      if (w.z_width[ui] == 2) out.p(w.z_at[ui] + 1) += w.z[ui](1) * w.y(i);
    }
  }
  // G_Wᵀλ = −(H·p + g), block by block.
  w.r.noalias() = qp.H * out.p;
  w.r = -(w.r + g);
  out.lambda.setZero(static_cast<Eigen::Index>(working.size()));
  for (std::size_t b = 0; b < blocks; ++b) {
    if (w.count[b] == 0) continue;
    const Eigen::Index o = qp.block_start[b];
    const std::size_t k0 = w.of[b][0];
    const Eigen::Index i0 = working[k0];
    if (qp.block_size[b] == 1) {
      out.lambda(static_cast<Eigen::Index>(k0)) = w.r(o) / qp.G(i0, o);
      continue;
    }
    const Eigen::Vector2d r(w.r(o), w.r(o + 1));
    const Eigen::Vector2d a0(qp.G(i0, o), qp.G(i0, o + 1));
    if (w.count[b] == 1) {
      out.lambda(static_cast<Eigen::Index>(k0)) = a0.dot(r) / a0.squaredNorm();
      continue;
    }
    const std::size_t k1 = w.of[b][1];
    const Eigen::Index i1 = working[k1];
    Eigen::Matrix2d m;
    m.col(0) = a0;
    m.col(1) = Eigen::Vector2d(qp.G(i1, o), qp.G(i1, o + 1));
    const Eigen::Vector2d l = m.partialPivLu().solve(r);
    out.lambda(static_cast<Eigen::Index>(k0)) = l(0);
    out.lambda(static_cast<Eigen::Index>(k1)) = l(1);
  }
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
  const bool blocks = !qp.row_block.empty();
  // With blocks, each row as its first variable and one or two coefficients: G·p in a few
  // flops a row instead of a dense product.
  std::vector<Eigen::Index> row_at;
  std::vector<Eigen::Vector2d> row_a;
  if (blocks) {
    row_at.resize(static_cast<std::size_t>(m));
    row_a.resize(static_cast<std::size_t>(m));
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto b = static_cast<std::size_t>(qp.row_block[static_cast<std::size_t>(i)]);
      const Eigen::Index o = qp.block_start[b];
      row_at[static_cast<std::size_t>(i)] = o;
      row_a[static_cast<std::size_t>(i)] =
          Eigen::Vector2d(qp.G(i, o), qp.block_size[b] == 2 ? qp.G(i, o + 1) : 0.0);
    }
  }
  const auto times_G = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
    if (!blocks) {
      out.noalias() = qp.G * v;
      return;
    }
    const Eigen::Index last = v.size() - 1;
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto u = static_cast<std::size_t>(i);
      const Eigen::Index o = row_at[u];
      out(i) = row_a[u](0) * v(o) + (o < last ? row_a[u](1) * v(o + 1) : 0.0);
    }
  };
  BlockWorkspace workspace;
  Step step;
  Eigen::VectorXd g(n);
  Eigen::VectorXd Gp(m);
  Eigen::VectorXd Gx(m);  // kept along the steps: G·(x + αp) = Gx + α·Gp
  times_G(out.x, Gx);
  bool at_optimum = false;  // at the working set's optimum after a full step (p = 0 then)
  for (out.iterations = 0; out.iterations < max_iterations; ++out.iterations) {
    g.noalias() = qp.H * out.x;
    g += qp.c;
    if (blocks) {
      block_step(qp, working, g, workspace, step);
    } else {
      working_set_step(qp, working, g, step);
    }
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
    times_G(p, Gp);
    const double moving = 1e-14 * p.cwiseAbs().maxCoeff();  // G_i·p below: parallel to it
    for (Eigen::Index i = 0; i < m; ++i) {
      if (in_working[static_cast<std::size_t>(i)] || Gp(i) <= moving) continue;
      const double slack = std::max(qp.h(i) - Gx(i), 0.0);
      const double alpha_i = slack / Gp(i);
      if (alpha_i < alpha) {
        alpha = alpha_i;
        blocking = i;
      }
    }
    out.x += alpha * p;
    Gx += alpha * Gp;
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
