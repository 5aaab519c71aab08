// Internal: a bounding-volume hierarchy over axis-aligned boxes, for "which items are near this
// box" queries: faces against faces in the self-intersection search, input elements against
// balls in the refinement.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
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

}  // namespace vorocrust::geometry
