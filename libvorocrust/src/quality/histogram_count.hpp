// Internal: one value counted into a histogram of bins spread evenly over [low, high], as the
// cells' figures bin theirs (cell_quality.hpp): values below low in the first bin, high itself
// in the last, values above high counted apart.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace vorocrust::quality {

inline void count_in_histogram(double value, double low, double high, std::vector<std::size_t>& bins,
                               std::size_t& above_high) {
  if (value > high) {
    ++above_high;
    return;
  }
  const double width = (high - low) / static_cast<double>(bins.size());
  const double bin = std::floor((value - low) / width);
  ++bins[static_cast<std::size_t>(std::clamp(bin, 0.0, static_cast<double>(bins.size() - 1)))];
}

}  // namespace vorocrust::quality
