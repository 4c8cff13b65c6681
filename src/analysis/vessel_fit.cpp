// The output-error fit of `identify vessel`: Ceres over the simulator's own hull model driven by
// the logged feedback (vessel_fit.hpp; docs/theory.md, "Vessel identification").

#include "vessel_fit.hpp"

#include <ceres/ceres.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "dynpos/core/error.hpp"

namespace dynpos::analysis::vessel_fit {

double FitParameter::value(double theta) const noexcept {
  return log_scale ? start * std::exp(theta) : start * (1.0 + theta);
}

double FitParameter::slope(double theta) const noexcept {
  return log_scale ? start * std::exp(theta) : start;
}

double* field(scenario::VesselConfig& config, const std::string& key) {
  for (core::ParamSection& section : scenario::vessel_param_sections(config)) {
    for (core::ParamField& f : section.fields) {
      if (section.name + "." + f.range.key == key) return f.value;
    }
  }
  return nullptr;
}

namespace {

constexpr int kNuisance = 7;

// The residuals of one test: the hull driven by its inputs against its measured u, v, r.
struct TestResidual {
  const HullFit* fit;
  std::size_t k;  // the test

  bool operator()(double const* const* blocks, double* residuals) const {
    // One block per parameter (so that a held one costs no derivative), then the nuisance.
    const std::size_t n = fit->parameters().size();
    std::vector<double> theta(n);
    for (std::size_t i = 0; i < n; ++i) theta[i] = blocks[i][0];
    const double* nu = blocks[n];
    std::vector<Eigen::Vector3d> sim;
    try {
      const scenario::HullDrive drive(fit->vessel(theta));
      sim = drive.simulate(fit->tests()[k]->drive, fit->stages(k),
                           Eigen::Vector3d(nu[0], nu[1], nu[2]), Eigen::Vector2d(nu[3], nu[4]),
                           Eigen::Vector2d(nu[5], nu[6]));
    } catch (const core::InputError&) {
      return false;  // a value out of its range: Ceres tries a shorter step
    }
    const FitTest& t = *fit->tests()[k];
    const std::array<double, 3>& scale = fit->scale[k];
    std::size_t j = 0;
    for (int c = 0; c < 3; ++c) {
      for (std::size_t m = 0; m < t.index[c].size(); ++m) {
        const double r = (sim[t.index[c][m]][c] - t.measured[c][m]) / scale[c];
        if (!std::isfinite(r)) return false;
        residuals[j++] = r;
      }
    }
    return true;
  }
};

}  // namespace

struct HullFit::Impl {
  ceres::Problem problem;
  std::vector<ceres::ResidualBlockId> blocks;

  // The Jacobian (and the residuals, when not null) at the current values, columns: every θ,
  // then each test's nuisance.
  ceres::CRSMatrix jacobian(std::vector<double>& theta, std::vector<Nuisance>& nuisance,
                            unsigned jobs, std::vector<double>* residuals) {
    ceres::Problem::EvaluateOptions eo;
    for (double& t : theta) {
      problem.SetParameterBlockVariable(&t);
      eo.parameter_blocks.push_back(&t);
    }
    eo.num_threads = static_cast<int>(jobs);
    eo.apply_loss_function = false;
    for (Nuisance& n : nuisance) eo.parameter_blocks.push_back(n.data());
    ceres::CRSMatrix crs;
    problem.Evaluate(eo, nullptr, residuals, nullptr, &crs);
    return crs;
  }
};

HullFit::HullFit(const scenario::VesselConfig& start, std::vector<FitParameter> parameters,
                 std::vector<const FitTest*> tests, unsigned jobs)
    : theta(parameters.size(), 0.0),
      nuisance(tests.size()),
      scale(tests.size(), {0.02, 0.02, 1e-3}),
      impl_(std::make_unique<Impl>()),
      start_(start),
      parameters_(std::move(parameters)),
      tests_(std::move(tests)),
      jobs_(jobs == 0 ? 2 : jobs) {
  scenario::VesselConfig copy = start_;
  const std::vector<core::ParamSection> sections = scenario::vessel_param_sections(copy);
  for (const FitParameter& p : parameters_) {
    const double* f = field(copy, p.key);
    std::optional<std::pair<std::size_t, std::size_t>> slot;
    for (std::size_t s = 0; s < sections.size() && f != nullptr; ++s) {
      for (std::size_t i = 0; i < sections[s].fields.size(); ++i) {
        if (sections[s].fields[i].value == f) slot.emplace(s, i);
      }
    }
    if (!slot) throw std::logic_error("vessel_fit: no vessel-file key " + p.key);
    slots_.push_back(*slot);
  }
  const scenario::HullDrive units(start_);
  for (const FitTest* t : tests_) stages_.push_back(units.stages(t->drive));
  for (std::size_t k = 0; k < tests_.size(); ++k) {
    nuisance[k] << tests_[k]->nu0_guess, 0.0, 0.0, 0.0, 0.0;
    auto* cost = new ceres::DynamicNumericDiffCostFunction<TestResidual, ceres::FORWARD>(
        new TestResidual{this, k}, ceres::TAKE_OWNERSHIP);
    std::vector<double*> blocks;
    for (double& t : theta) {
      cost->AddParameterBlock(1);
      blocks.push_back(&t);
    }
    cost->AddParameterBlock(kNuisance);
    blocks.push_back(nuisance[k].data());
    cost->SetNumResiduals(static_cast<int>(tests_[k]->residual_count()));
    impl_->blocks.push_back(impl_->problem.AddResidualBlock(cost, nullptr, blocks));
  }
}

HullFit::~HullFit() = default;

scenario::VesselConfig HullFit::vessel(const std::vector<double>& t) const {
  scenario::VesselConfig v = start_;
  if (parameters_.empty()) return v;
  // One pass over the tables for every parameter (a key lookup each was a fifth of the cost of
  // an evaluation).
  const std::vector<core::ParamSection> sections = scenario::vessel_param_sections(v);
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    *sections[slots_[i].first].fields[slots_[i].second].value = parameters_[i].value(t[i]);
  }
  return v;
}

