#include "dynpos/model/sea_state.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "dynpos/core/error.hpp"
#include "dynpos/sim/random.hpp"

namespace dynpos::model {
namespace {

constexpr double kG = 9.81;      // [m/s²]
constexpr double kRho = 1025.0;  // [kg/m³]
constexpr double kTwoPi = 2.0 * M_PI;

void require(bool ok, const std::string& what) {
  if (!ok) throw core::InputError({}, what);
}

// The vessel file's [waves] table (core/param_range.hpp).
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> fields(P& p) {
  return {
      {{"length_m", "m", 1, 500}, &p.length_m},
      {{"beam_m", "m", 0.5, 100}, &p.beam_m},
      {{"heave_period_s", "s", 0.5, 60}, &p.heave_period_s},
      {{"heave_damping", "1", 1e-3, 2}, &p.heave_damping},
      {{"roll_period_s", "s", 0.5, 60}, &p.roll_period_s},
      {{"roll_damping", "1", 1e-3, 2}, &p.roll_damping},
      {{"pitch_period_s", "s", 0.5, 60}, &p.pitch_period_s},
      {{"pitch_damping", "1", 1e-3, 2}, &p.pitch_damping},
      {{"yaw_factor", "1", 0, 10}, &p.yaw_factor},
      {{"drift_coefficient", "1", 0, 5}, &p.drift_coefficient},
  };
}

// Second-order resonance |H| and phase lag for a response driven quasi-statically at low ω.
void resonance(double omega, double period_s, double zeta, double& gain, double& lag) {
  const double ratio = omega * period_s / kTwoPi;
  const double re = 1.0 - ratio * ratio;
  const double im = 2.0 * zeta * ratio;
  gain = 1.0 / std::sqrt(re * re + im * im);
  lag = std::atan2(im, re);
}

// The hull's averaging of waves of deep-water number k [1/m] shorter than it.
double short_wave_attenuation(double k, double length_m) {
  const double ratio = length_m * k / kTwoPi;
  return 1.0 / (1.0 + ratio * ratio);
}

// Calls f(ω, S) on a fine grid of the sea's frequencies with S the unit-height spectra of the
// WF motion in surge and sway (the wave amplitude's) and yaw (the slope's, by k²), each with the
// hull's short-wave attenuation.
template <typename F>
void for_response_spectrum(const SeaStateParams& sea, const WaveResponseParams& response, F&& f) {
  const double wp = kTwoPi / sea.tp_s;
  const double lo = sea.omega_min_factor * wp, hi = sea.omega_max_factor * wp;
  constexpr int kSteps = 4000;
  for (int i = 0; i <= kSteps; ++i) {
    const double omega = lo + (hi - lo) * i / kSteps;
    const double k = omega * omega / kG;
    const double a = short_wave_attenuation(k, response.length_m);
    const double s = jonswap(omega, 1.0, sea.tp_s, sea.gamma) * a * a;
    f(omega, Eigen::Vector3d(s, s, s * k * k));
  }
}

}  // namespace

void SeaStateParams::validate() const {
  const double n = components;
  core::check_ranges("environment",
                     std::vector<core::ConstParamField>{{kSignificantWaveHeightRange, &hs_m},
                                                        {kPeakPeriodRange, &tp_s},
                                                        {kWaveComponentsRange, &n}});
  require(gamma >= 1 && gamma <= 7, "SeaStateParams.gamma must be in [1, 7]");
  require(std::isfinite(from_rad), "SeaStateParams.from_rad must be finite");
  require(omega_min_factor > 0 && omega_min_factor < 1,
          "SeaStateParams.omega_min_factor must be in (0, 1)");
  require(omega_max_factor > 1 && omega_max_factor < 20,
          "SeaStateParams.omega_max_factor must be in (1, 20)");
}

std::vector<core::ParamField> param_fields(WaveResponseParams& params) { return fields(params); }

void WaveResponseParams::validate() const { core::check_ranges("waves", fields(*this)); }

double jonswap(double omega, double hs_m, double tp_s, double gamma) {
  if (omega <= 0.0 || hs_m <= 0.0) return 0.0;
  const double wp = kTwoPi / tp_s;
  const double sigma = omega <= wp ? 0.07 : 0.09;
  const double x = wp / omega;
  // Pierson–Moskowitz shape in H_s, T_p, with the JONSWAP peak factor and the usual
  // normalisation A_γ = 1 − 0.287·ln γ (DNV-RP-C205).
  const double pm = 5.0 / 16.0 * hs_m * hs_m * std::pow(wp, 4) / std::pow(omega, 5) *
                    std::exp(-1.25 * x * x * x * x);
  const double r = std::exp(-(omega - wp) * (omega - wp) / (2.0 * sigma * sigma * wp * wp));
  return (1.0 - 0.287 * std::log(gamma)) * pm * std::pow(gamma, r);
}

Eigen::Vector3d response_peak_frequency(const SeaStateParams& sea,
                                        const WaveResponseParams& response) {
  Eigen::Vector3d peak = Eigen::Vector3d::Constant(kTwoPi / sea.tp_s),
                  best = Eigen::Vector3d::Zero();
  for_response_spectrum(sea, response, [&](double omega, const Eigen::Vector3d& s) {
    for (int d = 0; d < 3; ++d) {
      if (s[d] > best[d]) best[d] = s[d], peak[d] = omega;
    }
  });
  return peak;
}

Eigen::MatrixXd response_variance_shares(const SeaStateParams& sea,
                                         const WaveResponseParams& response,
                                         const std::vector<double>& ratios) {
  if (ratios.empty() || ratios.front() != 1.0 ||
      std::adjacent_find(ratios.begin(), ratios.end(), std::greater_equal<>()) != ratios.end()) {
    throw std::invalid_argument(
        "response_variance_shares: the ratios must start at 1 and increase");
  }
  const Eigen::Vector3d peak = response_peak_frequency(sea, response);
  const auto n = static_cast<Eigen::Index>(ratios.size());
  Eigen::MatrixXd shares = Eigen::MatrixXd::Zero(3, n);
  for_response_spectrum(sea, response, [&](double omega, const Eigen::Vector3d& s) {
    for (int d = 0; d < 3; ++d) {
      Eigen::Index c = 0;  // the last component whose lower boundary lies below ω
      while (c + 1 < n && omega > peak[d] * std::sqrt(ratios[c] * ratios[c + 1])) ++c;
      shares(d, c) += s[d];
    }
  });
  for (int d = 0; d < 3; ++d) {
    const double total = shares.row(d).sum();
    if (total > 0.0) {
      shares.row(d) /= total;
    } else {
      shares.row(d).setZero(), shares(d, 0) = 1.0;  // calm: one component
    }
  }
  return shares;
}

std::vector<WaveComponent> discretise(const SeaStateParams& sea, std::uint64_t seed) {
  sea.validate();
  std::vector<WaveComponent> out;
  if (sea.hs_m <= 0.0) return out;
  sim::Rng rng(seed, "waves");
  const double wp = kTwoPi / sea.tp_s;
  const double lo = sea.omega_min_factor * wp;
  const double width = (sea.omega_max_factor - sea.omega_min_factor) * wp / sea.components;
  out.reserve(static_cast<std::size_t>(sea.components));
  for (int i = 0; i < sea.components; ++i) {
    const double omega = lo + (i + rng.uniform()) * width;
    const double amplitude = std::sqrt(2.0 * jonswap(omega, sea.hs_m, sea.tp_s, sea.gamma) * width);
    out.push_back({omega, amplitude, rng.uniform(0.0, kTwoPi)});
  }
  return out;
}

WaveMotion::WaveMotion(const SeaStateParams& sea, const WaveResponseParams& response,
                       std::uint64_t seed, double period_s)
    : sea_(sea), response_(response), components_(discretise(sea, seed)) {
  response_.validate();
  if (!(period_s > 0.0)) throw std::invalid_argument("WaveMotion period_s must be > 0");
  const std::size_t n = components_.size();
  gain_.resize(n);
  lag_.resize(n);
  phasor_.resize(n);
  rotor_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const WaveComponent& c = components_[i];
    const double k = c.omega * c.omega / kG;  // deep-water wave number
    const double attenuation = short_wave_attenuation(k, response_.length_m);
    double g_heave = 0, l_heave = 0, g_roll = 0, l_roll = 0, g_pitch = 0, l_pitch = 0;
    resonance(c.omega, response_.heave_period_s, response_.heave_damping, g_heave, l_heave);
    resonance(c.omega, response_.roll_period_s, response_.roll_damping, g_roll, l_roll);
    resonance(c.omega, response_.pitch_period_s, response_.pitch_damping, g_pitch, l_pitch);
    const double slope = k * c.amplitude;  // wave slope amplitude [rad]
    // Horizontal: the orbital motion of the water (amplitude a), heave: a through the
    // heave resonance; angles: the wave slope through the roll/pitch resonances.
    gain_[i] << c.amplitude * attenuation, c.amplitude * attenuation,
        c.amplitude * attenuation * g_heave, slope * attenuation * g_roll,
        slope * attenuation * g_pitch, slope * attenuation * response_.yaw_factor;
    const double lags[6] = {0.0, 0.0, l_heave, l_roll, l_pitch, 0.0};
    for (int dof = 0; dof < 6; ++dof) lag_[i][dof] = std::polar(1.0, -lags[dof]);
    phasor_[i] = std::polar(1.0, c.phase);
    rotor_[i] = std::polar(1.0, c.omega * period_s);
  }
}

