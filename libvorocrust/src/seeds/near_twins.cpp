// Near-twin seeds and the shrinks that part them (paper 2.4).
#include "seeds/near_twins.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "geometry/point_cloud.hpp"

namespace vorocrust {

namespace {

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

std::vector<std::pair<std::uint32_t, std::uint32_t>> twin_pairs(const std::vector<Point>& points,
                                                                 const std::vector<double>& radii) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> twins;
  if (points.empty()) return twins;
  using Cloud = PointCloudAdaptor<Point, IdentityPosition>;
  const Cloud cloud{&points};
  const StaticKdTree<Cloud> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tbb::enumerable_thread_specific<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found;
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, static_cast<std::uint32_t>(points.size()), 1024),
                    [&](const auto& range) {
                      auto& mine = found.local();
                      std::vector<std::uint32_t> near;
                      for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
                        const double reach = kTwin * radii[i];
                        points_within(tree, points[i], reach * reach, near);
                        for (std::uint32_t j : near) {
                          if (j != i) mine.emplace_back(std::min(i, j), std::max(i, j));
                        }
                      }
                    });
  for (const auto& mine : found) twins.insert(twins.end(), mine.begin(), mine.end());
  std::sort(twins.begin(), twins.end());
  twins.erase(std::unique(twins.begin(), twins.end()), twins.end());
  return twins;
}

TwinShrinks choose_twin_shrinks(const BallIndex& balls, const std::vector<SeedPair>& pairs) {
  TwinShrinks out;
  std::vector<Point> points;
  std::vector<double> radii;
  points.reserve(2 * pairs.size());
  radii.reserve(2 * pairs.size());
  for (const SeedPair& pair : pairs) {
    points.insert(points.end(), pair.points.begin(), pair.points.end());
    radii.insert(radii.end(), 2, mean_radius(balls, pair));
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> twins = twin_pairs(points, radii);
  // The two points of one pair lie on either side of the surface, never twins but of a
  // degenerate triplet, which the pair's own seeds settle.
  std::erase_if(twins, [](const auto& t) { return t.first / 2 == t.second / 2; });
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
