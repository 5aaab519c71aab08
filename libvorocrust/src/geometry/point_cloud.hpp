// Internal: nanoflann adaptors over points held elsewhere, and the filtered nearest-neighbour
// result set of paper A.2 (a subtree is pruned only by distance; points the filter accepts as
// co-smooth never shrink the search radius).
#pragma once

#include <cstdint>
#include <limits>
#include <nanoflann.hpp>
#include <vector>

#include "vorocrust/seeds.hpp"
#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

// A nanoflann dataset over a vector of items, each projected to its position by `Position`.
template <class Item, class Position>
struct PointCloudAdaptor {
  const std::vector<Item>* items = nullptr;
  std::size_t kdtree_get_point_count() const { return items->size(); }
  double kdtree_get_pt(std::uint32_t i, std::size_t dim) const {
    return Position{}((*items)[i])[static_cast<int>(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};

struct IdentityPosition {
  const Point& operator()(const Point& p) const { return p; }
};
struct SeedPosition {
  const Point& operator()(const Seed& s) const { return s.position; }
};
using SeedCloud = PointCloudAdaptor<Seed, SeedPosition>;

template <class Adaptor>
using StaticKdTree = nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<double, Adaptor, double, std::uint32_t>, Adaptor, 3, std::uint32_t>;

template <class Adaptor>
using DynamicKdTree = nanoflann::KDTreeSingleIndexDynamicAdaptor<
    nanoflann::L2_Simple_Adaptor<double, Adaptor, double, std::uint32_t>, Adaptor, 3, std::uint32_t>;

// Nearest point the filter rejects; `reject(index)` is true for points that count.
template <class Reject>
class FilteredNearest {
 public:
  using DistanceType = double;
  using IndexType = std::uint32_t;
  // Only points nearer than sqrt(initial_squared_bound) count: the search never looks further.
  explicit FilteredNearest(Reject reject, double initial_squared_bound = std::numeric_limits<double>::infinity())
      : reject_(std::move(reject)), best_(initial_squared_bound) {}
  bool full() const { return true; }
  bool addPoint(double squared_distance, std::uint32_t index) {
    if (squared_distance < best_ && reject_(index)) {
      best_ = squared_distance;
      index_ = index;
    }
    return true;
  }
  double worstDist() const { return best_; }
  double squared_distance() const { return best_; }
  std::uint32_t index() const { return index_; }

 private:
  Reject reject_;
  double best_;
  std::uint32_t index_ = ~std::uint32_t{0};
};

// Collects every index within a squared radius (strictly inside).
class WithinRadius {
 public:
  using DistanceType = double;
  using IndexType = std::uint32_t;
  WithinRadius(double squared_radius, std::vector<std::uint32_t>& out) : r2_(squared_radius), out_(out) {}
  bool full() const { return true; }
  bool addPoint(double squared_distance, std::uint32_t index) {
    if (squared_distance < r2_) out_.push_back(index);
    return true;
  }
  double worstDist() const { return r2_; }

 private:
  double r2_;
  std::vector<std::uint32_t>& out_;
};

// The indices of the points of `tree` strictly within sqrt(squared_radius) of p, into `out`.
template <class Tree>
void points_within(const Tree& tree, const Point& p, double squared_radius, std::vector<std::uint32_t>& out) {
  out.clear();
  WithinRadius within(squared_radius, out);
  tree.findNeighbors(within, p.data(), nanoflann::SearchParams());
}

}  // namespace vorocrust
