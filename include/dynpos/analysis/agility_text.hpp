#pragma once
/// \file
/// The options of `identify agility` that a command line gives as comma-separated numbers: a
/// step window and the current as observed.

#include <string>

#include "dynpos/analysis/agility.hpp"
#include "dynpos/ident/agility.hpp"

namespace dynpos::analysis {

/// T_STEP,T_END,DIR_DEG[,THRUST_PCT[,YAW_PCT]] as a window (thrust 100 % when not given, no yaw
/// when not given); option_error("window") for an item that is not a number or another count.
ident::AgilityWindow parse_agility_window(const std::string& spec);

/// SPEED_MPS,TO_DEG as the current as observed (the request judges the values);
/// option_error("current") for an item that is not a number or another count.
ObservedCurrent parse_observed_current(const std::string& spec);

}  // namespace dynpos::analysis
