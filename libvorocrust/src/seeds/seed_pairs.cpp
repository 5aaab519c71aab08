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
  KeptSeedPairs kept;
  (void)kept.update(balls);
  return kept.release();
}

namespace {

// The balls whose triplets a change from `radius` (each ball's radius when last found; new balls
// have none) can have changed: a changed ball itself, and every ball its old or new sphere
// reached. A triplet is kept under its smallest ball p, and each ball that decides it (one of
// the three, or a fourth holding a point of p's sphere) overlaps p.
std::vector<std::uint32_t> balls_to_find_again(const BallIndex& balls, const std::vector<double>& radius) {
  const std::size_t n = balls.size();
  std::vector<char> again(n, 0);
  std::vector<std::uint32_t> near;
  for (std::uint32_t c = 0; c < n; ++c) {
    const bool is_new = c >= radius.size();
    if (!is_new && balls[c].radius == radius[c]) continue;
    again[c] = 1;
    near.clear();
    // Radii only shrink; the margin keeps a tie in the tree's distances from leaving one out.
    const double reach = (is_new ? balls[c].radius : radius[c]) * (1 + 1e-9);
    for (int t = 0; t < 3; ++t) balls.reaching(static_cast<StratumType>(t), balls[c].site.position, reach, near);
    for (std::uint32_t p : near) again[p] = 1;
  }
  std::vector<std::uint32_t> out;
  for (std::uint32_t p = 0; p < n; ++p) {
    if (again[p]) out.push_back(p);
  }
  return out;
}

}  // namespace

const SeedPairs& KeptSeedPairs::update(const BallIndex& balls) {
  const std::size_t n = balls.size();
  const std::vector<std::uint32_t> again = balls_to_find_again(balls, radius_);
  found_again_ = again.size();
  // Each ball's triplets apart, in fixed chunks: the result does not depend on the thread count.
  constexpr std::size_t kChunk = 64;
  std::vector<SeedPairs> fresh(again.size());
  tbb::parallel_for(std::size_t{0}, (again.size() + kChunk - 1) / kChunk, [&](std::size_t c) {
    std::vector<std::uint32_t> near;
    for (std::size_t i = c * kChunk; i < std::min(again.size(), (c + 1) * kChunk); ++i) {
      triplets_of(balls, again[i], near, fresh[i]);
    }
  });
  // The kept balls' pairs as they were, the others' found again, in ball order.
  SeedPairs next;
  std::vector<std::size_t> first_uncovered{0}, first_half_covered{0};
  first_uncovered.reserve(n + 1);
  first_half_covered.reserve(n + 1);
  triplets_.resize(n, 0);
  auto fresh_one = fresh.begin();
  auto next_again = again.begin();
  for (std::uint32_t p = 0; p < n; ++p) {
    if (next_again != again.end() && *next_again == p) {
      ++next_again;
      SeedPairs& found = *fresh_one++;
      triplets_[p] = static_cast<std::uint32_t>(found.triplets);
      next.uncovered.insert(next.uncovered.end(), found.uncovered.begin(), found.uncovered.end());
      std::move(found.half_covered.begin(), found.half_covered.end(), std::back_inserter(next.half_covered));
    } else {
      next.uncovered.insert(next.uncovered.end(), pairs_.uncovered.begin() + first_uncovered_[p],
                            pairs_.uncovered.begin() + first_uncovered_[p + 1]);
      std::move(pairs_.half_covered.begin() + first_half_covered_[p],
                pairs_.half_covered.begin() + first_half_covered_[p + 1], std::back_inserter(next.half_covered));
    }
    next.triplets += triplets_[p];
    first_uncovered.push_back(next.uncovered.size());
    first_half_covered.push_back(next.half_covered.size());
  }
  pairs_ = std::move(next);
  first_uncovered_ = std::move(first_uncovered);
  first_half_covered_ = std::move(first_half_covered);
  radius_.resize(n);
  for (std::uint32_t p = 0; p < n; ++p) radius_[p] = balls[p].radius;
  return pairs_;
}

SeedPairs KeptSeedPairs::release() {
  SeedPairs out = std::move(pairs_);
  *this = KeptSeedPairs();  // every ball counts as new again
  return out;
}

}  // namespace vorocrust
