#pragma once
// The output-error fit of `identify vessel` (private to the module): the vessel's hull driven by
// each test's logged feedback (scenario::HullDrive) set against the logged u, v, r by Ceres over
// the free vessel-file values, each test (a stretch of a log) with its own start velocity and
// drifting current.

#include <Eigen/Core>
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "dynpos/scenario/hull_drive.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis::vessel_fit {

/// One logged test as the fit uses it.
struct FitTest {
  std::string name;       ///< the log
  std::size_t first = 0;  ///< the index of drive's first sample in the whole log's
  scenario::DriveSeries drive;
  /// Channel c (0: u [m/s], 1: v [m/s], 2: r [rad/s]) measured at drive samples index[c][k].
  std::array<std::vector<std::size_t>, 3> index;
  std::array<std::vector<double>, 3> measured;
  Eigen::Vector3d nu0_guess = Eigen::Vector3d::Zero();

  std::size_t residual_count() const noexcept {
    return index[0].size() + index[1].size() + index[2].size();
  }
};

/// A vessel-file value the fit may free, as its key "table.key", with the unit of the value.
struct FitParameter {
  std::string key;
  double start = 0.0;     ///< SI, the starting file's
  bool log_scale = true;  ///< p = start·exp(θ); else p = start·(1 + θ)

  double value(double theta) const noexcept;
  /// dp/dθ at θ.
  double slope(double theta) const noexcept;
};

/// The field of `key` ("hull.x_u_Ns_m") in `config` (SI), or nullptr when the vessel file has
/// no such numeric key.
double* field(scenario::VesselConfig& config, const std::string& key);

/// Per test (a stretch of a log): ν at its first sample (u₀, v₀, r₀), the current (north, east)
/// [m/s] there and its rate of change [m/s²] — the sea's current drifts (tide), and a constant
/// one over a whole log would leave that drift in the hull's damping.
using Nuisance = Eigen::Matrix<double, 7, 1>;

/// The fit over a set of tests. The θ of the parameters are shared, each test has its Nuisance;
/// residuals are (simulated − measured)/scale per test and channel.
class HullFit {
 public:
  HullFit(const scenario::VesselConfig& start, std::vector<FitParameter> parameters,
          std::vector<const FitTest*> tests, unsigned jobs);
  ~HullFit();
  HullFit(const HullFit&) = delete;
  HullFit& operator=(const HullFit&) = delete;

  std::vector<double> theta;                 ///< per parameter
  std::vector<Nuisance> nuisance;            ///< per test
  std::vector<std::array<double, 3>> scale;  ///< per test and channel, > 0

  /// The starting vessel with the parameters at `t`.
  scenario::VesselConfig vessel(const std::vector<double>& t) const;
  const std::vector<FitParameter>& parameters() const noexcept { return parameters_; }
  const std::vector<const FitTest*>& tests() const noexcept { return tests_; }
  /// The stage inputs of test k's drive (the units are not fitted: one set for every θ).
  const scenario::DriveStages& stages(std::size_t k) const noexcept { return stages_[k]; }

  /// Solves for the nuisance and the parameters of `free` (the others held at theta; all of them
  /// when hull_fixed); returns the number of iterations; `message` gets Ceres' report when it did
  /// not converge.
  int solve(const std::vector<bool>& free, bool hull_fixed, int max_iterations,
            std::string* message);

  /// σ of θ of the free parameters (NaN for the others) from the Jacobian at the current
  /// values (the pseudo-inverse of JᵀJ over them and the nuisance, which is marginalised;
  /// directions the data do not see dropped) times √variance.
  std::vector<double> theta_sigma(const std::vector<bool>& free, double variance);

  /// σ of θ of the free parameters (NaN for the others) by the block sandwich A⁺BA⁺: A = JᵀJ as
  /// in theta_sigma, B = Σ g_b g_bᵀ with g_b = J_bᵀ r_b over the blocks of `block_s` of each
  /// test, each block's residuals divided by 1 − its mean leverage. No noise model: honest where
  /// the residuals stay correlated longer than an AR(1) lag says (a current's slow drift).
  std::vector<double> theta_sigma_blocks(const std::vector<bool>& free, double block_s);

  /// Multiplies each test's channel scale by √((1 + ρ)/(1 − ρ)), ρ ∈ [−0.8, 0.95] the lag-one
  /// autocorrelation of its residuals: the information of N samples of an AR(1) error is that
  /// of N(1 − ρ)/(1 + ρ) independent ones.
  void widen_for_correlation();

  /// JᵀJ of the residuals at the current values, columns: every parameter's θ, then each
  /// test's Nuisance (one Jacobian of every test). `theta_information`: per test, the diagonal
  /// of its own JᵀJ over the θ (what each test tells of each parameter).
  Eigen::MatrixXd normal_matrix(std::vector<Eigen::VectorXd>* theta_information);

  /// Sets each test's channel scale to the RMS of its residual (not below floor[c]).
  void rescale(const std::array<double, 3>& floor);

  /// ν of test k at its drive samples with the current values.
  std::vector<Eigen::Vector3d> simulate(std::size_t k) const;

  /// χ²/(N − P) with P the free parameters and the nuisance.
  double residual_variance(const std::vector<bool>& free);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  scenario::VesselConfig start_;
  std::vector<FitParameter> parameters_;
  // Where each parameter is in vessel_param_sections(): (section, field).
  std::vector<std::pair<std::size_t, std::size_t>> slots_;
  std::vector<const FitTest*> tests_;
  std::vector<scenario::DriveStages> stages_;
  unsigned jobs_;
};

}  // namespace dynpos::analysis::vessel_fit
