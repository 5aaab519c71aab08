// Internal: a k-d tree of balls that grows one ball at a time and answers neighbourhood queries
// bounded by the largest radius below each node. The refinement's ball index (paper A.3, A.4) and
// the interior sampler (A.5) both keep their balls in one.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust::geometry {

// A k-d tree of balls that grows one ball at a time: a new ball descends to its leaf, and a full
// leaf splits between the middle centres along their widest spread. Darts land uniformly at
// random, so balls arrive in random order and the tree stays balanced without rebuilding, as a
// binary search tree does under random insertions.
//
// Each node knows the box of the centres below it and the largest radius below it, which bounds
// every query at any time. (The paper bounds neighbourhoods through the Lipschitz radii, which
// hold only once C3 is enforced.) Shrinking leaves that radius stale, never too small. It knows
// the smallest radius below it too, which shrinking keeps exact: the Lipschitz bound at p gains
// nothing from a node whose smallest radius plus L times its distance already reaches the bound.
class BallTree {
 public:
  void insert(const Point& centre, double radius, std::uint32_t ball);
  void shrink(std::uint32_t ball, double radius) {
    const auto [leaf, position] = slot_[ball];
    leaves_[leaf][position].radius = radius;
    // The path the ball took on insertion, each node's smallest radius lowered.
    descend(leaves_[leaf][position].centre, [&](Node& node) { node.min_radius = std::min(node.min_radius, radius); });
  }

  struct Sphere {
    Point centre;
    double radius;
    std::uint32_t ball;
  };
  // Whether some ball, its radius scaled by `scale`, holds p strictly inside.
  bool contains(const Point& p, double scale = 1) const {
    bool inside = false;
    const double s2 = scale * scale;
    search(
        p, [&](double d2, double max_radius, std::uint32_t) { return !inside && d2 < s2 * max_radius * max_radius; },
        [&](const Sphere& s) { inside = inside || (s.centre - p).squaredNorm() < s2 * s.radius * s.radius; });
    return inside;
  }
  // min over the balls q of r_q + L |p - q|: the largest radius a ball at p may have beside them
  // under the Lipschitz condition (infinity when the tree is empty). Only balls numbered `first`
  // or later count, and the bound starts at `below`: a ball that already kept the condition with
  // the older ones checks only the newer ones.
  double lipschitz_bound(const Point& p, double L, std::uint32_t first = 0,
                         double below = std::numeric_limits<double>::infinity()) const {
    double best = below;
    search(
        p,
        [&](double d2, double, std::uint32_t newest, double min_radius) {
          return newest >= first && min_radius + L * std::sqrt(d2) < best;
        },
        [&](const Sphere& s) {
          if (s.ball >= first) best = std::min(best, s.radius + L * (s.centre - p).norm());
        });
    return best;
  }

  // Calls visit(sphere) for every sphere in the subtrees that keep(squared distance from p to
  // the subtree's box of centres, largest radius in it, newest ball in it[, smallest radius in
  // it]) accepts; nearer subtrees first.
  template <class Keep, class Visit>
  void search(const Point& p, Keep&& keep, Visit&& visit) const {
    if (!nodes_.empty()) search(0, p, keep, visit);
  }

 private:
  static constexpr std::size_t kLeafSize = 8;
  struct Node {
    Point lo = Point::Constant(std::numeric_limits<double>::infinity());
    Point hi = Point::Constant(-std::numeric_limits<double>::infinity());
    double max_radius = 0;
    double min_radius = std::numeric_limits<double>::infinity();
    std::uint32_t newest = 0;  // the largest ball index below: balls are numbered as they come
    int axis = -1;             // -1 for a leaf
    double split = 0;
    std::uint32_t child = 0;  // inner node: its children are child and child + 1; leaf: its index in leaves_
    void include(const Point& centre, double radius, std::uint32_t ball) {
      lo = lo.cwiseMin(centre);
      hi = hi.cwiseMax(centre);
      max_radius = std::max(max_radius, radius);
      min_radius = std::min(min_radius, radius);
      newest = std::max(newest, ball);
    }
  };

