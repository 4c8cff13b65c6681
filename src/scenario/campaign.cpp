#include "dynpos/scenario/campaign.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/sim/random.hpp"

namespace dynpos::scenario {
namespace {

// The key figures of a run, from its truth block by block.
class SummaryBuilder {
 public:
  explicit SummaryBuilder(RunSummary& summary) : s_(summary) {}

  void add(const core::Log& truth) {
    const auto& t = truth.time();
    const auto& u = truth.values("u");
    const auto& v = truth.values("v");
    const auto& r = truth.values("r");
    const auto& n = truth.values("north");
    const auto& e = truth.values("east");
    // Every shaft's power: the model's port, stb and tunnel, or a layout's units, in log order.
    std::vector<const std::vector<double>*> powers;
    for (const core::Channel& c : truth.channels()) {
      if (c.name.rfind("power.", 0) == 0) powers.push_back(&c.values);
    }
    for (std::size_t i = 0; i < t.size(); ++i) {
      Row row{t[i], n[i], e[i], {}};
      for (const std::vector<double>* p : powers) row.power_W.push_back((*p)[i]);
      s_.max_speed_mps = std::max(s_.max_speed_mps, std::hypot(u[i], v[i]));
      s_.max_yaw_rate_dps = std::max(s_.max_yaw_rate_dps, std::abs(r[i]) * 180.0 / M_PI);
      if (last_) {
        s_.distance_m += std::hypot(row.north - last_->north, row.east - last_->east);
        // Trapezoidal ∫P dt over the log samples (summed in this order: the same bits as ever).
        double sum = 0.0;
        for (const double p : row.power_W) sum += p;
        for (const double p : last_->power_W) sum += p;
        energy_J_ += 0.5 * (row.t - last_->t) * sum;
      }
      last_ = std::move(row);
    }
    s_.rows += t.size();
    s_.energy_kJ = energy_J_ / 1e3;
  }

 private:
  struct Row {
    double t, north, east;        // [s], [m], [m]
    std::vector<double> power_W;  // each shaft's power [W]
  };
  RunSummary& s_;
  std::optional<Row> last_;
  double energy_J_ = 0.0;
};

}  // namespace

std::uint64_t campaign_seed(std::uint64_t master_seed, const std::string& scenario_name) {
  return sim::stream_seed(master_seed, scenario_name);
}

std::vector<ScenarioSpec> load_campaign(const std::filesystem::path& scenario_dir) {
  std::vector<ScenarioSpec> specs;
  for (const std::string& name : list_scenarios(scenario_dir)) {
    specs.push_back(load_scenario(scenario_dir / (name + ".toml")));
  }
  if (specs.empty()) {
    throw core::InputError({scenario_dir.string(), {}, {}, {}}, "no scenario files found");
  }
  return specs;
}

std::vector<RunSummary> run_campaign(const std::vector<ScenarioSpec>& scenarios,
                                     const VesselConfig& vessel, std::uint64_t master_seed,
                                     const std::filesystem::path& out_dir, unsigned jobs) {
  std::vector<RunSummary> summaries(scenarios.size());
  // The longest runs first, so that a short one finishes the campaign, not a long one.
  std::vector<std::size_t> order(scenarios.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return scenarios[a].duration_s > scenarios[b].duration_s;
  });
  core::parallel_for(order.size(), jobs, [&](std::size_t k) {
    const ScenarioSpec& spec = scenarios[order[k]];
    const std::uint64_t seed = campaign_seed(master_seed, spec.name);
    const auto start = std::chrono::steady_clock::now();
    RunSummary s;
    s.name = spec.name;
    s.description = spec.description;
    s.duration_s = spec.duration_s;
    s.seed = seed;
    SummaryBuilder summary(s);
    run_scenario_into(spec, vessel, seed, out_dir / spec.name,
                      [&](const core::Log&, const core::Log& truth) { summary.add(truth); });
    s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summaries[order[k]] = std::move(s);
  });
  return summaries;
}

}  // namespace dynpos::scenario
