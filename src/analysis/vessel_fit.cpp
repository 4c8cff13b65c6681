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

std::vector<double> HullFit::theta_sigma(const std::vector<bool>& free, double variance) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> out(theta.size(), nan);
  std::vector<Eigen::Index> cols;
  for (std::size_t i = 0; i < theta.size(); ++i) {
    if (i < free.size() && free[i]) cols.push_back(static_cast<Eigen::Index>(i));
  }
  if (cols.empty()) return out;
  const std::size_t n_free = cols.size();
  const Eigen::MatrixXd a = normal_matrix(nullptr);
  for (auto i = static_cast<Eigen::Index>(theta.size()); i < a.rows(); ++i) cols.push_back(i);
  const auto m = static_cast<Eigen::Index>(cols.size());
  Eigen::MatrixXd sub(m, m);
  for (Eigen::Index i = 0; i < m; ++i) {
    for (Eigen::Index j = 0; j < m; ++j) sub(i, j) = a(cols[i], cols[j]);
  }
  // The pseudo-inverse: eigenvalues under 1e-14 of the largest (a direction the data do not
  // see) are dropped, not an error.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(sub);
  const Eigen::VectorXd& ev = eig.eigenvalues();
  const double tol = ev.cwiseAbs().maxCoeff() * 1e-14;
  for (std::size_t k = 0; k < n_free; ++k) {
    double var = 0.0;
    for (Eigen::Index e = 0; e < m; ++e) {
      const double x = eig.eigenvectors()(static_cast<Eigen::Index>(k), e);
      if (ev[e] > tol) var += x * x / ev[e];
    }
    if (var > 0.0) out[static_cast<std::size_t>(cols[k])] = std::sqrt(var * variance);
  }
  return out;
}

Eigen::MatrixXd HullFit::normal_matrix(std::vector<Eigen::VectorXd>* theta_information) {
  ceres::Problem::EvaluateOptions eo;
  for (double& t : theta) {
    impl_->problem.SetParameterBlockVariable(&t);
    eo.parameter_blocks.push_back(&t);
  }
  eo.num_threads = static_cast<int>(jobs_);
  eo.apply_loss_function = false;
  for (Nuisance& n : nuisance) eo.parameter_blocks.push_back(n.data());
  ceres::CRSMatrix crs;
  impl_->problem.Evaluate(eo, nullptr, nullptr, nullptr, &crs);
  const auto cols = static_cast<Eigen::Index>(crs.num_cols);
  Eigen::MatrixXd jtj = Eigen::MatrixXd::Zero(cols, cols);
  const auto n_theta = static_cast<Eigen::Index>(theta.size());
  if (theta_information != nullptr) {
    theta_information->assign(tests_.size(), Eigen::VectorXd::Zero(n_theta));
  }
  std::size_t test = 0, test_end = tests_.empty() ? 0 : tests_[0]->residual_count();
  // A row has the θ and one test's nuisance: the outer product of its non-zeros only.
  for (int i = 0; i < crs.num_rows; ++i) {
    while (static_cast<std::size_t>(i) >= test_end && test + 1 < tests_.size()) {
      test_end += tests_[++test]->residual_count();
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
