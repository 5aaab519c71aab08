// Ball neighbourhoods (paper appendix A.3, A.4).
#include "refinement/ball_index.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "refinement/point_cloud.hpp"

namespace vorocrust {

namespace {

using Adaptor = PointCloudAdaptor<Point, IdentityPosition>;
using Tree = DynamicKdTree<Adaptor>;

// Centres in a k-d tree that grows; `ball[i]` is the ball of the tree's i-th point.
struct CentreTree {
  std::vector<Point> centres;
  std::vector<std::uint32_t> ball;
  Adaptor adaptor;
  std::unique_ptr<Tree> tree;

  CentreTree() {
    adaptor.items = &centres;
    tree = std::make_unique<Tree>(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  }
  std::uint32_t add(const Point& p, std::uint32_t b) {
    centres.push_back(p);
    ball.push_back(b);
    const auto local = static_cast<std::uint32_t>(centres.size() - 1);
    tree->addPoints(local, local);
    return local;
  }
  void within(const Point& p, double distance, std::vector<std::uint32_t>& out) const {
    if (centres.empty() || !(distance > 0)) return;
    const double query[3] = {p.x(), p.y(), p.z()};
    std::vector<std::uint32_t> local;
    WithinRadius result(distance * distance, local);
    tree->findNeighbors(result, query, nanoflann::SearchParams());
    for (std::uint32_t i : local) out.push_back(ball[i]);
  }
};

int radius_class(double radius) {
  int exponent = 0;
  std::frexp(radius, &exponent);  // radius in [2^(exponent-1), 2^exponent)
  return exponent;
}

}  // namespace

struct BallIndex::Trees {
  CentreTree all[3];
  std::map<int, CentreTree> classes[3];
};

BallIndex::BallIndex() : trees_(std::make_unique<Trees>()) {}
BallIndex::~BallIndex() = default;

std::uint32_t BallIndex::add(const SurfaceSite& site, double radius) {
  const auto id = static_cast<std::uint32_t>(balls_.size());
  balls_.push_back({site, radius});
  class_slot_.emplace_back(0, 0);
  trees_->all[static_cast<int>(site.type)].add(site.position, id);
  file_in_class(id);
  return id;
}

void BallIndex::file_in_class(std::uint32_t id) {
  const RefinedBall& b = balls_[id];
  const int k = radius_class(b.radius);
  CentreTree& tree = trees_->classes[static_cast<int>(b.site.type)][k];
  class_slot_[id] = {k, tree.add(b.site.position, id)};
}

void BallIndex::shrink(std::uint32_t i, double radius) {
  if (!(radius < balls_[i].radius)) return;
  balls_[i].radius = radius;
  const auto [k, local] = class_slot_[i];
  if (radius_class(radius) == k) return;
  trees_->classes[static_cast<int>(balls_[i].site.type)][k].tree->removePoint(local);
  file_in_class(i);
}

std::size_t BallIndex::count(StratumType type) const { return trees_->all[static_cast<int>(type)].centres.size(); }

std::int64_t BallIndex::nearest(StratumType type, const Point& p) const {
  const CentreTree& t = trees_->all[static_cast<int>(type)];
  if (t.centres.empty()) return -1;
  const double query[3] = {p.x(), p.y(), p.z()};
  FilteredNearest any([](std::uint32_t) { return true; });
  t.tree->findNeighbors(any, query, nanoflann::SearchParams());
  return t.ball[any.index()];
}

void BallIndex::centres_within(StratumType type, const Point& p, double distance, std::vector<std::uint32_t>& out) const {
  trees_->all[static_cast<int>(type)].within(p, distance, out);
}

void BallIndex::reaching(StratumType type, const Point& p, double margin, std::vector<std::uint32_t>& out) const {
  std::vector<std::uint32_t> candidates;
  for (const auto& [k, tree] : trees_->classes[static_cast<int>(type)]) {
    tree.within(p, std::ldexp(1.0, k) + margin, candidates);
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (std::uint32_t b : candidates) {
    if ((balls_[b].site.position - p).norm() < balls_[b].radius + margin) out.push_back(b);
  }
}

}  // namespace vorocrust
