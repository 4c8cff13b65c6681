#pragma once
/// \file
/// The arms of further MRUs from the logger alone: (4.65) with the reference point at the
/// INS's MRU instead of the control origin, so A₀ is that MRU's own logged acceleration and no
/// velocity is needed. In BODY, with F the smoother of mru_observer.hpp applied to every term,
///   F(a_k) − F(a_imu) = F(M)·(l_k − l_imu),   M = S(ω)² + S(ω̇),
/// solved by the least squares of estimate_mru_arms() for l_k − l_imu. The accelerations may
/// be kinematic or specific force: gravity is the same at both units and cancels.

#include <string>
#include <vector>

#include "dynpos/calib/imu_series.hpp"
#include "dynpos/calib/mru_observer.hpp"
#include "dynpos/core/log.hpp"

namespace dynpos::calib {

/// Arms of the MRUs `names` (roles NAME.ax/ay/az of `log`, interpolated onto the IMU's time)
/// from the IMU [m, BODY], by `options`' method. The IMU's time axis should be uniform (a
/// logger's fixed rate). Throws core::InputError naming a missing role.
MruEstimateResult estimate_mru_arms_from_imu(const ImuSeries& imu, const core::Log& log,
                                             const std::vector<std::string>& names,
                                             double smooth_window_s = 1.0,
                                             const MruEstimateOptions& options = {});

}  // namespace dynpos::calib
