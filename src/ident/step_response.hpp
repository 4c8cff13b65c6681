#pragma once
// The output of one step, cut from a log and reduced to what every step-response method needs:
// times relative to the step, the levels before and after (3.4)–(3.5), the noise level, level
// crossing times, and the steady-state check (private).

#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dynpos/ident/fit_status.hpp"
#include "dynpos/ident/step_detector.hpp"

namespace dynpos::ident::detail {

struct LevelOptions {
  std::optional<double> pre_step_s;
  double tail_fraction = 0.2;
  double steady_state_tolerance = 0.02;
  std::size_t min_samples = 20;
  std::string output_name;
};

struct StepResponse {
  double t_step = 0.0;
  std::vector<double> tau;  // t − t_step of the valid samples used, increasing
  std::vector<double> y;
  std::size_t n_pre = 0;  // the first n_pre samples have tau ≤ 0
  double tau_end = 0.0;   // t_end − t_step
  double y0 = 0.0;        // mean before the step
  double y_final = 0.0;   // mean over the tail
  double delta_y = 0.0;   // y_final − y0
  double noise_sigma = 0.0;
  std::vector<FitWarning> warnings;
};

/// Checks the options shared by the step-response fits; throws core::InputError under `owner`
/// ("FOPDT options") naming the bad value.
void validate_window_options(const std::optional<double>& pre_step_s, double tail_fraction,
                             double steady_state_tolerance, double min_r_squared,
                             std::size_t min_samples, const char* owner);

/// Cuts and checks the window; throws core::InputError for the bad-input cases of fit_fopdt().
StepResponse prepare_step_response(std::span<const double> t, std::span<const double> y,
                                   const Step& step, const LevelOptions& options);

/// Time (relative to the step) where the output has covered `fraction` of Δy. The samples from
/// the last one 3σ̂ below to the first one 3σ̂ above the level are fitted by a least-squares
/// quadratic in time whose crossing is taken (five samples or more: noisy data); with fewer, or
/// when the quadratic does not cross inside the stretch, the mean of the first and the last
/// linearly interpolated crossings. nullopt when the output never gets 3σ̂ past the level.
std::optional<double> crossing_time(const StepResponse& response, double fraction);

/// R² and RMS residual of a model over the response samples.
struct FitQuality {
  double r_squared = 0.0;
  double rms = 0.0;
};

template <typename Model>
FitQuality fit_quality(const StepResponse& response, const Model& model) {
  double mean = 0.0;
  for (double v : response.y) mean += v;
  mean /= static_cast<double>(response.y.size());
  double sse = 0.0;
  double sst = 0.0;
  for (std::size_t i = 0; i < response.y.size(); ++i) {
    const double r = response.y[i] - model(response.t_step + response.tau[i]);
    sse += r * r;
    sst += (response.y[i] - mean) * (response.y[i] - mean);
  }
  FitQuality q;
  q.r_squared = sst > 0.0 ? 1.0 - sse / sst : 0.0;
  q.rms = std::sqrt(sse / static_cast<double>(response.y.size()));
  return q;
}

}  // namespace dynpos::ident::detail