namespace {

// Holds the parameters outside `free` constant (all of them when hull_fixed).
void hold(ceres::Problem& problem, std::vector<double>& theta, const std::vector<bool>& free,
          bool hull_fixed) {
  for (std::size_t i = 0; i < theta.size(); ++i) {
    if (hull_fixed || i >= free.size() || !free[i]) {
      problem.SetParameterBlockConstant(&theta[i]);
    } else {
      problem.SetParameterBlockVariable(&theta[i]);
    }
  }
}

}  // namespace

int HullFit::solve(const std::vector<bool>& free, bool hull_fixed, int max_iterations,
                   std::string* message) {
  hold(impl_->problem, theta, free, hull_fixed);
  ceres::Solver::Options o;
  // JᵀJ is an arrow: the θ against everything, each stretch's nuisance against itself. Its
  // sparse Cholesky costs little; a dense QR of the whole Jacobian cost most of a solve.
  o.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  o.max_num_iterations = max_iterations;
  o.function_tolerance = 1e-7;
  o.parameter_tolerance = 1e-7;
  o.num_threads = static_cast<int>(jobs_);
  o.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(o, &impl_->problem, &summary);
  if (message != nullptr && summary.termination_type != ceres::CONVERGENCE) {
    *message = summary.message;
  }
  return static_cast<int>(summary.iterations.size());
}

double HullFit::residual_variance(const std::vector<bool>& free) {
  double cost = 0.0;
  ceres::Problem::EvaluateOptions eo;
  eo.num_threads = static_cast<int>(jobs_);
  impl_->problem.Evaluate(eo, &cost, nullptr, nullptr, nullptr);
  std::size_t n = 0;
  for (const FitTest* t : tests_) n += t->residual_count();
  std::size_t p = kNuisance * tests_.size();
  for (bool f : free) p += f ? 1 : 0;
  return n > p ? 2.0 * cost / static_cast<double>(n - p) : std::numeric_limits<double>::quiet_NaN();
}

