// MRU lever arms (thesis 4.3): G(t) of Proposition 3, the option parsers, the signal
// preparation from a mixed-rate log, and input errors.

#include "dynpos/calib/mru_observer.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "dynpos/core/error.hpp"
#include "dynpos/core/rotation.hpp"

namespace dynpos::calib {
namespace {

// Example 3 of the thesis: r = 1, ṗ = 0.1, ṙ = 0.1, everything else 0. Multiplying out (4.77)
// by hand gives G = [−0.3 1 0.2; −1 −0.3 0; 0.1 0 0]; the thesis prints −0.1 for G₂₃, but
// row 2 of ṠS is (0, −0.1, 0) and of 2SṠ is (0, −0.2, 0), so G₂₃ = 0. Both have full rank, the
// example's conclusion (det = 0.006). Exact arithmetic, so 1e-12.
TEST(MruObserver, GMatrixMatchesExample3) {
  const Eigen::Matrix3d G = mru_g_matrix({0.0, 0.0, 1.0}, {0.1, 0.0, 0.1}, Eigen::Vector3d::Zero());
  Eigen::Matrix3d expected;
  expected << -0.3, 1, 0.2, -1, -0.3, 0, 0.1, 0, 0;
  EXPECT_LT((G - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(G.determinant(), 0.006, 1e-12);
}

TEST(MruObserver, ParsesOptions) {
  EXPECT_EQ(parse_mru_accel("specific-force"), MruAccel::kSpecificForce);
  EXPECT_EQ(parse_mru_accel("kinematic"), MruAccel::kKinematic);
  EXPECT_FALSE(parse_mru_accel("gravity"));
  EXPECT_EQ(parse_mru_method("observer"), MruMethod::kObserver);
  EXPECT_FALSE(parse_mru_method("kalman"));
  EXPECT_EQ(to_string(MruMethod::kLsq), "lsq");
}

// One MRU at l on pure rotation about a fixed origin (ν = 0): a = ω̇ × l + ω × (ω × l), (4.65)
// in BODY. Motion at 100 Hz, the MRU in blank-celled rows of the same log at 50 Hz (mixed
// rates), heading wrapping through 360°. Least squares must return l to 1 mm (noise-free; the
// interpolation of the 50 Hz channel onto the grid is exact at its own samples).
TEST(MruObserver, MixedRateLogRecoversArm) {
  const Eigen::Vector3d l(2.0, -1.0, 3.0);
  const auto omega = [](double t) {
    return Eigen::Vector3d(0.05 * std::cos(t), 0.04 * std::cos(0.8 * t + 1), 0.03);
  };
  std::vector<double> time;
  for (int i = 0; i <= 20000; ++i) time.push_back(0.01 * i);
  core::Log log(time);
  std::vector<double> cols[11];
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double t = time[i];
    const Eigen::Vector3d w = omega(t);
    const Eigen::Vector3d wd = (omega(t + 1e-4) - omega(t - 1e-4)) / 2e-4;
    const Eigen::Vector3d a = wd.cross(l) + w.cross(w.cross(l));
    // Attitude only enters through R (not used by least squares); heading wraps at 2π.
    const double vals[11] = {
        0.0,   0.0,  std::fmod(6.0 + 0.03 * t, 2 * M_PI), w.x(), w.y(), w.z(), 0.0, 0.0, a.x(),
        a.y(), a.z()};
    for (int c = 0; c < 11; ++c) {
      const bool mru = c >= 8;
      cols[c].push_back(mru && i % 2 == 1 ? core::kMissing : vals[c]);
    }
  }
  const char* names[11] = {"roll", "pitch", "heading", "p",       "q",      "r",
                           "u",    "v",     "mru1.ax", "mru1.ay", "mru1.az"};
  for (int c = 0; c < 11; ++c) log.add_channel(names[c], "", cols[c]);
  const MruSignals s = mru_signals_from_logs(log, {{"mru1", &log, "log.csv"}});
  EXPECT_FALSE(s.notes.empty());  // w not logged
  const MruEstimateResult r = estimate_mru_arms(s);
  ASSERT_EQ(r.status, core::Status::kOk);
  EXPECT_LT((r.arms[0].l_b_m - l).norm(), 1e-3);
}

TEST(MruObserver, MissingRoleAndShortLogAreInputErrors) {
  core::Log log(std::vector<double>{0.0, 0.01, 0.02});
  for (const char* n : {"roll", "pitch", "heading", "p", "q", "r", "u", "v"}) {
    log.add_channel(n, "", {0.0, 0.0, 0.0});
  }
  EXPECT_THROW(mru_signals_from_logs(log, {{"mru1", &log, "x.csv"}}), core::InputError);
  for (const char* n : {"mru1.ax", "mru1.ay", "mru1.az"}) log.add_channel(n, "", {0.0, 0.0, 0.0});
  EXPECT_THROW(mru_signals_from_logs(log, {{"mru1", &log, "x.csv"}}), core::InputError);
  EXPECT_THROW(mru_signals_from_logs(log, {}), core::InputError);
}

TEST(MruObserver, OptionsValidate) {
  MruEstimateOptions o;
  o.converge_fraction = 1.0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::calib