WaveMotion6 WaveMotion::motion(double heading_rad, double heading_rate,
                               double heading_accel) const {
  // β: direction the waves travel to, relative to the bow (0 = following seas). Each DOF is
  // d(β)·x_raw(t); β̇ = −ψ̇ and β̈ = −ψ̈ add the terms of a turning hull.
  const double beta = sea_.from_rad + M_PI - heading_rad;
  const double beta_d = -heading_rate, beta_dd = -heading_accel;
  const double cb = std::cos(beta), sb = std::sin(beta);
  const double c2b = std::cos(2.0 * beta), s2b = std::sin(2.0 * beta);
  Eigen::Matrix<double, 6, 1> d, d1, d2;  // d(β), d′(β), d″(β)
  d << cb, sb, 1.0, sb, -cb, s2b;
  d1 << -sb, cb, 0.0, cb, sb, 2.0 * c2b;
  d2 << -cb, -sb, 0.0, -sb, cb, -4.0 * s2b;
  Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero(), v = x, a = x;
  // The complex products are written out: the same numbers as std::complex's operator*, without
  // its check for a NaN result (which keeps the loop from running straight through).
  for (std::size_t i = 0; i < components_.size(); ++i) {
    const double w = components_[i].omega;
    const double p_re = phasor_[i].real(), p_im = phasor_[i].imag();
    for (int dof = 0; dof < 6; ++dof) {
      const double l_re = lag_[i][dof].real(), l_im = lag_[i][dof].imag();
      const std::complex<double> z(p_re * l_re - p_im * l_im, p_re * l_im + p_im * l_re);
      const double amp = gain_[i][dof];
      // x = A cos(ωt + φ − lag), ẋ = −Aω sin(·), ẍ = −Aω² cos(·).
      x[dof] += amp * z.real();
      v[dof] -= amp * w * z.imag();
      a[dof] -= amp * w * w * z.real();
    }
  }
  WaveMotion6 out;
  out.position = d.cwiseProduct(x);
  out.velocity = d.cwiseProduct(v) + beta_d * d1.cwiseProduct(x);
  out.acceleration = d.cwiseProduct(a) + 2.0 * beta_d * d1.cwiseProduct(v) +
                     (beta_d * beta_d * d2 + beta_dd * d1).cwiseProduct(x);
  return out;
}

