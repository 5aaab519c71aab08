#include "seeds/seed_pairs.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "seeds/sphere_triplet.hpp"

namespace vorocrust {

void overlapping_balls(const BallIndex& balls, std::uint32_t p, std::vector<std::uint32_t>& out) {
  out.clear();
  const RefinedBall& ball = balls[p];
  for (int t = 0; t < 3; ++t) balls.reaching(static_cast<StratumType>(t), ball.site.position, ball.radius, out);
  std::sort(out.begin(), out.end());
  out.erase(std::remove(out.begin(), out.end(), p), out.end());
}

namespace {

bool overlap(const RefinedBall& a, const RefinedBall& b) {
  return (a.site.position - b.site.position).norm() < a.radius + b.radius;
}

// The triplets whose smallest ball index is p. Every ball holding a point of p's sphere
// overlaps p, so p's neighbourhood holds every candidate fourth ball.
void triplets_of(const BallIndex& balls, std::uint32_t p, std::vector<std::uint32_t>& near, SeedPairs& out) {
  overlapping_balls(balls, p, near);
  const RefinedBall& bp = balls[p];
  const auto first_above_p = std::upper_bound(near.begin(), near.end(), p);
  for (auto iq = first_above_p; iq != near.end(); ++iq) {
    const RefinedBall& bq = balls[*iq];
    for (auto ir = iq + 1; ir != near.end(); ++ir) {
      const RefinedBall& br = balls[*ir];
      if (!overlap(bq, br)) continue;
      const auto points =
          sphere_triplet_points(bp.site.position, bp.radius, bq.site.position, bq.radius, br.site.position, br.radius);
      if (!points) continue;
      ++out.triplets;
      bool covered[2] = {false, false};
      std::vector<std::uint32_t> fourth;
      for (std::uint32_t s : near) {
        if (s == *iq || s == *ir) continue;
        const RefinedBall& bs = balls[s];
        bool holds = false;
        for (int k = 0; k < 2; ++k) {
          if ((bs.site.position - (*points)[k]).norm() < bs.radius) holds = covered[k] = true;
        }
        if (holds) fourth.push_back(s);
      }
      const SeedPair pair{{p, *iq, *ir}, *points};
      if (!covered[0] && !covered[1]) {
        out.uncovered.push_back(pair);
      } else if (covered[0] != covered[1]) {
        out.half_covered.push_back({pair, covered[0] ? 0 : 1, std::move(fourth)});
      }
    }
  }
}

}  // namespace

double mean_radius(const BallIndex& balls, const SeedPair& pair) {
  double r = 0;
  for (std::uint32_t b : pair.balls) r += balls[b].radius / 3;
  return r;
}

SeedPairs find_seed_pairs(const BallIndex& balls) {
  // Fixed chunks, concatenated in order: the result does not depend on the thread count.
  constexpr std::size_t kChunk = 256;
  const std::size_t n = balls.size();
  std::vector<SeedPairs> chunks((n + kChunk - 1) / kChunk);
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
    std::vector<std::uint32_t> near;
    for (std::size_t p = c * kChunk; p < std::min(n, (c + 1) * kChunk); ++p) {
      triplets_of(balls, static_cast<std::uint32_t>(p), near, chunks[c]);
    }
  });
  SeedPairs all;
  for (SeedPairs& chunk : chunks) {
    all.triplets += chunk.triplets;
    all.uncovered.insert(all.uncovered.end(), chunk.uncovered.begin(), chunk.uncovered.end());
    std::move(chunk.half_covered.begin(), chunk.half_covered.end(), std::back_inserter(all.half_covered));
  }
  return all;
}

}  // namespace vorocrust
