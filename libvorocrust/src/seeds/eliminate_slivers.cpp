// Sliver elimination (paper 2.4).
#include "seeds/eliminate_slivers.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "seeds/near_twins.hpp"
#include "seeds/skinny_triangles.hpp"
#include "seeds/sphere_triplet.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {

namespace {

// Quartets per half-covered pair are all 4-subsets of the triplet and the balls covering its
// points; a handful of covering balls is the rule, so this cap only bounds pathological cases.
constexpr std::size_t kMaxCandidates = 10;

// The least shrinking offered so far: ball `ball` to `radius`, by the ratio Delta.
struct Candidate {
  std::uint32_t ball = 0;
  double radius = 0;
  double ratio = std::numeric_limits<double>::infinity();

  // Ball `q` (index `ball`) giving up a point at distance d < q.radius (paper 2.4, "Shrinkage
  // Ratio"); on a tie the lower ball index wins, so the choice is independent of order.
  void offer(std::uint32_t candidate, const RefinedBall& q, double d) {
    const double r = (q.radius - d) / q.radius;
    if (r < ratio || (r == ratio && candidate < ball)) *this = {candidate, d * (1 - kShrinkClearance), r};
  }
};

// The quartet in isolation: for each of its four triplets whose pair the fourth ball
// half-covers, shrinking that fourth ball to uncover the point resolves it; keep the least
// shrinkage ratio (paper 2.4, "Shrinkage Ratio").
void consider_quartet(const BallIndex& balls, const std::array<std::uint32_t, 4>& quartet, Candidate& best) {
  for (int out = 0; out < 4; ++out) {
    std::array<std::uint32_t, 3> t;
    for (int k = 0, j = 0; k < 4; ++k) {
      if (k != out) t[j++] = quartet[k];
    }
    const RefinedBall &a = balls[t[0]], &b = balls[t[1]], &c = balls[t[2]];
    const auto points = sphere_triplet_points(a.site.position, a.radius, b.site.position, b.radius, c.site.position,
                                              c.radius);
    if (!points) continue;
    const RefinedBall& q = balls[quartet[out]];
    const double d0 = (q.site.position - (*points)[0]).norm(), d1 = (q.site.position - (*points)[1]).norm();
    if ((d0 < q.radius) == (d1 < q.radius)) continue;  // not half-covered by q
    best.offer(quartet[out], q, std::min(d0, d1));
  }
}

}  // namespace

BallShrinks choose_sliver_shrinks(const BallIndex& balls, const std::vector<HalfCoveredPair>& half_covered) {
  BallShrinkRequests requests;
  for (const HalfCoveredPair& h : half_covered) {
    std::vector<std::uint32_t> set(h.pair.balls.begin(), h.pair.balls.end());
    set.insert(set.end(), h.fourth.begin(), h.fourth.begin() + std::min(h.fourth.size(), kMaxCandidates - 3));
    Candidate best;
    const std::size_t n = set.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        for (std::size_t k = j + 1; k < n; ++k)
          for (std::size_t l = k + 1; l < n; ++l) consider_quartet(balls, {set[i], set[j], set[k], set[l]}, best);
    if (!std::isfinite(best.ratio)) {
      // Only a larger set of balls half-covers the pair: take the nearest covering ball
      // directly, as the paper's inset does.
      const Point& g = h.pair.points[h.covered];
      for (std::uint32_t s : h.fourth) {
        const double d = (balls[s].site.position - g).norm();
        if (d < balls[s].radius) best.offer(s, balls[s], d);
      }
    }
    if (std::isfinite(best.ratio)) requests.ask(best.ball, best.radius);
  }
  return requests.result(balls);
}

namespace {

// Safe mode bounds the rounds (paper 2.4), so this stays a guard; were it reached, the run stops
// as a refusal that names where the slivers are, not as an internal error.
Error unending_slivers(const BallIndex& balls, const SeedPairs& pairs, int rounds) {
  const SeedPair& first = pairs.half_covered.front().pair;
  Error::Location where;
  for (std::uint32_t b : first.balls) {
    if (!where.face && balls[b].site.type == StratumType::Patch) where.face = balls[b].site.element;
  }
  return Error(Error::Kind::InvalidGeometry,
               "sliver elimination did not end after " + std::to_string(rounds) + " rounds: " +
                   std::to_string(pairs.half_covered.size()) + " half-covered seed pairs are left, the first near " +
                   describe_point(first.points[0]) +
                   "; surfaces that nearly touch there are the usual cause; another --seed or a smaller --lipschitz "
                   "places the balls differently",
               where);
}

}  // namespace

SeedPairs eliminate_slivers(BallRefinement& refinement, const SliverOptions& options, const ProgressCallback& progress,
                            SliverStats& stats) {
  using Clock = std::chrono::steady_clock;
  int sliver_rounds = 0;
  KeptSeedPairs kept;
  for (;;) {
    if (progress && !progress({"slivers", -1})) throw Error(Error::Kind::Cancelled, "cancelled during sliver elimination");
    const auto start = Clock::now();
    const SeedPairs& pairs = kept.update(refinement.index());
    SliverIteration record;
    record.triplets = pairs.triplets;
    record.half_covered = pairs.half_covered.size();
    record.balls = refinement.index().size();
    const auto finish = [&](const BallShrinks& shrinks, SliverIteration::Shrunk why) {
      record.shrunk = why;
      record.balls_shrunk = shrinks.radii.size();
      record.max_shrinkage_ratio = shrinks.max_ratio;
      for (const auto& [ball, radius] : shrinks.radii) {
        if (why != SliverIteration::Shrunk::ForSkinnyTriangles) {
          refinement.shrink_for_slivers(ball, radius);
        } else {
          refinement.shrink_for_skinny_triangle(ball, radius);
        }
      }
      refinement.run();
      record.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      stats.iterations.push_back(record);
    };
    if (!pairs.half_covered.empty()) {
      if (sliver_rounds >= options.max_iterations) throw unending_slivers(refinement.index(), pairs, sliver_rounds);
      if (sliver_rounds++ == options.iterations_before_safe_mode) {
        stats.safe_mode = true;
        refinement.relax_deep_coverage();
      }
      finish(choose_sliver_shrinks(refinement.index(), pairs.half_covered), SliverIteration::Shrunk::ForSlivers);
      continue;
    }
    // Twins first: a skinny-triangle round's new balls can make twins, but parting twins only
    // moves points apart.
    const TwinShrinks twins = choose_twin_shrinks(refinement.index(), pairs.uncovered);
    record.near_twins = twins.twins;
    if (!twins.shrinks.radii.empty() &&
        stats.rounds_for(SliverIteration::Shrunk::ForNearTwins) < static_cast<std::size_t>(options.max_near_twin_rounds)) {
      finish(twins.shrinks, SliverIteration::Shrunk::ForNearTwins);
      continue;
    }
    if (options.min_triangle_angle_degrees > 0) {
      const SkinnyTriangleShrinks skinny = choose_skinny_triangle_shrinks(
          refinement.index(), pairs.uncovered, options.min_triangle_angle_degrees, refinement.deep_coverage());
      record.skinny_triangles = skinny.skinny;
      const auto splits = stats.rounds_for(SliverIteration::Shrunk::ForSkinnyTriangles);
      if (splits < static_cast<std::size_t>(options.max_skinny_triangle_rounds) && !skinny.shrinks.radii.empty()) {
        finish(skinny.shrinks, SliverIteration::Shrunk::ForSkinnyTriangles);
        continue;
      }
    }
    record.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    stats.iterations.push_back(record);
    return kept.release();
  }
}

}  // namespace vorocrust
