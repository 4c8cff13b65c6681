#include "dynpos/ident/channel_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dynpos/core/error.hpp"

namespace dynpos::ident {
namespace {

core::InputError option_error(const std::string& what) {
  return core::InputError({{}, {}, {}, "channel integral"}, what);
}

}  // namespace

ChannelIntegral integrate_channel(std::span<const double> t, std::span<const double> x,
                                  double t_from_s, double t_to_s, const ChannelIntegralOptions& o) {
  if (t.size() != x.size()) throw option_error("time and channel lengths differ");
  if (!(std::isfinite(t_from_s) && std::isfinite(t_to_s) && t_to_s > t_from_s)) {
    throw option_error("the window must have t_to > t_from");
  }
  if (!(o.max_gap_s > 0.0)) throw option_error("max_gap_s must be > 0");
  if (!(o.min_coverage > 0.0 && o.min_coverage <= 1.0)) {
    throw option_error("min_coverage must be in (0, 1]");
  }
  // Valid samples inside the window.
  std::vector<std::pair<double, double>> v;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t_from_s || t[i] > t_to_s || std::isnan(x[i])) continue;
    v.emplace_back(t[i], o.absolute ? std::abs(x[i]) : x[i]);
  }
  ChannelIntegral r;
  r.samples = v.size();
  if (v.empty()) return r;
  double integral = 0.0;
  double covered = 0.0;
  // Held flat from the window edges to the first/last sample, if that edge is within a gap.
  const double head = v.front().first - t_from_s;
  if (head <= o.max_gap_s) {
    integral += head * v.front().second;
    covered += head;
  } else {
    r.longest_gap_s = head;
  }
  const double tail = t_to_s - v.back().first;
  if (tail <= o.max_gap_s) {
    integral += tail * v.back().second;
    covered += tail;
  } else {
    r.longest_gap_s = std::max(r.longest_gap_s, tail);
  }
  for (std::size_t k = 1; k < v.size(); ++k) {
    const double dt = v[k].first - v[k - 1].first;
    if (dt > o.max_gap_s) {
      r.longest_gap_s = std::max(r.longest_gap_s, dt);
      continue;
    }
    integral += 0.5 * (v[k].second + v[k - 1].second) * dt;
    covered += dt;
  }
  r.covered_s = covered;
  r.coverage = covered / (t_to_s - t_from_s);
  if (r.coverage + 1e-12 < o.min_coverage || covered <= 0.0) return r;
  r.integral = integral;
  r.mean = integral / covered;
  return r;
}

}  // namespace dynpos::ident
