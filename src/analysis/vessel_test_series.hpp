#pragma once
// A logged test as the vessel fit reads it (private to the module): the roles the hull drive and
// the fit need, put on the re-simulation's time step.

#include <optional>
#include <string>
#include <vector>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/scenario/thrust_feedback.hpp"
#include "vessel_fit.hpp"
#include "vessel_units.hpp"

namespace dynpos::analysis::vessel_fit {

/// The roles `identify vessel` and `compare-trial` read.
bool wanted_role(const std::string& role);

/// A test read: the fit's inputs and measurements, cut into stretches, and the logged track
/// when there is one.
struct LoggedTest {
  FitTest whole;
  /// `whole` cut into stretches of about stretch_s, each fitted from its own start velocity and
  /// current (neighbours share their boundary sample).
  std::vector<FitTest> stretches;
  io::InputReport input;
  std::vector<double> north_m, east_m;  ///< at the drive samples; empty: no position logged
  /// Each unit's rpm, order and thrust as logged (the units' identification).
  vessel_units::LogUnits units;
};

/// Reads `source` (roles: wanted_role) and puts it on a step of step_s [s]: every input of
/// `feedback`'s units, the heading and the wind interpolated at the step's times (held before
/// the first and after the last sample), u, v, r at the logged samples at most every sample_s
/// [s]. Throws core::InputError naming the log for a role that is missing.
LoggedTest read_test(const LogSource& source, const scenario::ThrustFeedback& feedback,
                     double step_s, double sample_s, double stretch_s);

/// `whole` cut into stretches of about stretch_s [s] (at least half of it each).
std::vector<FitTest> cut(const FitTest& whole, double stretch_s);

}  // namespace dynpos::analysis::vessel_fit
