// A shuffle from a fixed seed that gives the same order on every platform (the standard
// library's shuffles and distributions differ between implementations), for the randomised
// algorithms whose answers must be reproducible.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/split_mix.hpp"

namespace vorocrust::geometry {

template <class T>
void fixed_shuffle(std::vector<T>& items, std::uint64_t seed = 0x5EED) {
  SplitMix64 next(seed);
  for (std::size_t i = items.size(); i > 1; --i) std::swap(items[i - 1], items[next() % i]);
}

}  // namespace vorocrust::geometry