  template <class Keep, class Visit>
  void search(std::uint32_t index, const Point& p, Keep& keep, Visit& visit) const {
    const Node& node = nodes_[index];
    const double d2 = (p - p.cwiseMax(node.lo).cwiseMin(node.hi)).squaredNorm();
    if constexpr (std::is_invocable_v<Keep&, double, double, std::uint32_t, double>) {
      if (!keep(d2, node.max_radius, node.newest, node.min_radius)) return;
    } else {
      if (!keep(d2, node.max_radius, node.newest)) return;
    }
    if (node.axis < 0) {
      for (const Sphere& s : leaves_[node.child]) visit(s);
      return;
    }
    const std::uint32_t nearer = p[node.axis] < node.split ? 0 : 1;
    search(node.child + nearer, p, keep, visit);
    search(node.child + 1 - nearer, p, keep, visit);
  }
  // Calls at(node) on each node from the root to the leaf where `centre` belongs, the path every
  // ball at `centre` took (splits send the centres below a node the same way); returns the leaf.
  template <class AtNode>
  std::uint32_t descend(const Point& centre, AtNode&& at) {
    std::uint32_t index = 0;
    for (;;) {
      Node& node = nodes_[index];
      at(node);
      if (node.axis < 0) return index;
      index = node.child + (centre[node.axis] < node.split ? 0 : 1);
    }
  }
  void split(std::uint32_t index);
  void place(std::uint32_t leaf, const Sphere& s) {
    slot_[s.ball] = {leaf, static_cast<std::uint32_t>(leaves_[leaf].size())};
    leaves_[leaf].push_back(s);
  }

  std::vector<Node> nodes_;
  std::vector<std::vector<Sphere>> leaves_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> slot_;  // per ball: its leaf and position there
};

inline void BallTree::insert(const Point& centre, double radius, std::uint32_t ball) {
  if (nodes_.empty()) {
    nodes_.emplace_back();
    leaves_.emplace_back();
  }
  const std::uint32_t index = descend(centre, [&](Node& node) { node.include(centre, radius, ball); });
  if (slot_.size() <= ball) slot_.resize(ball + 1);
  place(nodes_[index].child, {centre, radius, ball});
  if (leaves_[nodes_[index].child].size() > kLeafSize) split(index);
}

inline void BallTree::split(std::uint32_t index) {
  int axis;
  (nodes_[index].hi - nodes_[index].lo).maxCoeff(&axis);
  if (!(nodes_[index].hi[axis] > nodes_[index].lo[axis])) return;  // one centre many times: keep the leaf
  const std::uint32_t left_leaf = nodes_[index].child;
  std::vector<Sphere> spheres = std::move(leaves_[left_leaf]);
  leaves_[left_leaf].clear();
  std::vector<double> values;
  for (const Sphere& s : spheres) values.push_back(s.centre[axis]);
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  double split = 0.5 * (values[middle - 1] + values[middle]);
  if (!(split > values.front())) split = 0.5 * (values.front() + values.back());  // ties: both sides keep some
  const auto child = static_cast<std::uint32_t>(nodes_.size());
  nodes_.resize(nodes_.size() + 2);
  nodes_[child].child = left_leaf;
  nodes_[child + 1].child = static_cast<std::uint32_t>(leaves_.size());
  leaves_.emplace_back();
  for (const Sphere& s : spheres) {
    Node& side = nodes_[child + (s.centre[axis] < split ? 0 : 1)];
    side.include(s.centre, s.radius, s.ball);
    place(side.child, s);
  }
  Node& node = nodes_[index];
  node.axis = axis;
  node.split = split;
  node.child = child;
}

}  // namespace vorocrust::geometry
