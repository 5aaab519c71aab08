// Internal: items at points, hashed by the cube of side `side` each lies in, for finding the
// items near a point or a box in a few lookups when the points are spread unevenly or move.
//
// Contract: insert(item, p) files an item at p; move(item, from, to) files it again (from must be
// where it was filed). near(lo, hi, visit) calls visit(item) for every item in the cubes that the
// box [lo, hi] grown by `side` meets: every item within `side` of the box, and some farther. Items
// in one cube come in the order they were filed. Coordinates are taken in cubes modulo 2^21 on
// each axis: boxes must span fewer cubes than that.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

class CubeHash {
 public:
  explicit CubeHash(double side) : side_(side) {}

  void insert(std::uint32_t item, const Point& p) { cubes_[key(cube_of(p))].push_back(item); }

  void move(std::uint32_t item, const Point& from, const Point& to) {
    std::vector<std::uint32_t>& was = cubes_[key(cube_of(from))];
    was.erase(std::find(was.begin(), was.end(), item));
    insert(item, to);
  }

  template <class Visit>
  void near(const Point& lo, const Point& hi, Visit&& visit) const {
    const auto a = cube_of(lo - Point::Constant(side_)), b = cube_of(hi + Point::Constant(side_));
    for (std::int64_t z = a[2]; z <= b[2]; ++z) {
      for (std::int64_t y = a[1]; y <= b[1]; ++y) {
        for (std::int64_t x = a[0]; x <= b[0]; ++x) {
          const auto it = cubes_.find(key({x, y, z}));
          if (it == cubes_.end()) continue;
          for (std::uint32_t item : it->second) visit(item);
        }
      }
    }
  }

 private:
  std::array<std::int64_t, 3> cube_of(const Point& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / side_)), static_cast<std::int64_t>(std::floor(p.y() / side_)),
            static_cast<std::int64_t>(std::floor(p.z() / side_))};
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    const auto part = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0x1fffffu; };
    return part(c[0]) | (part(c[1]) << 21) | (part(c[2]) << 42);
  }

  double side_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cubes_;
};

}  // namespace vorocrust::geometry
