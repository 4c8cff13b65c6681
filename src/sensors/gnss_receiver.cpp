#include "dynpos/sensors/gnss_receiver.hpp"

#include <cmath>

#include "param_tables.hpp"

namespace dynpos::sensors {

void GeodeticOrigin::validate() const {
  core::check_ranges("sensors", detail::origin_fields(*this));
}

void GnssParams::validate() const { core::check_ranges(name, detail::gnss_fields(*this)); }

namespace {

sim::Rng stream(std::uint64_t seed, const std::string& name, const char* channel) {
  return sim::Rng(seed, name + "." + channel);
}

}  // namespace

GnssReceiver::GnssReceiver(const GnssParams& params, const GeodeticOrigin& origin, double period_s,
                           std::uint64_t seed)
    : params_(params),
      frame_({origin.lat_deg, origin.lon_deg, origin.height_m}),
      noise_{sim::WhiteNoise(params.horizontal_std_m, stream(seed, params.name, "noise.north")),
             sim::WhiteNoise(params.horizontal_std_m, stream(seed, params.name, "noise.east")),
             sim::WhiteNoise(params.vertical_std_m, stream(seed, params.name, "noise.down"))},
      bias_{
          sim::GaussMarkov::with_stationary_std(params.bias_time_constant_s, params.bias_std_m,
                                                period_s, stream(seed, params.name, "bias.north")),
          sim::GaussMarkov::with_stationary_std(params.bias_time_constant_s, params.bias_std_m,
                                                period_s, stream(seed, params.name, "bias.east")),
          sim::GaussMarkov::with_stationary_std(params.bias_time_constant_s, params.bias_std_m,
                                                period_s, stream(seed, params.name, "bias.down"))} {
  params_.validate();
  origin.validate();
  for (sim::GaussMarkov& b : bias_) b.reset_stationary();
}

GnssFix GnssReceiver::measure(const RigidBodyMotion& m) {
  Eigen::Vector3d p_n = point_position_n(m, params_.lever_arm_b);
  for (int i = 0; i < 3; ++i) {
    if (noise_[i].std_dev() > 0.0) p_n[i] += noise_[i].sample();
    if (params_.bias_std_m > 0.0) {
      p_n[i] += bias_[i].value();
      bias_[i].step();
    }
  }
  GnssFix fix;
  fix.p_n = p_n;
  const core::GeodeticPoint point = frame_.to_geodetic(p_n);
  fix.lat_deg = point.lat_deg;
  fix.lon_deg = point.lon_deg;
  fix.height_m = point.height_m;
  return fix;
}

Eigen::Vector3d GnssReceiver::to_local_n(double lat_deg, double lon_deg, double height_m) const {
  return frame_.to_ned({lat_deg, lon_deg, height_m});
}

}  // namespace dynpos::sensors
