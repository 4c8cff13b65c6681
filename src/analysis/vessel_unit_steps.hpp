#pragma once
// The order steps of one unit in the logs of identify vessel (private to the module): the step
// detector on its shaft speed order, a FOPDT fit (3.7) of its logged shaft speed over each step,
// the same fit of a model's response to the same step at the log's samples, the unit's thrust
// map per log, and a vessel-file value from estimates (docs/theory.md, "The units").

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/ident/step_detector.hpp"
#include "dynpos/model/fopdt_truth.hpp"
#include "vessel_units.hpp"

namespace dynpos::analysis::vessel_units {

/// A model's shaft speed [rps] after an order step from → to [rps] at t = 0, from steady state.
using ModelResponse = std::function<model::StepResponse(double from, double to)>;

/// One order step of a unit and the FOPDT fit of its logged shaft speed over it.
struct LoggedStep {
  const LogUnits* log = nullptr;      ///< the log (outlives the step)
  const UnitColumns* unit = nullptr;  ///< the unit's columns in it
  ident::Step step;
  double time_constant_s = 0.0, time_constant_sigma_s = 0.0;
  double dead_time_s = 0.0, dead_time_sigma_s = 0.0;
  double delta_n_rps() const { return *step.u_after - *step.u_before; }
};

/// Every order step of `unit` in `logs` whose shaft speed has a FOPDT fit with σ (a fit that
/// failed, or with its dead time at its bound, is no estimate).
std::vector<LoggedStep> logged_steps(const std::vector<LogUnits>& logs, const std::string& unit);

/// The FOPDT fit of a model's response to a step, on the step's samples.
struct ModelFit {
  double time_constant_s = 0.0;
  double dead_time_s = 0.0;
};

/// A model's shaft speed [rps] at the log's samples over a step's window (NaN elsewhere and
/// where the log has no shaft speed): the two fits see the same window, sampling and shape.
using ModelSamples = std::function<std::vector<double>(const LoggedStep&)>;

/// `response` to the step's order levels as an ideal step at its step time.
ModelSamples ideal_step(ModelResponse response);

/// A step fitted on the log and on a model.
struct StepFit {
  const LoggedStep* logged = nullptr;
  ModelFit model;
};

/// The steps with the same FOPDT fit of the model's samples (those without are left out).
std::vector<StepFit> with_model(const std::vector<LoggedStep>& steps, const ModelSamples& model);

/// A unit's thrust map coefficients c₊, c₋ [N/rps²] (3.17), one estimate per log.
struct MapEstimates {
  std::vector<Estimate> c_forward, c_reverse;
};
MapEstimates thrust_maps(const std::vector<LogUnits>& logs, const std::string& unit);

/// The unit's logged dynamics, combined over the steps and logs, against the model's, and its
/// thrust map.
UnitIdentification dynamics(const std::string& unit, const std::vector<StepFit>& fits,
                            const MapEstimates& maps);

/// A value of the file from estimates: determined when σ/|value| ≤ max_rel, with the estimates'
/// count and logs; otherwise the start, with why and `excitation` (what would determine it).
VesselParameter parameter(const std::string& key, const std::string& unit, double start,
                          const std::vector<Estimate>& estimates, const std::string& how,
                          const std::string& excitation, double max_rel);

/// Into value and σ (NaN, NaN without estimates).
void set(const std::optional<Combined>& c, double& value, double& sigma);

}  // namespace dynpos::analysis::vessel_units
