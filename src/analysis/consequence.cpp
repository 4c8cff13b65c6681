#include "dynpos/analysis/consequence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/capability/consequence.hpp"
#include "dynpos/capability/environment_table.hpp"
#include "dynpos/core/angle.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {
namespace {

// The trailing means of b̂ over (t − window, t] at each point time, by one pass over the track.
class TrailingMean {
 public:
  TrailingMean(const control::ObserverTrack& track, double window_s)
      : track_(track), window_s_(window_s) {}

  // The mean of b̂ over (t − window, t] (a window without a sample: the last sample's b̂) and
  // the index of the last sample at or before t; t is not before the previous call's, nor
  // before the first sample.
  std::pair<Eigen::Vector3d, std::size_t> at(double t_s) {
    const auto& t = track_.t_s;
    for (; end_ < t.size() && t[end_] <= t_s + 1e-9; ++end_) sum_ += track_.estimate[end_].bias_n;
    for (; begin_ < end_ && t[begin_] <= t_s - window_s_ + 1e-9; ++begin_) {
      sum_ -= track_.estimate[begin_].bias_n;
    }
    if (end_ == begin_) return {track_.estimate[end_ - 1].bias_n, end_ - 1};
    return {sum_ / static_cast<double>(end_ - begin_), end_ - 1};
  }

 private:
  const control::ObserverTrack& track_;
  double window_s_;
  std::size_t begin_ = 0, end_ = 0;
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
};

ConsequencePoint point_at(const capability::FailureConsequence& consequence, double t_s,
                          const Eigen::Vector3d& bias_n, double heading_rad) {
  ConsequencePoint p;
  p.t_s = t_s;
  p.heading_rad = core::wrap_2pi(heading_rad);
  p.bias_n = bias_n;
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  p.load_b = {c * bias_n.x() + s * bias_n.y(), -s * bias_n.x() + c * bias_n.y(), bias_n.z()};
  const capability::FeasibilityPoint intact = consequence.intact(p.load_b);
  p.intact = intact.load_factor;
  p.intact_capped = intact.capped;
  const std::vector<capability::FeasibilityPoint> all = consequence.load_factors(p.load_b);
  for (std::size_t k = 0; k < all.size(); ++k) {
    p.factors.push_back(all[k].load_factor);
    if (all[k].load_factor < all[p.worst].load_factor) p.worst = k;
  }
  p.limiting = all.at(p.worst).limiting;
  return p;
}

}  // namespace

void ConsequenceRequest::validate() const {
  estimate.validate();
  if (!(std::isfinite(step_s) && step_s > 0.0)) {
    throw option_error("step", fmt::format("the step must be > 0 s, got {}", step_s), "e.g. 10");
  }
  if (!(std::isfinite(mean_window_s) && mean_window_s > 0.0)) {
    throw option_error(
        "window", fmt::format("the mean's window must be > 0 s, got {}", mean_window_s), "e.g. 60");
  }
}

ConsequenceReport run_consequence(const ConsequenceRequest& q) {
  q.validate();
  ConsequenceReport r;
  EstimateRequest eq = q.estimate;
  eq.out.clear();
  r.estimate = run_estimate(eq);
  r.step_s = q.step_s;
  r.mean_window_s = q.mean_window_s;
  r.csv = q.out;
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(vessel_file_or_default(q.estimate.vessel));
  r.layout = vessel.thrusters.empty() ? "model" : "[[thruster]]";
  const capability::FailureConsequence consequence(vessel);
  r.cases = consequence.cases();
  const control::ObserverTrack& track = r.estimate.track;
  const double first =
      std::max(track.start_s + q.estimate.settle_s + q.mean_window_s, track.t_s.front());
  TrailingMean mean(track, q.mean_window_s);
  for (double k = std::ceil(first / q.step_s - 1e-9);; k += 1.0) {
    const double t = k * q.step_s;
    if (t > track.t_s.back() + 1e-9) break;
    const auto [bias_n, last] = mean.at(t);
    r.points.push_back(point_at(consequence, t, bias_n, track.estimate[last].eta_n.z()));
  }
  if (r.points.empty()) {
    throw q.estimate.source.error(
        "time",
        fmt::format("the log ends at {:.1f} s, before the first point at {:.1f} s (the "
                    "observer's start {:.1f} s + settle {:g} s + window {:g} s)",
                    track.t_s.back(), first, track.start_s, q.estimate.settle_s, q.mean_window_s),
        "give a longer log, or a shorter --settle or --window");
  }
  return r;
}

ConsequenceSummary summarise(const ConsequenceReport& r) {
  ConsequenceSummary s;
  const std::size_t n = r.points.size();
  s.case_min.assign(r.cases.size(), 0);
  s.case_fraction_below_one.assign(r.cases.size(), 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const ConsequencePoint& p = r.points[i];
    if (p.margin() < r.points[s.smallest].margin()) s.smallest = i;
    if (p.intact < r.points[s.intact_min].intact) s.intact_min = i;
    s.fraction_negative += p.margin() < 0.0 ? 1.0 : 0.0;
    s.fraction_below_reserve += p.factors[p.worst] < capability::kDynamicAllowance ? 1.0 : 0.0;
    for (std::size_t k = 0; k < r.cases.size(); ++k) {
      if (p.factors[k] < r.points[s.case_min[k]].factors[k]) s.case_min[k] = i;
      s.case_fraction_below_one[k] += p.factors[k] < 1.0 ? 1.0 : 0.0;
    }
  }
  s.fraction_negative /= static_cast<double>(n);
  s.fraction_below_reserve /= static_cast<double>(n);
  for (double& f : s.case_fraction_below_one) f /= static_cast<double>(n);
  return s;
}

}  // namespace dynpos::analysis
