#include "dynpos/calib/imu_mru_arms.hpp"

#include "dynpos/core/error.hpp"
#include "resample_onto.hpp"

namespace dynpos::calib {
namespace {

// Keeps the samples from the first to the last where every unit's acceleration is present.
void trim_to_common_span(MruRawSamples& raw) {
  auto ok = [&](std::size_t i) {
    for (const auto& a : raw.a_b_mps2)
      if (!a[i].allFinite()) return false;
    return true;
  };
  std::size_t b = 0, e = raw.t_s.size();
  while (b < e && !ok(b)) ++b;
  while (e > b && !ok(e - 1)) --e;
  auto cut = [&](auto& v) {
    v = {v.begin() + static_cast<long>(b), v.begin() + static_cast<long>(e)};
  };
  cut(raw.t_s);
  cut(raw.theta_rad);
  cut(raw.omega_b_rps);
  cut(raw.v_b_mps);
  for (auto& a : raw.a_b_mps2) cut(a);
  for (std::size_t i = 0; i < raw.t_s.size(); ++i)
    if (!ok(i))
      throw core::InputError({{}, {}, {}, raw.names.front() + ".ax"},
                             "an MRU's accelerations have gaps inside the IMU's time",
                             "log every MRU over the whole maneuver");
}

}  // namespace

MruEstimateResult estimate_mru_arms_from_imu(const ImuSeries& imu, const core::Log& log,
                                             const std::vector<std::string>& names,
                                             double smooth_window_s,
                                             const MruEstimateOptions& options) {
  MruRawSamples raw;
  raw.t_s = imu.t_s;
  raw.theta_rad = imu.theta_rad;
  raw.omega_b_rps = imu.omega_b_rps;
  raw.v_b_mps.assign(imu.size(), Eigen::Vector3d::Zero());  // a₀ comes from the IMU instead
  raw.names = names;
  raw.names.push_back(imu.name);
  for (const std::string& name : names) {
    std::vector<std::vector<double>> axes;
    for (const char* f : {".ax", ".ay", ".az"}) {
      if (!log.has(name + f))
        throw core::InputError({{}, {}, {}, name + f}, "the MRU '" + name + "' has no " + name + f,
                               "map it with --col " + name + f + "=COLUMN");
      axes.push_back(detail::resample_onto(log.time(), log.values(name + f), imu.t_s, false));
    }
    std::vector<Eigen::Vector3d> a(imu.size());
    for (std::size_t i = 0; i < imu.size(); ++i) a[i] = {axes[0][i], axes[1][i], axes[2][i]};
    raw.a_b_mps2.push_back(std::move(a));
  }
  raw.a_b_mps2.push_back(imu.accel_b_mps2);
  trim_to_common_span(raw);
  MruSignalOptions so;
  so.accel = imu.accel;
  so.smooth_window_s = smooth_window_s;
  MruSignals s = mru_signals_from_samples(raw, so);
  // F(a_k) − F(a_imu) against a₀ = 0: the difference of two units on one rigid body.
  const std::vector<Eigen::Vector3d> a_imu = s.a_b_mps2.back();
  s.a_b_mps2.pop_back();
  s.names.pop_back();
  for (auto& a : s.a_b_mps2)
    for (std::size_t i = 0; i < a.size(); ++i) a[i] -= a_imu[i];
  for (auto& a0 : s.a0_b_mps2) a0.setZero();
  // The gyro noise n squared biases F(S(ω)²) by E[S(n)²] = diag(σ²) − tr(diag(σ²))·I: at
  // 0.03 °/s and a 1.7 °/s turn that is 0.07 % of the centripetal term, 1 cm on a 15 m arm.
  const Eigen::Vector3d var = white_noise_std(raw.omega_b_rps).array().square();
  const Eigen::Matrix3d bias =
      Eigen::Matrix3d(var.asDiagonal()) - var.sum() * Eigen::Matrix3d::Identity();
  for (auto& M : s.M_b) M -= bias;
  return estimate_mru_arms(s, options);
}

}  // namespace dynpos::calib
