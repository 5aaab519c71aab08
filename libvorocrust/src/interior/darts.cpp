// Dart throwing over the grown box (paper A.5).
#include "interior/interior_sampler.hpp"

#include <optional>
#include <random>

namespace vorocrust::interior {

// Uniform darts over the grown box until `misses` darts in a row land in a ball.
void InteriorSampler::throw_darts() {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int misses = 0; misses < options_.misses;) {
    const Point z = box_.lo + (box_.hi - box_.lo).cwiseProduct(Point(unit(rng_), unit(rng_), unit(rng_)));
    if (const std::optional<Seed> seed = admit(z)) {
      add(*seed);
      ++stats_.darts;
      misses = 0;
    } else {
      ++misses;
    }
  }
}

}  // namespace vorocrust::interior
