// Internal: SplitMix64, a small random generator that costs nothing to start. Work split over
// threads takes one stream per item (stream(seed, item)), so its numbers do not depend on which
// thread draws them; unit() gives the same doubles on every platform, which the standard
// library's distributions do not promise.
#pragma once

#include <cstdint>

namespace vorocrust {

class SplitMix64 {
 public:
  using result_type = std::uint64_t;

  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  // The stream of item `item` of the work seeded by `seed`.
  static SplitMix64 stream(std::uint64_t seed, std::uint64_t item) { return SplitMix64(seed ^ mix(item + kGamma)); }

  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return ~result_type{0}; }
  result_type operator()() { return mix(state_ += kGamma); }
  // Uniform in [0, 1).
  double unit() { return static_cast<double>((*this)() >> 11) * 0x1.0p-53; }

 private:
  static constexpr std::uint64_t kGamma = 0x9E3779B97F4A7C15ull;
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t state_;
};

}  // namespace vorocrust
