#include "dynpos/hybrid/derivative_sampler.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "dynpos/sim/noise.hpp"

namespace dynpos::hybrid {

DerivativeSampler::DerivativeSampler(Eigen::Index n, double sample_period_s, double noise_power,
                                     sim::Rng rng, SampleSpacing spacing)
    : period_(sample_period_s),
      spacing_(spacing),
      noise_std_(0.0),
      rng_(std::move(rng)),
      previous_(Eigen::VectorXd::Zero(std::max<Eigen::Index>(n, 0))),
      estimate_(Eigen::VectorXd::Zero(std::max<Eigen::Index>(n, 0))),
      previous_time_(std::numeric_limits<double>::quiet_NaN()),
      older_time_(std::numeric_limits<double>::quiet_NaN()) {
  if (n < 1) throw std::invalid_argument("DerivativeSampler: signal size must be >= 1");
  if (!(std::isfinite(sample_period_s) && sample_period_s > 0.0)) {
    throw std::invalid_argument("DerivativeSampler: sample period " +
                                std::to_string(sample_period_s) + " s must be finite and > 0");
  }
  if (!(std::isfinite(noise_power) && noise_power >= 0.0)) {
    throw std::invalid_argument("DerivativeSampler: noise power " + std::to_string(noise_power) +
                                " must be finite and >= 0");
  }
  noise_std_ = sim::discrete_std_from_psd(noise_power, sample_period_s);
}

bool DerivativeSampler::sample(double t, const Eigen::Ref<const Eigen::VectorXd>& y) {
  if (y.size() != previous_.size()) {
    throw std::invalid_argument("DerivativeSampler::sample: signal of size " +
                                std::to_string(y.size()) + ", expected " +
                                std::to_string(previous_.size()));
  }
  bool ready = false;
  if (has_previous_) {
    const double spacing = spacing_ == SampleSpacing::kNominal ? period_ : t - previous_time_;
    estimate_ = (y - previous_) / spacing;  // (5.80), (5.92)
    if (noise_std_ > 0.0) {
      for (Eigen::Index i = 0; i < estimate_.size(); ++i)
        estimate_(i) += noise_std_ * rng_.normal();
    }
    older_time_ = previous_time_;
    ready = true;
  }
  previous_ = y;
  previous_time_ = t;
  has_previous_ = true;
  return ready;
}

}  // namespace dynpos::hybrid
