#pragma once
// A small dense convex quadratic programme, solved by the primal active-set method (Nocedal &
// Wright, Numerical Optimization, 2nd ed., algorithm 16.3) from a feasible start (private).
//
//     min ½xᵀHx + cᵀx   s.t.  Gx ≤ h,   H symmetric positive definite.
//
// Each iteration solves the equality-constrained step on the working set W by the null-space
// method (a QR of G_Wᵀ), so the working constraints hold to round-off whatever the conditioning
// of H; a blocking constraint added on the way is never a combination of W's (G_W p = 0 while
// G_i p > 0), so G_W keeps full rank. For the few tens of variables and a hundred constraints
// of a thrust allocation.

#include <Eigen/Dense>
#include <vector>

namespace dynpos::model::detail {

struct ConvexQp {
  Eigen::MatrixXd H;
  Eigen::VectorXd c;
  Eigen::MatrixXd G;
  Eigen::VectorXd h;
  // Optional block structure: the variables in consecutive blocks of one or two (a unit's
  // forces), every row of G on the variables of one block, row i on block row_block[i] starting
  // at block_start[b] of size block_size[b]. Given, each step's null space is built block by
  // block (an orthonormal basis of each block's free directions) instead of by a QR of the
  // whole working set: the same step, several times faster. Empty: G is taken as dense.
  std::vector<Eigen::Index> block_start;
  std::vector<int> block_size;
  std::vector<int> row_block;
};

struct QpSolution {
  Eigen::VectorXd x;
  bool converged = false;  // false: the iteration cap ended it; x is feasible all the same
  int iterations = 0;
  std::vector<Eigen::Index> working;  // the working set at the end (the active constraints)
};

// Solves `qp` from x0, which must satisfy Gx0 ≤ h (within 1e-9 of each |h_i| + 1). The working
// set starts with those of `working0` that x0 holds with equality (to 1e-9 of |h_i| + 1) and
// that are independent of the ones taken before them: a warm start from the solution of an
// earlier programme with the same constraints (a nearby demand), which then needs a step or two
// instead of one per active constraint. H being positive definite, the optimum is the same from
// any start, up to round-off.
QpSolution solve_convex_qp(const ConvexQp& qp, const Eigen::VectorXd& x0,
                           const std::vector<Eigen::Index>& working0 = {});

}  // namespace dynpos::model::detail
