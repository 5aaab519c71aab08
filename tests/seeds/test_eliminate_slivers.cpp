// Seed pairs and sliver elimination on hand-made quartets (paper 2.4, Figure 8).
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <utility>

#include "ball_sites.hpp"
#include "features/strata.hpp"
#include "refinement/ball_index.hpp"
#include "seeds/eliminate_slivers.hpp"
#include "seeds/seed_pairs.hpp"
#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/validate.hpp"

namespace vorocrust {
namespace {

using test::site_at;

// Four balls around a nearly flat quad: the diagonal a-c is slightly shorter than b-d, so the
// two triangles through a-c are the surface and the quartet's fourth-ball coverage decides it.
void flat_quad(BallIndex& balls, double lift, double radius) {
  balls.add(site_at(Point(0, 0, 0)), radius);
  balls.add(site_at(Point(1, 0, lift)), radius);
  balls.add(site_at(Point(1.02, 1, 0)), radius);
  balls.add(site_at(Point(0, 1, lift)), radius);
}

TEST(SeedPairs, ATetrahedronOfBallsGivesFourTripletsOnce) {
  BallIndex balls;
  flat_quad(balls, 0.0, 0.9);
  const SeedPairs pairs = find_seed_pairs(balls);
  EXPECT_EQ(pairs.triplets, 4u);
  for (const SeedPair& p : pairs.uncovered) EXPECT_TRUE(p.balls[0] < p.balls[1] && p.balls[1] < p.balls[2]);
}

TEST(SeedPairs, APlanarQuartetHasNoHalfCoveredPair) {
  // Centres in one plane: a fourth ball is as near to either point of a pair, so it covers both
  // or neither.
  BallIndex balls;
  flat_quad(balls, 0.0, 0.8);
  const SeedPairs pairs = find_seed_pairs(balls);
  EXPECT_TRUE(pairs.half_covered.empty());
  EXPECT_EQ(pairs.uncovered.size(), 2u);  // the two triangles across the shorter diagonal
}

TEST(SliverElimination, ShrinkingTheChosenBallsLeavesNoHalfCoveredPair) {
  // Lifting two opposite centres makes the quartet a flat tetrahedron: a sliver.
  BallIndex balls;
  flat_quad(balls, 0.08, 0.8);
  SeedPairs pairs = find_seed_pairs(balls);
  ASSERT_FALSE(pairs.half_covered.empty());
  const BallShrinks shrinks = choose_sliver_shrinks(balls, pairs.half_covered);
  ASSERT_FALSE(shrinks.radii.empty());
  EXPECT_GT(shrinks.max_ratio, 0);
  EXPECT_LT(shrinks.max_ratio, 0.5);
  for (const auto& [ball, radius] : shrinks.radii) {
    EXPECT_LT(radius, balls[ball].radius);
    balls.shrink(ball, radius);
  }
  pairs = find_seed_pairs(balls);
  EXPECT_TRUE(pairs.half_covered.empty());
  EXPECT_EQ(pairs.uncovered.size(), 2u);  // Figure 8: two facets, no Steiner vertex
}

// cgal_joint's balls as the refinement first leaves them, handed to `use`.
template <class Use>
auto with_joint_balls(Use use) {
  SurfaceMesh mesh = read_mesh(test::model("cgal_joint.off"));
  (void)validate(mesh);
  const Strata strata = detect_strata(mesh, 30 * std::numbers::pi / 180);
  const SizingField sizing;
  RefinementOptions options;
  options.sharp_angle = 30 * std::numbers::pi / 180;
  RefinementStats stats;
  const ProgressCallback progress;  // the refinement keeps a reference to it, as to the others
  BallRefinement refinement(mesh, strata, sizing, options, progress, stats);
  refinement.run();
  return use(refinement);
}

// Paper 2.4: safe mode comes after a bound on the sliver rounds. The rounds that split balls
// about skinny triangles each bring a few sliver rounds of their own; counted only since the
// last split, the rounds never reached the bound on igl_camelhead --smooth, which took 387.
TEST(SliverElimination, SafeModeCountsTheSliverRoundsAcrossSkinnyTriangleSplits) {
  SliverOptions options;
  options.min_triangle_angle_degrees = 30;
  const auto eliminate = [&](SliverStats& stats) {
    return with_joint_balls([&](BallRefinement& refinement) {
      const SeedPairs pairs = eliminate_slivers(refinement, options, ProgressCallback(), stats);
      return std::pair(pairs.half_covered.size(), refinement.deep_coverage());
    });
  };
  options.iterations_before_safe_mode = 1000;
  SliverStats unbounded;
  (void)eliminate(unbounded);
  ASSERT_FALSE(unbounded.safe_mode);
  std::size_t rounds = 0, longest_run = 0;
  for (std::size_t i = 0, run = 0; i < unbounded.iterations.size(); ++i) {
    const bool sliver_round = unbounded.iterations[i].shrunk == SliverIteration::Shrunk::ForSlivers;
    run = sliver_round ? run + 1 : 0;
    rounds += sliver_round;
    longest_run = std::max(longest_run, run);
  }
  ASSERT_GT(rounds, longest_run) << "no split between the sliver rounds: the test needs one";

  options.iterations_before_safe_mode = static_cast<int>(longest_run);
  SliverStats bounded;
  const auto [half_covered, deep_coverage] = eliminate(bounded);
  EXPECT_TRUE(bounded.safe_mode) << rounds << " sliver rounds, at most " << longest_run << " in a row";
  EXPECT_EQ(half_covered, 0u);
  EXPECT_NEAR(deep_coverage, 1 - 0.13397459621556135 / 2, 1e-12);  // alpha/2-deep (paper 2.4)
}

// The pairs kept from round to round are those found afresh, in the same order, while each
// round finds only a small share of the balls' triplets again.
TEST(SeedPairs, KeptPairsAreThoseFoundAfreshAfterEachSliverRound) {
  const auto same_pair = [](const SeedPair& a, const SeedPair& b) { return a.balls == b.balls && a.points == b.points; };
  with_joint_balls([&](BallRefinement& refinement) {
    KeptSeedPairs kept;
    std::size_t rounds = 0, least_found_again = refinement.index().size();
    for (; rounds < 6; ++rounds) {
      const SeedPairs& pairs = kept.update(refinement.index());
      const SeedPairs fresh = find_seed_pairs(refinement.index());
      ASSERT_EQ(pairs.triplets, fresh.triplets);
      ASSERT_EQ(pairs.uncovered.size(), fresh.uncovered.size());
      for (std::size_t i = 0; i < fresh.uncovered.size(); ++i) ASSERT_TRUE(same_pair(pairs.uncovered[i], fresh.uncovered[i])) << i;
      ASSERT_EQ(pairs.half_covered.size(), fresh.half_covered.size());
      for (std::size_t i = 0; i < fresh.half_covered.size(); ++i) {
        const HalfCoveredPair &a = pairs.half_covered[i], &b = fresh.half_covered[i];
        ASSERT_TRUE(same_pair(a.pair, b.pair) && a.covered == b.covered && a.fourth == b.fourth) << i;
      }
      if (rounds > 0) least_found_again = std::min(least_found_again, kept.balls_found_again());
      if (pairs.half_covered.empty()) break;
      const BallShrinks shrinks = choose_sliver_shrinks(refinement.index(), pairs.half_covered);
      for (const auto& [ball, radius] : shrinks.radii) refinement.shrink_for_slivers(ball, radius);
      refinement.run();
    }
    ASSERT_GE(rounds, 2u) << "too few sliver rounds to compare";
    EXPECT_LT(least_found_again, refinement.index().size() / 4);
  });
}

// The guard on the rounds is a refusal that names a face and a place, never an internal error: a
// plugin's user must learn what to change. cgal_joint's first balls hold 368 half-covered pairs,
// so a guard of no round at all trips at once.
TEST(SliverElimination, TheGuardOnRoundsRefusesNamingTheFace) {
  with_joint_balls([](BallRefinement& refinement) {
    SliverOptions options;
    options.max_iterations = 0;
    SliverStats stats;
    try {
      (void)eliminate_slivers(refinement, options, ProgressCallback(), stats);
      FAIL() << "the guard did not trip";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::InvalidGeometry) << e.what();
      EXPECT_TRUE(e.where().face.has_value()) << e.what();
      EXPECT_NE(e.message().find("half-covered seed pairs are left, the first near ("), std::string::npos) << e.what();
      EXPECT_NE(e.message().find("--seed"), std::string::npos) << e.what();
    }
  });
}

}  // namespace
}  // namespace vorocrust
