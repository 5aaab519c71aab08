// A shuffle from a fixed seed that gives the same order on every platform (the standard
// library's shuffles and distributions differ between implementations), for the randomised
// algorithms whose answers must be reproducible.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace vorocrust::quality {

template <class T>
void fixed_shuffle(std::vector<T>& items, std::uint64_t seed = 0x5EED) {
  const auto next = [&seed] {  // splitmix64
    std::uint64_t z = (seed += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  for (std::size_t i = items.size(); i > 1; --i) std::swap(items[i - 1], items[next() % i]);
}

}  // namespace vorocrust::quality
