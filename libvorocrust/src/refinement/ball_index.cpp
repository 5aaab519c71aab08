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

// Appends the balls whose centres lie within the search radius and which reach the query point
// (|p - centre| < radius + margin), straight from the tree's leaves.
class ReachingBalls {
 public:
  using DistanceType = double;
  using IndexType = std::uint32_t;
  ReachingBalls(double search_radius, double margin, const std::vector<std::uint32_t>& ball_of,
                const std::vector<RefinedBall>& balls, std::vector<std::uint32_t>& out)
      : r2_(search_radius * search_radius), margin_(margin), ball_of_(ball_of), balls_(balls), out_(out) {}
  bool full() const { return true; }
  double worstDist() const { return r2_; }
  bool addPoint(double squared_distance, std::uint32_t local) {
    const std::uint32_t b = ball_of_[local];
    const double reach = balls_[b].radius + margin_;
    if (squared_distance < reach * reach) out_.push_back(b);
    return true;
  }

 private:
  double r2_, margin_;
  const std::vector<std::uint32_t>& ball_of_;
  const std::vector<RefinedBall>& balls_;
  std::vector<std::uint32_t>& out_;
};

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
  // Removed points (balls refiled in another class) are skipped by nanoflann's search, so each
  // ball is met at most once.
  const double query[3] = {p.x(), p.y(), p.z()};
  for (const auto& [k, tree] : trees_->classes[static_cast<int>(type)]) {
    if (tree.centres.empty()) continue;
    ReachingBalls result(std::ldexp(1.0, k) + margin, margin, tree.ball, balls_, out);
    tree.tree->findNeighbors(result, query, nanoflann::SearchParams());
  }
}

void BallIndex::lipschitz_violators(StratumType type, const Point& p, double radius, double L,
                                    std::vector<std::uint32_t>& out) const {
  // A ball of class k (radius below 2^k) can violate C3 only within (2^k - radius) / L of p.
  std::vector<std::uint32_t> near;
  for (const auto& [k, tree] : trees_->classes[static_cast<int>(type)]) {
    near.clear();
    tree.within(p, (std::ldexp(1.0, k) - radius) / L, near);
    for (std::uint32_t b : near) {
      if (balls_[b].radius > radius + L * (balls_[b].site.position - p).norm()) out.push_back(b);
    }
  }
}

}  // namespace vorocrust
