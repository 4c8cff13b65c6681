#pragma once
/// \file
/// Excitation diagnostics of a maneuver for lever-arm estimation (thesis 4.2.1–4.2.2):
/// the observability rank condition of Proposition 1, rank[S² + Ṡ] = 3 (4.25); persistence of
/// excitation of Ω = R·S, the smallest eigenvalue of ∫ₜ^{t+T} SᵀS dτ (4.51)–(4.58), over a
/// sliding window; and the observability Gramian W₀ = ∫ CᵀC dτ (4.13) of the LTV system
/// (4.8)–(4.12). From these, a verdict per arm component (well, weakly, not determined) with
/// advice on the motion that is missing. The verdict logic is shared by every lever-arm
/// estimator (GNSS and MRU).

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "dynpos/calib/arm_estimate.hpp"
#include "dynpos/calib/motion_series.hpp"

namespace dynpos::calib {

/// Thresholds of the verdict on one arm component, from its standard deviation [m].
struct VerdictThresholds {
  double well_std_m = 0.02;  ///< σ ≤ this: well determined [m], > 0
  double weak_std_m = 0.25;  ///< σ ≤ this: weakly determined, above: not determined [m]
  void validate() const;     ///< throws std::invalid_argument unless 0 < well < weak
};

/// The verdict on a component from its 1σ [m]; NaN or infinite σ is "not determined".
Determinacy determinacy_from_std(double std_m, const VerdictThresholds& thresholds = {});

/// The worse of two verdicts.
Determinacy worse(Determinacy a, Determinacy b);

/// Advice for one BODY component (0 = x, 1 = y, 2 = z) of an arm that is not well determined,
/// e.g. "z is weakly determined: more roll or pitch needed"; empty when it is well determined.
/// x is seen through yaw and pitch, y through yaw and roll, z through roll and pitch (R·l).
std::string determinacy_advice(int axis, Determinacy d);

/// Options of excitation_diagnostics().
struct ExcitationOptions {
  double window_s = 60.0;  ///< T of the sliding PE window (4.51) [s], > 0
  /// A singular value of S² + Ṡ above this counts towards its rank (4.25) [rad²/s²], > 0.
  /// The default is about (0.01 rad/s)²: motion below it drowns in MRU rate noise.
  double rank_tolerance_rps2 = 1e-4;
  /// 1σ of one GNSS position component [m] and the fix rate [Hz], used to turn the Gramian
  /// into a predicted 1σ of each arm component (the noise floor of any unbiased estimator).
  double gnss_std_m = 0.01;
  double gnss_rate_hz = 1.0;
  /// The per-sample diagnostics are reported at most at this rate [Hz], > 0 (a 100 Hz hour
  /// would otherwise give 360 000 eigen-decompositions); the integrals use every sample.
  double output_rate_hz = 10.0;
  VerdictThresholds verdict;
  void validate() const;  ///< throws std::invalid_argument naming the bad field
};

/// The diagnostics along a log, on the motion's time axis (decimated to output_rate_hz).
struct ExcitationDiagnostics {
  std::vector<double> t_s;
  std::vector<int> rank_s2_sdot;  ///< numerical rank of S² + Ṡ (4.25) per reported sample
  std::vector<double> s2_sdot_min_sv_rps2;  ///< its smallest singular value [rad²/s²]
  /// λ_min of ∫ SᵀS dτ over the window centred on the sample (4.55) [rad²/s]; NaN near the
  /// ends where the window does not fit in the log.
  std::vector<double> pe_min_eig_rad2ps;
  double rank3_fraction = 0.0;       ///< share of samples with rank 3 (Proposition 1)
  double pe_min_eig_min_rad2ps = 0;  ///< smallest windowed λ_min over the log (PE level α)
  double pe_min_eig_max_rad2ps = 0;  ///< largest windowed λ_min
  /// Observability Gramian of (4.8)–(4.9) for one antenna over the log, (4.13), x = [P₀; l]:
  /// its condition number (λ_max/λ_min) and the arm's predicted 1σ per BODY axis [m] from
  /// the arm block of W₀⁻¹ with the options' GNSS noise.
  double gramian_condition = 0.0;
  Eigen::Vector3d predicted_arm_std_m = Eigen::Vector3d::Zero();
  std::array<Determinacy, 3> verdict{Determinacy::kWell, Determinacy::kWell, Determinacy::kWell};
  std::vector<std::string> advice;  ///< one line per component that is not well determined
};

/// Computes the diagnostics; `motion` needs angular rates (ω) and attitude. Ṡ is from central
/// differences of ω. Throws std::invalid_argument if the motion has no angular rates or fewer
/// than three samples.
ExcitationDiagnostics excitation_diagnostics(const MotionSeries& motion,
                                             const ExcitationOptions& options = {});

}  // namespace dynpos::calib
