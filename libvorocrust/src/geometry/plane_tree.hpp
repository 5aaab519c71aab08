// Internal: a static k-d tree over points of the plane (nanoflann), for 2D domains.
#pragma once

#include <cstdint>
#include <nanoflann.hpp>
#include <vector>

#include "vorocrust/plane.hpp"

namespace vorocrust::geometry {

class PlaneTree {
 public:
  explicit PlaneTree(const std::vector<Point2>& points)
      : cloud_{&points}, tree_(2, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(12)) {}

  // Indices of the points within `radius` of p, in no particular order. Safe from many threads.
  void within(const Point2& p, double radius, std::vector<std::uint32_t>& out) const {
    out.clear();
    if (cloud_.points->empty()) return;
    thread_local std::vector<std::pair<std::uint32_t, double>> found_;
    found_.clear();
    const double q[2] = {p.x(), p.y()};
    tree_.radiusSearch(q, radius * radius, found_, nanoflann::SearchParams(32, 0, false));
    for (const auto& f : found_) out.push_back(f.first);
  }
  // The k nearest points, nearest first: indices and squared distances.
  std::size_t nearest(const Point2& p, std::size_t k, std::uint32_t* index, double* squared) const {
    if (cloud_.points->empty()) return 0;
    nanoflann::KNNResultSet<double, std::uint32_t> result(k);
    result.init(index, squared);
    const double q[2] = {p.x(), p.y()};
    tree_.findNeighbors(result, q, nanoflann::SearchParams());
    return result.size();
  }
  std::size_t size() const { return cloud_.points->size(); }

 private:
  struct Cloud {
    const std::vector<Point2>* points;
    std::size_t kdtree_get_point_count() const { return points->size(); }
    double kdtree_get_pt(std::uint32_t i, std::size_t dim) const { return (*points)[i][static_cast<int>(dim)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
  };
  Cloud cloud_;
  nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud, double, std::uint32_t>, Cloud, 2,
                                      std::uint32_t>
      tree_;
};

}  // namespace vorocrust::geometry
