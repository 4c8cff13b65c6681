#pragma once
/// \file
/// Deterministic, portable random numbers for the simulator.
///
/// std::normal_distribution and std::uniform_real_distribution are implemented differently by
/// different standard libraries, so logs would not be bit-identical across platforms. The engine
/// here is std::mt19937_64 (its output sequence is fixed by the C++ standard) and the
/// distributions are our own. Each noise source owns an Rng seeded from (master seed, source id),
/// so adding a source does not change the numbers any other source draws.

#include <cstdint>
#include <random>
#include <string_view>

namespace dynpos::sim {

/// SplitMix64 finaliser: a well-mixed 64-bit hash of x.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

/// FNV-1a hash of a source name, for naming noise streams ("gnss1.north", "wind.gust").
constexpr std::uint64_t hash_name(std::string_view name) {
  std::uint64_t h = 0xCBF29CE484222325ULL;
  for (char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001B3ULL;
  }
  return h;
}

/// The seed of the stream `source` under a master seed.
constexpr std::uint64_t stream_seed(std::uint64_t master_seed, std::string_view source) {
  return mix64(master_seed ^ mix64(hash_name(source)));
}

/// A seeded random stream with portable uniform and normal samplers.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  Rng(std::uint64_t master_seed, std::string_view source)
      : engine_(stream_seed(master_seed, source)) {}

  /// Uniform on [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  /// Uniform on [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  /// Standard normal N(0, 1) by the Marsaglia polar method (second value cached).
  double normal();

  /// N(mean, std²).
  double normal(double mean, double std_dev) { return mean + std_dev * normal(); }

  std::uint64_t next_u64() { return engine_(); }

 private:
  std::mt19937_64 engine_;
  double cached_ = 0.0;
  bool has_cached_ = false;
};

}  // namespace dynpos::sim
