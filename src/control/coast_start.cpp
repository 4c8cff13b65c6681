#include "dynpos/control/coast_start.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dynpos::control {
namespace {

// Whether y has the position (channel 0) or the heading (1).
bool has(const Eigen::Vector3d& y_n, int channel) {
  return channel == 0 ? !std::isnan(y_n.x()) && !std::isnan(y_n.y()) : !std::isnan(y_n.z());
}

// The DOFs of a channel: N, E (u, v) for the position, ψ (r) for the heading.
Eigen::Array3d dofs(int channel) {
  return channel == 0 ? Eigen::Array3d(1.0, 1.0, 0.0) : Eigen::Array3d(0.0, 0.0, 1.0);
}

}  // namespace

CoastStart::CoastStart(const Eigen::Vector3d& wave_peak_frequency_rad_s, double lost_after_s)
    : wave_peak_frequency_rad_s_(wave_peak_frequency_rad_s), lost_after_s_(lost_after_s) {
  if (!(lost_after_s >= 0.0) || !std::isfinite(lost_after_s)) {
    throw std::invalid_argument("observer coast: the time before a loss must be finite and >= 0");
  }
}

void CoastStart::start_if_lost(const Eigen::Vector3d& y_n, Eigen::Ref<Eigen::Vector3d> nu_b,
                               Eigen::Ref<Eigen::Vector3d> bias_n) {
  for (int c = 0; c < 2; ++c) {
    Channel& ch = channel_[c];
    if (has(y_n, c)) {
      ch = Channel{};
    } else if (!ch.lost && ch.missing_s > lost_after_s_ - 1e-9) {
      ch.lost = true;
      const Eigen::Array3d d = dofs(c);
      nu_b = (d * nu_mean_b_.array() + (1.0 - d) * nu_b.array()).matrix();
      bias_n = (d * bias_mean_n_.array() + (1.0 - d) * bias_n.array()).matrix();
    }
  }
}

void CoastStart::track(const Eigen::Vector3d& nu_b, const Eigen::Vector3d& bias_n, double dt_s) {
  Eigen::Array3d follow = Eigen::Array3d::Zero();
  for (int c = 0; c < 2; ++c) {
    channel_[c].missing_s += dt_s;  // the age of the last sample at the next step
    if (!channel_[c].lost) follow += dofs(c);
  }
  const Eigen::Vector3d alpha =
      follow *
      (1.0 - (-dt_s * wave_peak_frequency_rad_s_.array() / (2.0 * std::numbers::pi)).exp());
  nu_mean_b_ += alpha.cwiseProduct(nu_b - nu_mean_b_);
  bias_mean_n_ += alpha.cwiseProduct(bias_n - bias_mean_n_);
}

}  // namespace dynpos::control