Eigen::Matrix<double, 6, 1> WaveMotion::position_std(double heading_rad) const noexcept {
  const double beta = sea_.from_rad + M_PI - heading_rad;  // as in motion()
  Eigen::Matrix<double, 6, 1> d;
  d << std::cos(beta), std::sin(beta), 1.0, std::sin(beta), -std::cos(beta), std::sin(2.0 * beta);
  Eigen::Matrix<double, 6, 1> var = Eigen::Matrix<double, 6, 1>::Zero();
  for (const Eigen::Matrix<double, 6, 1>& g : gain_) var += 0.5 * g.cwiseProduct(d).cwiseAbs2();
  return var.cwiseSqrt();
}

void WaveMotion::advance() noexcept {
  for (std::size_t i = 0; i < phasor_.size(); ++i) {  // phasor × rotor, written out as above
    const double p_re = phasor_[i].real(), p_im = phasor_[i].imag();
    const double r_re = rotor_[i].real(), r_im = rotor_[i].imag();
    phasor_[i] = {p_re * r_re - p_im * r_im, p_re * r_im + p_im * r_re};
  }
}

Eigen::Vector3d drift_force_b(const WaveResponseParams& response, double hs_m,
                              double beta_rad) noexcept {
  const double scale = 0.5 * response.drift_coefficient * kRho * kG * hs_m * hs_m / 16.0;
  return {scale * response.beam_m * std::cos(beta_rad),
          scale * response.length_m * std::sin(beta_rad), 0.0};
}

Eigen::Vector3d WaveMotion::drift_force_b(double heading_rad) const noexcept {
  return model::drift_force_b(response_, sea_.hs_m, sea_.from_rad + M_PI - heading_rad);
}

}  // namespace dynpos::model
