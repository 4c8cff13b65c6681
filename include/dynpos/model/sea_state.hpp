#pragma once
/// \file
/// Irregular waves: the JONSWAP spectrum, its discretisation into components, the first-order
/// wave-frequency (WF) motion of the vessel in 6 DOF and the mean wave drift force.
///
/// The vessel's total motion is the low-frequency (LF) motion of the hull model plus the WF
/// motion here (the usual DP superposition, thesis section 2.1.4: DP controls only LF motion).
/// The WF motion is a sum of harmonic components evaluated at output times only, never inside
/// RK4 stages: a WaveMotion generator advances each component's phasor e^{jω_i t} by one
/// complex multiplication per output period, so a long run costs O(components) per sample and
/// is exactly reproducible. Encounter-frequency shift at forward speed is neglected (the
/// virtual trials run at ≤ 6 kn in low sea states).

#include <Eigen/Core>
#include <array>
#include <complex>
#include <cstdint>
#include <vector>

#include "dynpos/core/param_range.hpp"

namespace dynpos::model {

/// Range of the significant wave height a scenario sets (scenario file [environment]).
inline const core::ParamRange kSignificantWaveHeightRange{"hs_m", "m", 0, 8};
/// Range of the spectral peak period a scenario sets (scenario file [environment]).
inline const core::ParamRange kPeakPeriodRange{"tp_s", "s", 2, 20};
/// Range of the number of spectral components (scenario file [environment]).
inline const core::ParamRange kWaveComponentsRange{"wave_components", "1", 10, 1000};

/// Sea-state parameters.
struct SeaStateParams {
  double hs_m = 0.0;   ///< significant wave height H_s [m], kSignificantWaveHeightRange; 0 = calm
  double tp_s = 8.0;   ///< peak period T_p [s], kPeakPeriodRange
  double gamma = 3.3;  ///< JONSWAP peak enhancement γ [-], [1, 7]; 3.3 = mean JONSWAP
  double from_rad = 0.0;          ///< direction the waves come from, clockwise from north [rad]
  int components = 60;            ///< number of spectral components, kWaveComponentsRange
  double omega_min_factor = 0.5;  ///< lowest frequency as a multiple of ω_p, (0, 1)
  double omega_max_factor = 3.0;  ///< highest frequency as a multiple of ω_p, (1, 20)
  /// Throws core::InputError naming the first value outside its range.
  void validate() const;
};

/// Wave-response parameters of the hull (simple RAOs). Defaults: the virtual Gunnerus.
struct WaveResponseParams {
  double length_m = 31.25;      ///< hull length for short-wave attenuation. Source: Gunnerus Loa.
  double beam_m = 9.6;          ///< beam [m]. Source: Gunnerus main dimensions.
  double heave_period_s = 4.5;  ///< heave natural period [s]. Source: reasoned, T ≈ 2.7 m draught.
  double heave_damping = 0.3;   ///< heave damping ratio [-]. Source: reasoned (radiation damping).
  double roll_period_s = 8.0;   ///< roll natural period [s]. Source: as HullParams.
  double roll_damping = 0.1;    ///< roll damping ratio [-]. Source: as HullParams.
  double pitch_period_s = 5.0;  ///< pitch natural period [s]. Source: as HullParams.
  double pitch_damping = 0.3;   ///< pitch damping ratio [-]. Source: as HullParams.
  double yaw_factor = 0.3;  ///< yaw amplitude per wave slope at β = 45° [-]. Source: reasoned.
  /// Mean drift reflection coefficient [-]. Source: calibrated to the thesis' pure DP tables
  /// 3.14–3.22: 0.15 gives ≈ 6 kN beam drift in Hs 2 m on a 31 m hull, so the mean thrust lands
  /// in their 2–45 kN (0.5, a bluff hull's full reflection, gave 60–85 kN beam on).
  double drift_coefficient = 0.15;
  /// Throws core::InputError naming the first value outside its range (param_fields).
  void validate() const;
};

/// The wave response as the keys of the vessel file's [waves] section, with units and ranges
/// (core/param_range.hpp): the one table validate(), the file reader and the docs use.
std::vector<core::ParamField> param_fields(WaveResponseParams& params);

/// JONSWAP spectral density S(ω) [m²·s/rad] at ω [rad/s] for H_s, T_p, γ (σ = 0.07 below the
/// peak, 0.09 above; normalised so that ∫S dω = H_s²/16).
double jonswap(double omega, double hs_m, double tp_s, double gamma = 3.3);

/// Mean wave drift force in BODY (X, Y, N) [N, N, N·m] of long-crested waves of significant
/// height hs_m [m] travelling towards beta_rad [rad] off the bow (0: from astern, π: head
/// seas): ½·c·ρ·g·(H_s²/16)·(B cos β, L sin β, 0), c the drift coefficient.
Eigen::Vector3d drift_force_b(const WaveResponseParams& response, double hs_m,
                              double beta_rad) noexcept;

/// The peak frequencies [rad/s] of the wave-frequency motion's spectra in surge, sway (the
/// wave amplitude's, both) and yaw (the wave slope's, which weighs short waves by k²), each
/// with the hull's short-wave attenuation: the wave model a DP observer filters per DOF.
Eigen::Vector3d response_peak_frequency(const SeaStateParams& sea,
                                        const WaveResponseParams& response);

/// How the wave-frequency motion's variance in surge, sway and yaw (the spectra of
/// response_peak_frequency) spreads over a wave model of several components per DOF, the n-th
/// at `ratios[n]` times the DOF's peak frequency (ratios increasing, the first 1): row d, column
/// n is the share of DOF d's variance nearest in log frequency to component n (the boundaries
/// at the geometric means of neighbouring components; below the first, the first's). Each row
/// sums to 1. Throws std::invalid_argument unless the ratios start at 1 and increase.
Eigen::MatrixXd response_variance_shares(const SeaStateParams& sea,
                                         const WaveResponseParams& response,
                                         const std::vector<double>& ratios);

/// One harmonic wave component.
struct WaveComponent {
  double omega;      ///< ω [rad/s]
  double amplitude;  ///< a = √(2 S(ω) Δω) [m]
  double phase;      ///< [rad]
};

/// The discretised sea: equal-width bins, one random frequency per bin and a random phase,
/// drawn from Rng(seed, "waves").
std::vector<WaveComponent> discretise(const SeaStateParams& sea, std::uint64_t seed);

/// 6-DOF wave-frequency motion: (surge, sway, heave) [m] in a heading-aligned frame and
/// (roll, pitch, yaw) [rad], with first and second time derivatives.
struct WaveMotion6 {
  Eigen::Matrix<double, 6, 1> position = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> velocity = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> acceleration = Eigen::Matrix<double, 6, 1>::Zero();
};

/// Generates WF motion at t = k·period for k = 0, 1, 2, … (advance() moves to the next sample).
class WaveMotion {
 public:
  WaveMotion(const SeaStateParams& sea, const WaveResponseParams& response, std::uint64_t seed,
             double period_s);

