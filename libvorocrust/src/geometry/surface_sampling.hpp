// Internal: uniform random points on a set of elements: an element picked with probability
// proportional to its measure (length or area), then a uniform point on it.
//
// Both take their randomness as numbers uniform in [0, 1), so each caller keeps its own generator
// and its own order of draws, and equal draws give equal points.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

// Picks an index with probability proportional to its weight (weights >= 0, not all zero).
class WeightedPick {
 public:
  explicit WeightedPick(const std::vector<double>& weights) : prefix_(weights.size()) {
    double sum = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) prefix_[i] = sum += weights[i];
  }
  double total() const { return prefix_.empty() ? 0 : prefix_.back(); }
  std::size_t operator()(double u) const {  // u uniform in [0, 1)
    const double target = u * total();
    const auto it = std::upper_bound(prefix_.begin(), prefix_.end(), target);
    return std::min<std::size_t>(it - prefix_.begin(), prefix_.size() - 1);
  }

 private:
  std::vector<double> prefix_;
};

// A point uniform over triangle abc for u, v uniform in [0, 1): the draws outside the triangle
// are folded back onto it, so none is wasted.
inline Point point_in_triangle(const Point& a, const Point& b, const Point& c, double u, double v) {
  if (u + v > 1) u = 1 - u, v = 1 - v;
  return a + u * (b - a) + v * (c - a);
}

}  // namespace vorocrust::geometry