namespace {

// The free θ's columns, then every nuisance column (of `n_cols`).
std::vector<Eigen::Index> free_columns(const std::vector<bool>& free, std::size_t n_theta,
                                       Eigen::Index n_cols) {
  std::vector<Eigen::Index> cols;
  for (std::size_t i = 0; i < n_theta; ++i) {
    if (i < free.size() && free[i]) cols.push_back(static_cast<Eigen::Index>(i));
  }
  for (auto i = static_cast<Eigen::Index>(n_theta); i < n_cols; ++i) cols.push_back(i);
  return cols;
}

// The pseudo-inverse of a's rows and columns `cols`: eigenvalues under 1e-14 of the largest (a
// direction the data do not see) are dropped, not an error.
Eigen::MatrixXd sub_pseudo_inverse(const Eigen::MatrixXd& a,
                                   const std::vector<Eigen::Index>& cols) {
  const auto m = static_cast<Eigen::Index>(cols.size());
  Eigen::MatrixXd sub(m, m);
  for (Eigen::Index i = 0; i < m; ++i) {
    for (Eigen::Index j = 0; j < m; ++j) sub(i, j) = a(cols[i], cols[j]);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(sub);
  Eigen::VectorXd inverse = eig.eigenvalues();
  const double tol = inverse.cwiseAbs().maxCoeff() * 1e-14;
  for (double& e : inverse) e = e > tol ? 1.0 / e : 0.0;
  return eig.eigenvectors() * inverse.asDiagonal() * eig.eigenvectors().transpose();
}

// JᵀJ of `crs`, whose rows are the tests' residuals in turn; per test the diagonal of its own
// JᵀJ over the first n_theta columns when `theta_information` is not null.
Eigen::MatrixXd gram(const ceres::CRSMatrix& crs, const std::vector<const FitTest*>& tests,
                     Eigen::Index n_theta, std::vector<Eigen::VectorXd>* theta_information) {
  Eigen::MatrixXd jtj = Eigen::MatrixXd::Zero(crs.num_cols, crs.num_cols);
  if (theta_information != nullptr) {
    theta_information->assign(tests.size(), Eigen::VectorXd::Zero(n_theta));
  }
  std::size_t test = 0, test_end = tests.empty() ? 0 : tests[0]->residual_count();
  // A row has the θ and one test's nuisance: the outer product of its non-zeros only.
  for (int i = 0; i < crs.num_rows; ++i) {
    while (static_cast<std::size_t>(i) >= test_end && test + 1 < tests.size()) {
      test_end += tests[++test]->residual_count();
    }
    const auto a = static_cast<std::size_t>(crs.rows[static_cast<std::size_t>(i)]);
    const auto b = static_cast<std::size_t>(crs.rows[static_cast<std::size_t>(i) + 1]);
    for (std::size_t j = a; j < b; ++j) {
      const double vj = crs.values[j];
      for (std::size_t k = a; k <= j; ++k) {
        jtj(std::max(crs.cols[j], crs.cols[k]), std::min(crs.cols[j], crs.cols[k])) +=
            vj * crs.values[k];
      }
      if (theta_information != nullptr && crs.cols[j] < n_theta) {
        (*theta_information)[test][crs.cols[j]] += vj * vj;
      }
    }
  }
  return jtj.selfadjointView<Eigen::Lower>();
}

}  // namespace

std::vector<double> HullFit::theta_sigma(const std::vector<bool>& free, double variance) {
  std::vector<double> out(theta.size(), std::numeric_limits<double>::quiet_NaN());
  const Eigen::MatrixXd a = normal_matrix(nullptr);
  const std::vector<Eigen::Index> cols = free_columns(free, theta.size(), a.rows());
  const Eigen::MatrixXd inverse = sub_pseudo_inverse(a, cols);
  for (Eigen::Index k = 0; k < inverse.rows() && cols[k] < static_cast<Eigen::Index>(theta.size());
       ++k) {
    if (inverse(k, k) > 0.0) {
      out[static_cast<std::size_t>(cols[k])] = std::sqrt(inverse(k, k) * variance);
    }
  }
  return out;
}

std::vector<double> HullFit::theta_sigma_blocks(const std::vector<bool>& free, double block_s) {
  std::vector<double> out(theta.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<double> r;
  const ceres::CRSMatrix crs = impl_->jacobian(theta, nuisance, jobs_, &r);
  const auto n_theta = static_cast<Eigen::Index>(theta.size());
  const std::vector<Eigen::Index> cols = free_columns(free, theta.size(), crs.num_cols);
  const Eigen::MatrixXd inverse = sub_pseudo_inverse(gram(crs, tests_, n_theta, nullptr), cols);
  std::vector<Eigen::Index> position(static_cast<std::size_t>(crs.num_cols), -1);
  for (std::size_t k = 0; k < cols.size(); ++k) {
    position[static_cast<std::size_t>(cols[k])] = static_cast<Eigen::Index>(k);
  }
  const auto m = static_cast<Eigen::Index>(cols.size());
  Eigen::MatrixXd meat = Eigen::MatrixXd::Zero(m, m);
  std::size_t row = 0;
  for (const FitTest* t : tests_) {
    // Per block of the test: J_bᵀ r_b, the trace of its leverage J_b A⁺ J_bᵀ, its row count.
    const double t0 = t->drive.time_s.front();
    const auto n_blocks = static_cast<std::size_t>((t->drive.time_s.back() - t0) / block_s) + 1;
    std::vector<Eigen::VectorXd> score(n_blocks, Eigen::VectorXd::Zero(m));
    std::vector<double> leverage(n_blocks, 0.0), rows(n_blocks, 0.0);
    for (std::size_t c = 0; c < 3; ++c) {
      for (const std::size_t sample : t->index[c]) {
        const auto b = static_cast<std::size_t>((t->drive.time_s[sample] - t0) / block_s);
        const auto lo = static_cast<std::size_t>(crs.rows[row]);
        const auto hi = static_cast<std::size_t>(crs.rows[row + 1]);
        for (std::size_t j = lo; j < hi; ++j) {
          const Eigen::Index pj = position[static_cast<std::size_t>(crs.cols[j])];
          if (pj < 0) continue;
          score[b][pj] += crs.values[j] * r[row];
          for (std::size_t k = lo; k < hi; ++k) {
            const Eigen::Index pk = position[static_cast<std::size_t>(crs.cols[k])];
            if (pk >= 0) leverage[b] += crs.values[j] * inverse(pj, pk) * crs.values[k];
          }
        }
        rows[b] += 1.0;
        ++row;
      }
    }
    for (std::size_t b = 0; b < n_blocks; ++b) {
      if (rows[b] == 0.0) continue;
      const double shrink = 1.0 - std::min(leverage[b] / rows[b], 0.9);
      meat.noalias() += score[b] * score[b].transpose() / (shrink * shrink);
    }
  }
  const Eigen::MatrixXd covariance = inverse * meat * inverse;
  for (Eigen::Index k = 0; k < m && cols[k] < n_theta; ++k) {
    if (covariance(k, k) > 0.0) {
      out[static_cast<std::size_t>(cols[k])] = std::sqrt(covariance(k, k));
    }
  }
  return out;
}

Eigen::MatrixXd HullFit::normal_matrix(std::vector<Eigen::VectorXd>* theta_information) {
  const ceres::CRSMatrix crs = impl_->jacobian(theta, nuisance, jobs_, nullptr);
  return gram(crs, tests_, static_cast<Eigen::Index>(theta.size()), theta_information);
}

void HullFit::rescale(const std::array<double, 3>& floor) {
  for (std::size_t k = 0; k < tests_.size(); ++k) {
    const std::vector<Eigen::Vector3d> sim = simulate(k);
    const FitTest& t = *tests_[k];
    for (int c = 0; c < 3; ++c) {
      if (t.index[c].empty()) continue;
      double ss = 0.0;
      for (std::size_t m = 0; m < t.index[c].size(); ++m) {
        const double e = sim[t.index[c][m]][c] - t.measured[c][m];
        ss += e * e;
      }
      const double rms = std::sqrt(ss / static_cast<double>(t.index[c].size()));
      scale[k][c] = std::max(rms, floor[c]);
    }
  }
}

void HullFit::widen_for_correlation() {
  for (std::size_t k = 0; k < tests_.size(); ++k) {
    const std::vector<Eigen::Vector3d> sim = simulate(k);
    const FitTest& t = *tests_[k];
    for (int c = 0; c < 3; ++c) {
      const auto& idx = t.index[static_cast<std::size_t>(c)];
      const auto& y = t.measured[static_cast<std::size_t>(c)];
      double s0 = 0.0, s1 = 0.0;
      for (std::size_t m = 0; m < idx.size(); ++m) {
        const double e = sim[idx[m]][c] - y[m];
        s0 += e * e;
        if (m + 1 < idx.size()) s1 += e * (sim[idx[m + 1]][c] - y[m + 1]);
      }
      const double rho = s0 > 0.0 ? std::clamp(s1 / s0, -0.8, 0.95) : 0.0;
      scale[k][static_cast<std::size_t>(c)] *= std::sqrt((1.0 + rho) / (1.0 - rho));
    }
  }
}

std::vector<Eigen::Vector3d> HullFit::simulate(std::size_t k) const {
  const scenario::HullDrive drive(vessel(theta));
  const Nuisance& nu = nuisance[k];
  return drive.simulate(tests_[k]->drive, stages_[k], nu.head<3>(), nu.segment<2>(3), nu.tail<2>());
}

}  // namespace dynpos::analysis::vessel_fit