  /// The motion at the current sample for heading ψ [rad] (sets the relative wave direction).
  /// With the heading's rate ψ̇ [rad/s] and acceleration ψ̈ [rad/s²], velocity and acceleration
  /// are the exact derivatives of the position along a turning hull's path.
  WaveMotion6 motion(double heading_rad, double heading_rate = 0.0,
                     double heading_accel = 0.0) const;
  /// Moves to the next sample time.
  void advance() noexcept;
  /// Mean wave drift force in BODY (X, Y, N) [N, N, N·m] at heading ψ [rad].
  Eigen::Vector3d drift_force_b(double heading_rad) const noexcept;
  /// σ of the motion's position per DOF at a steady heading ψ [rad] (surge, sway, heave [m];
  /// roll, pitch, yaw [rad]): √(Σ A²/2) over the components, A each one's amplitude there.
  Eigen::Matrix<double, 6, 1> position_std(double heading_rad) const noexcept;
  const std::vector<WaveComponent>& components() const noexcept { return components_; }

 private:
  SeaStateParams sea_;
  WaveResponseParams response_;
  std::vector<WaveComponent> components_;
  // Per component: per-DOF transfer magnitude (without direction factor), phase lag, phasor.
  std::vector<Eigen::Matrix<double, 6, 1>> gain_;
  std::vector<std::array<std::complex<double>, 6>> lag_;  // e^{−j·lag} per DOF
  std::vector<std::complex<double>> phasor_;              // e^{j(ω t + φ)}
  std::vector<std::complex<double>> rotor_;               // e^{jω·period}
};

}  // namespace dynpos::model
