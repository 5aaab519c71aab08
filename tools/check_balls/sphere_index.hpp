// check_balls/sphere_index.hpp — which of many spheres (balls, or bounding spheres of faces and
// edges) come near a point.
//
// Contract: for_each_near(x, reach, f) calls f(i, |x - c_i|) for exactly the spheres i with
// |x - c_i| <= r_i + reach, each once. Spheres are grouped by radius (within a factor of two per
// group) and each group has its own k-d tree, so a few large spheres do not make every query look
// at every small one.
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <nanoflann.hpp>
#include <utility>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::checker {

class SphereIndex {
 public:
  SphereIndex() = default;
  SphereIndex(const std::vector<Point>& centres, const std::vector<double>& radii) {
    std::vector<int> group_of(centres.size());
    int lowest = std::numeric_limits<int>::max(), highest = std::numeric_limits<int>::min();
    for (std::size_t i = 0; i < centres.size(); ++i) {
      group_of[i] = radii[i] > 0 ? std::ilogb(radii[i]) : std::numeric_limits<int>::min();
      if (radii[i] > 0) lowest = std::min(lowest, group_of[i]), highest = std::max(highest, group_of[i]);
    }
    std::vector<std::unique_ptr<Group>> by_exponent(lowest <= highest ? highest - lowest + 2 : 1);
    for (std::size_t i = 0; i < centres.size(); ++i) {
      // Group 0 holds the points (radius 0), group k > 0 the radii in [2^(lowest+k-1), 2^(lowest+k)).
      const std::size_t slot = radii[i] > 0 ? static_cast<std::size_t>(group_of[i] - lowest + 1) : 0;
      auto& group = by_exponent[slot];
      if (!group) group = std::make_unique<Group>();
      group->cloud.points.push_back(centres[i]);
      group->ids.push_back(static_cast<Index>(i));
      group->max_radius = std::max(group->max_radius, radii[i]);
    }
    for (auto& group : by_exponent) {
      if (!group) continue;
      group->tree = std::make_unique<Tree>(3, group->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
      groups_.push_back(std::move(group));
    }
    radii_ = radii;
  }

  bool empty() const { return groups_.empty(); }

  template <class F>
  void for_each_near(const Point& x, double reach, F&& f) const {
    std::vector<std::pair<Index, double>> found;
    for (const auto& group : groups_) {
      const double r = group->max_radius + reach;
      // nanoflann compares squared distances strictly; widen a little and filter exactly below.
      group->tree->radiusSearch(x.data(), r * r * (1 + 1e-12) + 1e-300, found, nanoflann::SearchParams(32, 0, false));
      for (const auto& [local, squared] : found) {
        const Index i = group->ids[local];
        const double distance = std::sqrt(squared);
        if (distance <= radii_[i] + reach) f(i, distance);
      }
    }
  }

  // The sphere whose centre is nearest to x in each group, as a first guess for nearest-element
  // searches; calls f(i) for each.
  template <class F>
  void for_each_group_nearest(const Point& x, F&& f) const {
    for (const auto& group : groups_) {
      Index local = 0;
      double squared = 0;
      if (group->tree->knnSearch(x.data(), 1, &local, &squared) == 1) f(group->ids[local]);
    }
  }

 private:
  struct Cloud {
    std::vector<Point> points;
    std::size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return points[i][static_cast<Eigen::Index>(d)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud, double, Index>,
                                                   Cloud, 3, Index>;
  struct Group {
    Cloud cloud;
    std::vector<Index> ids;
    double max_radius = 0;
    std::unique_ptr<Tree> tree;
  };
  std::vector<std::unique_ptr<Group>> groups_;
  std::vector<double> radii_;
};

}  // namespace vorocrust::checker
