#pragma once
// The parameter tables of the sensors (core/param_range.hpp), shared by their validate()s and
// the vessel file's sections (sensor_suite.hpp). Each is a template over the struct or its
// const, so one list serves reading and checking.

#include <string>
#include <vector>

#include "dynpos/core/param_range.hpp"
#include "dynpos/sensors/gnss_receiver.hpp"
#include "dynpos/sensors/mru.hpp"
#include "dynpos/sensors/scalar_sensor.hpp"
#include "dynpos/sensors/sensor_timing.hpp"

namespace dynpos::sensors::detail {

template <typename P>
using Fields = std::vector<core::BasicParamField<core::ParamValue<P>>>;

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr double kRpmToRps = 1.0 / 60.0;

template <typename P>
void append(Fields<P>& to, const Fields<P>& more) {
  to.insert(to.end(), more.begin(), more.end());
}

// PREFIXrate_hz and PREFIXtime_offset_s.
template <typename P>
Fields<P> timing_fields(P& t, const std::string& prefix = "") {
  return {{{prefix + "rate_hz", "Hz", 0, 1000}, &t.rate_hz},
          {{prefix + "time_offset_s", "s", 0, 60}, &t.time_offset_s}};
}

// The geodetic origin of the local frame, keys of the [sensors] section.
template <typename P>
Fields<P> origin_fields(P& o) {
  return {
      {{"origin_lat_deg", "deg", -90, 90}, &o.lat_deg},
      {{"origin_lon_deg", "deg", -180, 180}, &o.lon_deg},
      {{"origin_height_m", "m", -1000, 10000}, &o.height_m},
  };
}

template <typename P>
Fields<P> lever_arm_fields(P& lever_arm_b) {
  return {
      {{"x_m", "m", -500, 500}, &lever_arm_b[0]},
      {{"y_m", "m", -500, 500}, &lever_arm_b[1]},
      {{"z_m", "m", -500, 500}, &lever_arm_b[2]},
  };
}

template <typename P>
Fields<P> gnss_fields(P& g) {
  Fields<P> f = lever_arm_fields(g.lever_arm_b);
  append<P>(f, timing_fields(g.timing));
  append<P>(f, {
                   {{"horizontal_std_m", "m", 0, 100}, &g.horizontal_std_m},
                   {{"vertical_std_m", "m", 0, 100}, &g.vertical_std_m},
                   {{"bias_std_m", "m", 0, 100}, &g.bias_std_m},
                   {{"bias_time_constant_s", "s", 1e-3, 1e7}, &g.bias_time_constant_s},
               });
  return f;
}

template <typename P>
Fields<P> mru_fields(P& m) {
  Fields<P> f = lever_arm_fields(m.lever_arm_b);
  append<P>(f, timing_fields(m.timing));
  append<P>(
      f, {
             {{"angle_std_deg", "deg", 0, 10, false, false, kDegToRad}, &m.angle_std_rad},
             {{"rate_std_deg_s", "deg/s", 0, 10, false, false, kDegToRad}, &m.rate_std_rad_s},
             {{"accel_std_mps2", "m/s²", 0, 10}, &m.accel_std_mps2},
             {{"accel_bias_std_mps2", "m/s²", 0, 10}, &m.accel_bias_std_mps2},
             {{"accel_bias_time_constant_s", "s", 1e-3, 1e7}, &m.accel_bias_time_constant_s},
             {{"angle_bias_std_deg", "deg", 0, 10, false, false, kDegToRad}, &m.angle_bias_std_rad},
             {{"angle_bias_time_constant_s", "s", 1e-3, 1e7}, &m.angle_bias_time_constant_s},
             {{"rate_bias_std_deg_s", "deg/s", 0, 10, false, false, kDegToRad},
              &m.rate_bias_std_rad_s},
             {{"rate_bias_time_constant_s", "s", 1e-3, 1e7}, &m.rate_bias_time_constant_s},
         });
  return f;
}

// How a channel's values are written in the vessel file: the unit that ends its keys ("mps"),
// the unit as written elsewhere ("m/s"), the factor to SI and the largest noise, bias or
// resolution [unit].
struct ChannelUnit {
  const char* suffix;
  const char* unit;
  double to_si;
  double max;
};

// A channel's noise keys PREFIXstd_UNIT, PREFIXbias_std_UNIT, PREFIXbias_time_constant_s,
// PREFIXresolution_UNIT.
template <typename P>
Fields<P> noise_fields(P& n, const std::string& prefix, const ChannelUnit& u) {
  const std::string suffix = u.suffix;
  return {
      {{prefix + "std_" + suffix, u.unit, 0, u.max, false, false, u.to_si}, &n.noise_std},
      {{prefix + "bias_std_" + suffix, u.unit, 0, u.max, false, false, u.to_si}, &n.bias_std},
      {{prefix + "bias_time_constant_s", "s", 1e-3, 1e7}, &n.bias_time_constant_s},
      {{prefix + "resolution_" + suffix, u.unit, 0, u.max, false, false, u.to_si}, &n.resolution},
  };
}

}  // namespace dynpos::sensors::detail
