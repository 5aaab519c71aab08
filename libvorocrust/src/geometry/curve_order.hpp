// Internal: an order of points along a Morton (Z-order) curve over their bounding box.
//
// curve_order(count, position) returns 0..count-1 sorted by the curve's key of position(i) (21
// bits per axis; ties by index). Neighbours in the list are mostly neighbours in space, so work
// that visits each point's neighbourhood in that order finds it still cached; the order depends
// on the points alone.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/box_tree.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

// The low 21 bits of x, three apart, for interleaving three coordinates.
inline std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

template <class Position>
std::vector<std::uint32_t> curve_order(std::size_t count, Position&& position) {
  Box box;
  for (std::size_t i = 0; i < count; ++i) box.include(position(i));
  const Point scale = (box.hi - box.lo).cwiseMax(1e-300).cwiseInverse() * double((1 << 21) - 1);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Point q = (position(i) - box.lo).cwiseProduct(scale);
    keys[i] = {spread_bits(static_cast<std::uint64_t>(q.x())) | spread_bits(static_cast<std::uint64_t>(q.y())) << 1 |
                   spread_bits(static_cast<std::uint64_t>(q.z())) << 2,
               static_cast<std::uint32_t>(i)};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> order(count);
  for (std::size_t i = 0; i < count; ++i) order[i] = keys[i].second;
  return order;
}

}  // namespace vorocrust::geometry
