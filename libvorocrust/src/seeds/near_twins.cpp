// Near-twin seeds and the shrinks that part them (paper 2.4).
#include "seeds/near_twins.hpp"

#include <algorithm>

#include "geometry/point_cloud.hpp"

namespace vorocrust {

namespace {

double mean_radius(const BallIndex& balls, const SeedPair& pair) {
  double r = 0;
  for (std::uint32_t b : pair.balls) r += balls[b].radius / 3;
  return r;
}

// The ball of the quartet that shrinks: of the balls in one triplet only, the largest (ties to
// the higher index, so the choice does not depend on which twin was found first).
std::uint32_t ball_to_shrink(const BallIndex& balls, const SeedPair& a, const SeedPair& b) {
  const auto in = [](const SeedPair& p, std::uint32_t ball) {
    return std::find(p.balls.begin(), p.balls.end(), ball) != p.balls.end();
  };
  std::uint32_t chosen = ~std::uint32_t{0};
  for (const SeedPair* pair : {&a, &b}) {
    const SeedPair& other = pair == &a ? b : a;
    for (std::uint32_t ball : pair->balls) {
      if (in(other, ball)) continue;
      if (chosen == ~std::uint32_t{0} || balls[ball].radius > balls[chosen].radius ||
          (balls[ball].radius == balls[chosen].radius && ball > chosen)) {
        chosen = ball;
      }
    }
  }
  return chosen;
}

}  // namespace

TwinShrinks choose_twin_shrinks(const BallIndex& balls, const std::vector<SeedPair>& pairs) {
  TwinShrinks out;
  std::vector<Point> points;
  points.reserve(2 * pairs.size());
  for (const SeedPair& pair : pairs) points.insert(points.end(), pair.points.begin(), pair.points.end());
  if (points.empty()) return out;
  using Cloud = PointCloudAdaptor<Point, IdentityPosition>;
  const Cloud cloud{&points};
  const StaticKdTree<Cloud> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  // Each point looks as far as its own triplet's radius says, as surface_seeds does, so a pair
  // counts when either of its points reaches the other.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> twins;
  std::vector<std::uint32_t> near;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const double reach = kTwin * mean_radius(balls, pairs[i / 2]);
    points_within(tree, points[i], reach * reach, near);
    for (std::uint32_t j : near) {
      if (j / 2 != i / 2) twins.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  std::sort(twins.begin(), twins.end());
  twins.erase(std::unique(twins.begin(), twins.end()), twins.end());
  out.twins = twins.size();
  BallShrinkRequests requests;
  for (const auto& [i, j] : twins) {
    const std::uint32_t ball = ball_to_shrink(balls, pairs[i / 2], pairs[j / 2]);
    if (ball != ~std::uint32_t{0}) requests.ask(ball, (1 - kShrinkClearance) * balls[ball].radius);
  }
  out.shrinks = requests.result(balls);
  return out;
}

}  // namespace vorocrust
