// Self-intersection search: a bounding-volume hierarchy over the faces' boxes proposes the
// candidate pairs, the exact triangle test of triangle_intersection.hpp decides them.
#include "geometry/self_intersections.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <limits>

#include "geometry/triangle_intersection.hpp"

namespace vorocrust::geometry {
namespace {

// A closed axis-aligned box; the default one is empty and overlaps nothing.
struct Box {
  Point lo = Point::Constant(std::numeric_limits<double>::infinity());
  Point hi = Point::Constant(-std::numeric_limits<double>::infinity());

  void include(const Point& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void include(const Box& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  bool overlaps(const Box& b) const {
    return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all();
  }
};

// A bounding-volume hierarchy over the boxes of chosen items, in flat arrays. Nodes are stored
// depth first: an inner node's left child is the next node and `first_or_right` names its right
// child; a leaf holds items[first_or_right, first_or_right + count).
class BoxTree {
 public:
  BoxTree(const std::vector<Box>& boxes, std::vector<std::uint32_t> items)
      : boxes_(boxes), items_(std::move(items)) {
    if (items_.empty()) return;
    nodes_.reserve(2 * (items_.size() / kLeafSize + 1));
    build(0, static_cast<std::uint32_t>(items_.size()));
  }

  template <class Visit>
  void for_each_overlap(const Box& query, Visit&& visit) const {
    if (nodes_.empty()) return;
    // Median splits keep the depth below 33 for any 32-bit item count, and the stack never
    // holds more than one pending right child per level.
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const std::uint32_t index = stack[--top];
      const Node& node = nodes_[index];
      if (!node.box.overlaps(query)) continue;
      if (node.count == 0) {
        stack[top++] = node.first_or_right;
        stack[top++] = index + 1;
        continue;
      }
      for (std::uint32_t k = node.first_or_right; k < node.first_or_right + node.count; ++k)
        if (boxes_[items_[k]].overlaps(query)) visit(items_[k]);
    }
  }

 private:
  static constexpr std::uint32_t kLeafSize = 4;

  struct Node {
    Box box;
    std::uint32_t first_or_right = 0;
    std::uint32_t count = 0;  // 0 for inner nodes
  };

  // Splits items at the median of their box centres along the axis where the centres spread
  // most: cheap, and balanced whatever the distribution, so the depth stays logarithmic.
  std::uint32_t build(std::uint32_t begin, std::uint32_t end) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Box box, centres;
    for (std::uint32_t k = begin; k < end; ++k) {
      const Box& b = boxes_[items_[k]];
      box.include(b);
      centres.include(Point(b.lo + b.hi));  // twice the centre: only the order matters
    }
    if (end - begin <= kLeafSize) {
      nodes_[index] = {box, begin, end - begin};
      return index;
    }
    int axis;
    (centres.hi - centres.lo).maxCoeff(&axis);
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + middle, items_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       const double ca = boxes_[a].lo[axis] + boxes_[a].hi[axis];
                       const double cb = boxes_[b].lo[axis] + boxes_[b].hi[axis];
                       return ca < cb || (ca == cb && a < b);
                     });
    build(begin, middle);
    const std::uint32_t right = build(middle, end);
    nodes_[index] = {box, right, 0};
    return index;
  }

  const std::vector<Box>& boxes_;
  std::vector<std::uint32_t> items_;
  std::vector<Node> nodes_;
};

TriangleCorners corners_of(const SurfaceMesh& mesh, std::size_t face) {
  const Triangle& t = mesh.triangles[face];
  return {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
}

}  // namespace

std::vector<FacePair> find_self_intersections(const SurfaceMesh& mesh) {
  const std::size_t num_faces = mesh.num_faces();
  std::vector<Box> boxes(num_faces);
  std::vector<char> testable(num_faces, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, num_faces, 1024), [&](const auto& range) {
    for (std::size_t f = range.begin(); f != range.end(); ++f) {
      const Triangle& t = mesh.triangles[f];
      if (t[0] >= mesh.num_vertices() || t[1] >= mesh.num_vertices() || t[2] >= mesh.num_vertices())
        continue;
      const TriangleCorners corners = corners_of(mesh, f);
      if (is_degenerate(corners)) continue;
      testable[f] = 1;
      for (const Point& p : corners) boxes[f].include(p);
    }
  });

  std::vector<std::uint32_t> items;
  Box bounds;
  for (std::size_t f = 0; f < num_faces; ++f) {
    if (!testable[f]) continue;
    items.push_back(static_cast<std::uint32_t>(f));
    bounds.include(boxes[f]);
  }
  if (items.empty()) return {};
  const BoxTree tree(boxes, std::move(items));
  // Boxes are exact (min and max round nothing), so closed overlap tests already keep faces
  // that merely touch; the margin only guards that property against future box rounding.
  const double margin = 1e-12 * (bounds.hi - bounds.lo).norm();

  tbb::enumerable_thread_specific<std::vector<FacePair>> found;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, num_faces, 256), [&](const auto& range) {
    std::vector<FacePair>& out = found.local();
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      if (!testable[i]) continue;
      Box query = boxes[i];
      query.lo.array() -= margin;
      query.hi.array() += margin;
      const TriangleCorners t = corners_of(mesh, i);
      tree.for_each_overlap(query, [&](std::uint32_t j) {
        if (j <= i) return;  // each pair once, from its smaller face
        // Duplicate faces share all three corners, which improperly_intersect declines.
        const SharedCorners shared = shared_corners(mesh.triangles[i], mesh.triangles[j]);
        if (improperly_intersect(t, corners_of(mesh, j), shared)) out.emplace_back(i, j);
      });
    }
  });

  std::vector<FacePair> pairs;
  for (const std::vector<FacePair>& part : found)
    pairs.insert(pairs.end(), part.begin(), part.end());
  // Threads finish in any order; sorting makes the result deterministic.
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace vorocrust::geometry
