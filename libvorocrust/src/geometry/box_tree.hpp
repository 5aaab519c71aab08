// Internal: a bounding-volume hierarchy over axis-aligned boxes, for "which items are near this
// box" queries (faces against faces in the self-intersection search, input elements against
// balls in the refinement) and "which item is nearest to this point" queries (sample points
// against a surface in the Hausdorff distance).
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

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
  // 0 inside the box; infinite for the empty box.
  double squared_distance(const Point& p) const {
    return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).squaredNorm();
  }
};

// A bounding-volume hierarchy over the boxes of chosen items, in flat arrays. Nodes are stored
// depth first: an inner node's left child is the next node and `first_or_right` names its right
// child; a leaf holds items[first_or_right, first_or_right + count).
class BoxTree {
 public:
  BoxTree(std::vector<Box> boxes, std::vector<std::uint32_t> items)
      : boxes_(std::move(boxes)), items_(std::move(items)) {
    if (items_.empty()) return;
    nodes_.reserve(2 * (items_.size() / kLeafSize + 1));
    build(0, static_cast<std::uint32_t>(items_.size()));
  }

  const Box& box(std::uint32_t item) const { return boxes_[item]; }

  // Calls visit(item) for every item whose box overlaps `query` (closed boxes: touching counts).
  template <class Visit>
  void for_each_overlap(const Box& query, Visit&& visit) const {
    for_each_where([&](const Box& box) { return box.overlaps(query); }, visit);
  }

  // Calls visit(item) for every item whose box passes `test`, descending only into nodes whose
  // box passes it: `test` must hold for a node whenever it holds for a box inside it. It may
  // change between calls (a ray query narrows as it finds hits).
  template <class Test, class Visit>
  void for_each_where(Test&& test, Visit&& visit) const {
    if (nodes_.empty()) return;
    // Median splits keep the depth below 33 for any 32-bit item count, and the stack never
    // holds more than one pending right child per level.
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const std::uint32_t index = stack[--top];
      const Node& node = nodes_[index];
      if (!test(node.box)) continue;
      if (node.count == 0) {
        stack[top++] = node.first_or_right;
        stack[top++] = index + 1;
        continue;
      }
      for (std::uint32_t k = node.first_or_right; k < node.first_or_right + node.count; ++k)
        if (test(boxes_[items_[k]])) visit(items_[k]);
    }
  }

  static constexpr std::uint32_t kNoItem = std::numeric_limits<std::uint32_t>::max();

  // The item nearest to `p` and its squared distance, as `squared_distance(item)` measures it,
  // which must never be less than the item box's squared distance to `p` (true of any point
  // set inside the box). Nearer children are visited first and nodes no nearer than the best
  // item so far are skipped, so ties go to the item met first in a fixed order: equal trees and
  // points give equal answers. {kNoItem, infinity} for an empty tree.
  // The search stops early at the first item whose squared distance is at most `good_enough`,
  // for callers who need the nearest distance only when it exceeds that.
  template <class SquaredDistance>
  std::pair<std::uint32_t, double> nearest(const Point& p, SquaredDistance&& squared_distance,
                                           double good_enough = -1) const {
    std::pair<std::uint32_t, double> best{kNoItem, std::numeric_limits<double>::infinity()};
    if (nodes_.empty()) return best;
    // Each level pops one node and pushes at most two, so the depth bound of for_each_overlap
    // holds here too.
    std::pair<std::uint32_t, double> stack[64];
    int top = 0;
    stack[top++] = {0, nodes_[0].box.squared_distance(p)};
    while (top > 0) {
      const auto [index, node_distance] = stack[--top];
      if (!(node_distance < best.second)) continue;
      const Node& node = nodes_[index];
      if (node.count == 0) {
        const std::uint32_t left = index + 1, right = node.first_or_right;
        const double to_left = nodes_[left].box.squared_distance(p), to_right = nodes_[right].box.squared_distance(p);
        // The nearer child goes on top, to be searched first.
        if (to_left <= to_right) {
          stack[top++] = {right, to_right};
          stack[top++] = {left, to_left};
        } else {
          stack[top++] = {left, to_left};
          stack[top++] = {right, to_right};
        }
        continue;
      }
      for (std::uint32_t k = node.first_or_right; k < node.first_or_right + node.count; ++k) {
        const std::uint32_t item = items_[k];
        if (!(boxes_[item].squared_distance(p) < best.second)) continue;
        const double d = squared_distance(item);
        if (d < best.second) best = {item, d};
        if (best.second <= good_enough) return best;
      }
    }
    return best;
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

  std::vector<Box> boxes_;
  std::vector<std::uint32_t> items_;
  std::vector<Node> nodes_;
};

// A tree over every face of `mesh`, its items the face indices.
inline BoxTree face_tree(const SurfaceMesh& mesh) {
  std::vector<Box> boxes(mesh.num_faces());
  std::vector<std::uint32_t> faces(mesh.num_faces());
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    for (Index v : mesh.triangles[f]) boxes[f].include(mesh.vertices[v]);
    faces[f] = f;
  }
  return BoxTree(std::move(boxes), std::move(faces));
}

}  // namespace vorocrust::geometry
