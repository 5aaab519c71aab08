// Internal: gives one index to every exactly equal coordinate triple. Used for STL, whose
// triangles repeat their corners, and when several files are merged into one model. Equality
// is exact (0.0 and -0.0 are equal): no coordinate is moved.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::io {

class VertexWelder {
 public:
  explicit VertexWelder(std::vector<Point>& vertices) : vertices_(vertices) { index_from(0); }

  // Makes vertices[first..] findable; a coordinate already indexed keeps its first index.
  void index_from(std::size_t first) {
    for (std::size_t i = first; i < vertices_.size(); ++i) index_.emplace(key(vertices_[i]), static_cast<Index>(i));
  }
  // Index of an indexed vertex at exactly `p`, or `none`.
  static constexpr Index none = ~Index{0};
  Index find(const Point& p) const {
    const auto it = index_.find(key(p));
    return it == index_.end() ? none : it->second;
  }
  // Index of the vertex at exactly `p`, appending it when new.
  Index weld(const Point& p) {
    const auto [it, inserted] = index_.emplace(key(p), static_cast<Index>(vertices_.size()));
    if (inserted) vertices_.push_back(p);
    return it->second;
  }

 private:
  using Key = std::array<double, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
      std::size_t h = 1469598103934665603ull;
      for (double d : k) {
        std::uint64_t bits;
        static_assert(sizeof bits == sizeof d);
        __builtin_memcpy(&bits, &d, sizeof d);
        h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      }
      return h;
    }
  };
  static Key key(const Point& p) {
    // -0.0 and 0.0 compare equal; give them one bit pattern so they also hash equal.
    return {p.x() == 0 ? 0.0 : p.x(), p.y() == 0 ? 0.0 : p.y(), p.z() == 0 ? 0.0 : p.z()};
  }
  std::vector<Point>& vertices_;
  std::unordered_map<Key, Index, KeyHash> index_;
};

}  // namespace vorocrust::io
